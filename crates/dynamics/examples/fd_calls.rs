//! Runs one forward-dynamics algorithm many times on a URDF with a floating base (or Dill(n)),
//! alternating two nearby states: a harness for instruction counts (callgrind), where the
//! difference of two call counts cancels start-up and model assembly.
//!
//! Usage: `fd_calls (URDF | dill:N) (on | crba | sparse | mass | rnea) (CALLS | time)`; with
//! `time` it prints the median ns per call of 41 batches of 2000 calls instead.

use biped_dynamics::dill::{dill, dill_test_state};
use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{
    forward_dynamics, inverse_dynamics, mass_matrix, nearby_state, Algorithm, Data, Model,
};
use nalgebra::DVector;
use std::hint::black_box;

/// A model with its first state `(q, v)`.
type Loaded = (Model, DVector<f64>, DVector<f64>);

/// The model and its first state from the command-line source.
fn load(source: &str) -> Result<Loaded, Box<dyn std::error::Error>> {
    if let Some(n) = source.strip_prefix("dill:") {
        let model = dill(n.parse()?)?;
        let (q, v) = dill_test_state(&model);
        return Ok((model, q, v));
    }
    let options = UrdfOptions {
        floating: true,
        ..UrdfOptions::default()
    };
    let model = load_file(source, &options)?.model;
    let zero = DVector::zeros(model.nv());
    let (q, v) = nearby_state(&model, &model.neutral(), &zero)?;
    Ok((model, q, v))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let [_, source, what, calls] = args.as_slice() else {
        return Err(
            "usage: fd_calls (URDF | dill:N) (on | crba | sparse | mass | rnea) CALLS".into(),
        );
    };
    let (model, q, v) = load(source)?;
    let states = [(q.clone(), v.clone()), nearby_state(&model, &q, &v)?];
    let tau = DVector::from_fn(model.nv(), |i, _| 0.3 * (i as f64).sin());
    let mut data = Data::new(&model);
    let mut call = |k: usize| -> Result<bool, Box<dyn std::error::Error>> {
        let (q, v) = &states[k & 1];
        Ok(match what.as_str() {
            "on" => forward_dynamics(&model, &mut data, q, v, &tau, None, Algorithm::On).is_ok(),
            "crba" => {
                forward_dynamics(&model, &mut data, q, v, &tau, None, Algorithm::Crba).is_ok()
            }
            "sparse" => {
                forward_dynamics(&model, &mut data, q, v, &tau, None, Algorithm::Sparse).is_ok()
            }
            "mass" => mass_matrix(&model, &mut data, q).is_ok(),
            "rnea" => inverse_dynamics(&model, &mut data, q, v, &tau, None).is_ok(),
            _ => return Err(format!("unknown function {what}").into()),
        })
    };
    if calls == "time" {
        let mut batches = Vec::new();
        for _ in 0..41 {
            let t = std::time::Instant::now();
            for k in 0..2000 {
                black_box(call(k)?);
            }
            batches.push(t.elapsed().as_nanos() as f64 / 2000.0);
        }
        batches.sort_by(f64::total_cmp);
        println!("{what} {:.0} ns", batches[20]);
        return Ok(());
    }
    for k in 0..calls.parse()? {
        black_box(call(k)?);
    }
    Ok(())
}
