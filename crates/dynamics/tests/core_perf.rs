//! Timing of the dynamics algorithms on a URDF (default: TALOS from example-robot-data).
//! Run: `cargo test --release -p biped_dynamics --test core_perf -- --ignored --nocapture`
//! with `BIPED_PERF_URDF=/path/robot.urdf` to choose another robot (floating base).

use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{forward_dynamics, inverse_dynamics, mass_matrix, on, Algorithm, Data};
use nalgebra::DVector;
use std::hint::black_box;
use std::time::Instant;

const DEFAULT_URDF: &str = "/root/.cache/biped-peers/lib/python3.11/site-packages/cmeel.prefix/share/example-robot-data/robots/talos_data/robots/talos_full_v2.urdf";

/// Median over 9 batches of the per-call time in ns.
fn median_ns(mut f: impl FnMut()) -> f64 {
    let n = 2000;
    let mut t: Vec<f64> = (0..9)
        .map(|_| {
            let s = Instant::now();
            for _ in 0..n {
                f();
            }
            s.elapsed().as_nanos() as f64 / n as f64
        })
        .collect();
    t.sort_by(|a, b| a.partial_cmp(b).unwrap());
    t[4]
}

#[test]
#[ignore = "timing; run in release with --ignored --nocapture"]
fn timings() {
    let path = std::env::var("BIPED_PERF_URDF").unwrap_or_else(|_| DEFAULT_URDF.to_string());
    let Ok(urdf) = load_file(
        &path,
        &UrdfOptions {
            floating: true,
            reject_mimic: false,
        },
    ) else {
        eprintln!("skipping: cannot load {path}");
        return;
    };
    let model = urdf.model;
    let mut data = Data::new(&model);
    let mut q = model.neutral();
    for (k, x) in q.iter_mut().enumerate().skip(7) {
        *x = 0.1 * ((k as f64) * 0.7).sin();
    }
    let v = DVector::from_fn(model.nv(), |i, _| ((i as f64) * 1.3).cos());
    let tau = DVector::from_fn(model.nv(), |i, _| ((i as f64) * 0.9).sin());
    println!(
        "{path}: nbodies {} nq {} nv {}",
        model.nbodies(),
        model.nq(),
        model.nv()
    );
    if let Some(n) = std::env::var("BIPED_PERF_CALLS")
        .ok()
        .and_then(|s| s.parse::<usize>().ok())
    {
        // Fixed number of calls, for instruction counting (valgrind --tool=callgrind);
        // BIPED_PERF_ALGO = on (default) | crba | sparse | mass | rnea.
        let which = std::env::var("BIPED_PERF_ALGO").unwrap_or_else(|_| "on".into());
        let algo = match which.as_str() {
            "crba" => Algorithm::Crba,
            "sparse" => Algorithm::Sparse,
            _ => Algorithm::On,
        };
        for _ in 0..n {
            let ok = match which.as_str() {
                "mass" => mass_matrix(&model, &mut data, &q).is_ok(),
                "rnea" => inverse_dynamics(&model, &mut data, &q, &v, &tau, None).is_ok(),
                _ => forward_dynamics(&model, &mut data, &q, &v, &tau, None, algo).is_ok(),
            };
            black_box(ok);
        }
        return;
    }
    for algo in [Algorithm::On, Algorithm::Crba, Algorithm::Sparse] {
        let t = median_ns(|| {
            black_box(forward_dynamics(&model, &mut data, &q, &v, &tau, None, algo).unwrap());
        });
        println!("forward_dynamics {algo:?}: {:.0} ns", t);
    }
    let t1 = median_ns(|| on::forward_pass_1(&model, &mut data, &q, &v, None).unwrap());
    let t2 = median_ns(|| {
        on::forward_pass_1(&model, &mut data, &q, &v, None).unwrap();
        on::backward_pass(&model, &mut data, &tau).unwrap();
    });
    let t3 = median_ns(|| {
        black_box(on::forward_pass_2(&model, &mut data));
    });
    println!(
        "O(n) passes: FW1 {:.0} ns, BW {:.0} ns, FW2 {:.0} ns",
        t1,
        t2 - t1,
        t3
    );
    let a = forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::On)
        .unwrap()
        .clone();
    let t = median_ns(|| {
        black_box(inverse_dynamics(&model, &mut data, &q, &v, &a, None).unwrap());
    });
    println!("inverse_dynamics (RNEA): {:.0} ns", t);
    let t = median_ns(|| {
        black_box(mass_matrix(&model, &mut data, &q).unwrap());
    });
    println!("mass_matrix (CRBA): {:.0} ns", t);
}
