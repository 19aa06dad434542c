//! The comparison shared by the `reference_*` tests: the reference O(n) algorithm against the
//! fast O(n) path, sparse LTL and CRBA, and its body accelerations against CRBA's.
#![allow(dead_code)]

use biped_dynamics::dynamics::reference;
use biped_dynamics::{forward_dynamics, Algorithm, Data, Model, Wrench};
use nalgebra::DVector;

/// `|a - b| / max(1, |a|, |b|)` in the max norm.
fn rel(a: &[f64], b: &[f64]) -> f64 {
    let amax = |x: &[f64]| x.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let diff = a
        .iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
    diff / amax(a).max(amax(b)).max(1.0)
}

/// Largest relative difference of the reference against O(n), CRBA and sparse LTL at one
/// state, and of its body accelerations against those CRBA propagates.
pub fn deviation(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
    tau: &DVector<f64>,
    fext: Option<&[Wrench]>,
) -> f64 {
    let reference::Solution { qddot: qdd, acc } =
        reference::forward_dynamics_with_accelerations(model, q, v, tau, fext).expect("reference");
    let mut data = Data::new(model);
    let mut worst: f64 = 0.0;
    for algo in [Algorithm::On, Algorithm::Sparse, Algorithm::Crba] {
        let fast = forward_dynamics(model, &mut data, q, v, tau, fext, algo).expect("fast");
        worst = worst.max(rel(qdd.as_slice(), fast.as_slice()));
    }
    for (i, a) in acc.iter().enumerate() {
        if let Some(a) = a {
            let fast = data.acc[i].to_vector();
            worst = worst.max(rel(a.as_slice(), fast.as_slice()));
        }
    }
    worst
}
