//! Test systems with known solutions for the integrator tests.
#![allow(dead_code)]

use biped_sim::ode::{OdeSystem, SplitSystem};
use std::convert::Infallible;

/// Error of the failing test system.
#[derive(Debug, thiserror::Error)]
#[error("test failure at t = {0}")]
pub struct Fail(pub f64);

/// Harmonic oscillator `x' = v, v' = -w^2 x`; state `[x, v]`.
pub struct Oscillator {
    pub w: f64,
}

impl Oscillator {
    /// Exact state at `t` from `[x0, v0]` at 0.
    pub fn exact(&self, z0: [f64; 2], t: f64) -> [f64; 2] {
        let (s, c) = (self.w * t).sin_cos();
        [
            z0[0] * c + z0[1] * s / self.w,
            -z0[0] * self.w * s + z0[1] * c,
        ]
    }

    /// Energy `(v^2 + w^2 x^2) / 2`.
    pub fn energy(&self, z: &[f64]) -> f64 {
        0.5 * (z[1] * z[1] + self.w * self.w * z[0] * z[0])
    }
}

impl OdeSystem for Oscillator {
    type Error = Infallible;
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&mut self, _t: f64, z: &[f64], zd: &mut [f64]) -> Result<(), Infallible> {
        zd[0] = z[1];
        zd[1] = -self.w * self.w * z[0];
        Ok(())
    }
}

impl SplitSystem for Oscillator {
    fn position_len(&self) -> usize {
        1
    }
    fn position_rate(&self, z: &[f64], xd: &mut [f64]) {
        xd[0] = z[1];
    }
}

/// Non-autonomous `y' = -2 t y^2`, exact `y = 1 / (1 + t^2)` from `y(0) = 1`.
pub struct Riccati;

impl Riccati {
    /// Exact solution.
    pub fn exact(t: f64) -> f64 {
        1.0 / (1.0 + t * t)
    }
}

impl OdeSystem for Riccati {
    type Error = Infallible;
    fn dim(&self) -> usize {
        1
    }
    fn rhs(&mut self, t: f64, z: &[f64], zd: &mut [f64]) -> Result<(), Infallible> {
        zd[0] = -2.0 * t * z[0] * z[0];
        Ok(())
    }
}

/// Quadrature `y' = p(t)` with polynomial coefficients `p[0] + p[1] t + ...`.
pub struct Quadrature(pub Vec<f64>);

impl Quadrature {
    /// Exact `y(t)` from `y(0) = 0`.
    pub fn exact(&self, t: f64) -> f64 {
        self.0
            .iter()
            .enumerate()
            .map(|(k, c)| c * t.powi(k as i32 + 1) / (k + 1) as f64)
            .sum()
    }
}

impl OdeSystem for Quadrature {
    type Error = Infallible;
    fn dim(&self) -> usize {
        1
    }
    fn rhs(&mut self, t: f64, _z: &[f64], zd: &mut [f64]) -> Result<(), Infallible> {
        zd[0] = self.0.iter().rev().fold(0.0, |acc, c| acc * t + c);
        Ok(())
    }
}

/// Van der Pol `x'' = mu (1 - x^2) x' - x`; state `[x, x']`.
pub struct VanDerPol {
    pub mu: f64,
}

impl OdeSystem for VanDerPol {
    type Error = Infallible;
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&mut self, _t: f64, z: &[f64], zd: &mut [f64]) -> Result<(), Infallible> {
        zd[0] = z[1];
        zd[1] = self.mu * (1.0 - z[0] * z[0]) * z[1] - z[0];
        Ok(())
    }
}

/// Kepler problem `r'' = -r / |r|^3`; state `[x, y, vx, vy]`.
pub struct Kepler;

impl Kepler {
    /// Initial state at pericentre of the orbit with eccentricity `e` (period `2 pi`).
    pub fn initial(e: f64) -> [f64; 4] {
        [1.0 - e, 0.0, 0.0, ((1.0 + e) / (1.0 - e)).sqrt()]
    }

    /// Energy `|v|^2 / 2 - 1 / |r|`.
    pub fn energy(z: &[f64]) -> f64 {
        0.5 * (z[2] * z[2] + z[3] * z[3]) - 1.0 / z[0].hypot(z[1])
    }
}

impl OdeSystem for Kepler {
    type Error = Infallible;
    fn dim(&self) -> usize {
        4
    }
    fn rhs(&mut self, _t: f64, z: &[f64], zd: &mut [f64]) -> Result<(), Infallible> {
        let r = z[0].hypot(z[1]);
        let r3 = r * r * r;
        zd[0] = z[2];
        zd[1] = z[3];
        zd[2] = -z[0] / r3;
        zd[3] = -z[1] / r3;
        Ok(())
    }
}

impl SplitSystem for Kepler {
    fn position_len(&self) -> usize {
        2
    }
    fn position_rate(&self, z: &[f64], xd: &mut [f64]) {
        xd.copy_from_slice(&z[2..4]);
    }
}

/// `y' = y` that records the largest evaluation time and fails (or yields NaN) on demand.
pub struct Probe {
    pub max_t: f64,
    pub nan_after: f64,
    pub fail_after: f64,
}

impl Probe {
    /// A probe that never fails.
    pub fn new() -> Self {
        Probe {
            max_t: f64::NEG_INFINITY,
            nan_after: f64::INFINITY,
            fail_after: f64::INFINITY,
        }
    }
}

impl OdeSystem for Probe {
    type Error = Fail;
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&mut self, t: f64, z: &[f64], zd: &mut [f64]) -> Result<(), Fail> {
        self.max_t = self.max_t.max(t);
        if t > self.fail_after {
            return Err(Fail(t));
        }
        zd[0] = if t > self.nan_after { f64::NAN } else { z[0] };
        zd[1] = -z[1];
        Ok(())
    }
}

impl SplitSystem for Probe {
    fn position_len(&self) -> usize {
        1
    }
    fn position_rate(&self, z: &[f64], xd: &mut [f64]) {
        xd[0] = z[0];
    }
}

/// Slope of `log err` over `log h` by least squares.
pub fn slope(hs: &[f64], errs: &[f64]) -> f64 {
    let n = hs.len() as f64;
    let xs: Vec<f64> = hs.iter().map(|h| h.ln()).collect();
    let ys: Vec<f64> = errs.iter().map(|e| e.ln()).collect();
    let mx = xs.iter().sum::<f64>() / n;
    let my = ys.iter().sum::<f64>() / n;
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}
