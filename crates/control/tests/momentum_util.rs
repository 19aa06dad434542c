//! Shared helpers of the momentum tests (included with `#[path]`; also built as an empty
//! test target).
#![allow(dead_code)]

use biped_dynamics::{Centroidal, Data, Model};
use biped_robots::lola::{build, LolaModel, LolaType};
use nalgebra::{DMatrix, DVector};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// Lola Type 2 and its workspaces.
pub struct Lola {
    pub lola: LolaModel,
    pub data: Data,
    pub centroidal: Centroidal,
    pub rng: StdRng,
}

impl Lola {
    /// Type 2 model with a seeded generator.
    pub fn new(seed: u64) -> Self {
        let lola = build(LolaType::Type2).expect("shipped Lola model builds");
        let data = Data::new(&lola.model);
        let centroidal = Centroidal::new(&lola.model);
        Self {
            lola,
            data,
            centroidal,
            rng: StdRng::seed_from_u64(seed),
        }
    }

    pub fn model(&self) -> &Model {
        &self.lola.model
    }

    /// Random state (joints in range, velocities in [-1, 1]).
    pub fn state(&mut self) -> (DVector<f64>, DVector<f64>) {
        let rng = &mut self.rng;
        self.lola
            .random_state(&mut |a, b| if a < b { rng.random_range(a..b) } else { a })
    }

    /// Uniform vector in [-1, 1]^n.
    pub fn vector(&mut self, n: usize) -> DVector<f64> {
        DVector::from_fn(n, |_, _| self.rng.random_range(-1.0..1.0))
    }
}

/// Relative error `|a - b| / max(1, |b|)`.
pub fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1.0)
}

/// Dense Moore-Penrose pseudo-inverse by SVD (independent reference).
pub fn pinv(m: &DMatrix<f64>) -> DMatrix<f64> {
    m.clone().pseudo_inverse(1e-12).expect("SVD pseudo-inverse")
}
