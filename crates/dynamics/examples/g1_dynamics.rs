//! Forward dynamics of the Unitree G1 humanoid (bundled URDF, floating base) by the three
//! methods of `biped_dynamics`: how closely they agree and how long each takes.
//!
//! Run with `cargo run -p biped_dynamics --example g1_dynamics` (add `--release` for
//! representative timings; the debug build leaves this crate unoptimised).

use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{forward_dynamics, inverse_dynamics, nearby_state, Algorithm, Data};
use nalgebra::DVector;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/g1_29dof_rev_1_0.urdf");
    let options = UrdfOptions {
        floating: true,
        ..UrdfOptions::default()
    };
    let urdf = load_file(path, &options)?;
    for warning in &urdf.warnings {
        println!("warning: {warning}");
    }
    let model = urdf.model;
    println!(
        "G1: {} bodies, nq = {}, nv = {}",
        model.nbodies(),
        model.nq(),
        model.nv()
    );

    // A generic state: every coordinate a little off the neutral pose, velocities 1e-3 rad/s,
    // and the second state near it (alternating the two makes every call a full evaluation).
    let (q, v) = nearby_state(&model, &model.neutral(), &DVector::zeros(model.nv()))?;
    let states = [(q.clone(), v.clone()), nearby_state(&model, &q, &v)?];
    let tau = DVector::from_fn(model.nv(), |i, _| 0.5 * (i as f64).cos());
    let mut data = Data::new(&model);

    let reference = forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::On)?.clone();
    let back = inverse_dynamics(&model, &mut data, &q, &v, &reference, None)?;
    println!(
        "O(n) forward dynamics, then RNEA: max |tau - tau_in| = {:.2e}",
        (back - &tau).amax()
    );

    let calls = 1000;
    for (name, algo) in [
        ("O(n)  ", Algorithm::On),
        ("CRBA  ", Algorithm::Crba),
        ("sparse", Algorithm::Sparse),
    ] {
        let qdd = forward_dynamics(&model, &mut data, &q, &v, &tau, None, algo)?;
        let diff = (qdd - &reference).amax();
        let start = Instant::now();
        for k in 0..calls {
            let (q, v) = &states[k % 2];
            forward_dynamics(&model, &mut data, q, v, &tau, None, algo)?;
        }
        let us = start.elapsed().as_secs_f64() * 1e6 / calls as f64;
        println!(
            "{name}: {us:8.2} us per call, max |qdd - qdd_O(n)| = {diff:.2e} (max |qdd| {:.2e})",
            reference.amax()
        );
    }
    Ok(())
}
