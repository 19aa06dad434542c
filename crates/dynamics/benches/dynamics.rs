//! Criterion benchmarks of forward dynamics (thesis 2.10): every algorithm on Dill(1..10)
//! (Fig. 2.19) and on a humanoid URDF with a floating base, plus the three O(n) passes (Fig. 2.21).
//!
//! The humanoid is TALOS (`talos_full_v2.urdf`) when found via `$BIPED_BENCH_URDF` or
//! `$ROBOTS/talos_data/robots/talos_full_v2.urdf` (see /work/shared/peers/setup.sh), else the
//! bundled Unitree G1 (`data/g1_29dof_rev_1_0.urdf`).

use biped_dynamics::dill::{dill, dill_test_state};
use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{
    forward_dynamics, forward_dynamics_kinematics, forward_dynamics_solve, nearby_state, on,
    Algorithm, Data, Model,
};
use criterion::{criterion_group, criterion_main, BenchmarkGroup, BenchmarkId, Criterion};
use nalgebra::DVector;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;

/// The three forward-dynamics algorithms with their benchmark names.
const ALGORITHMS: [(&str, Algorithm); 3] = [
    ("on", Algorithm::On),
    ("crba", Algorithm::Crba),
    ("sparse", Algorithm::Sparse),
];

/// A model with the state it is benchmarked at.
struct Case {
    name: String,
    model: Model,
    q: DVector<f64>,
    v: DVector<f64>,
    tau: DVector<f64>,
}

impl Case {
    /// The state and a [`nearby_state`]: timing loops alternate them so that every call does
    /// the whole work (a repeated `(q, v)` reuses the forward-dynamics kinematics).
    fn states(&self) -> [(DVector<f64>, DVector<f64>); 2] {
        let near = nearby_state(&self.model, &self.q, &self.v).expect("valid state");
        [(self.q.clone(), self.v.clone()), near]
    }
}

/// Dill(n) at the thesis' test state with zero joint torques.
fn dill_case(n: u32) -> Case {
    let model = dill(n).expect("Dill model");
    let (q, v) = dill_test_state(&model);
    let tau = DVector::zeros(model.nv());
    Case {
        name: n.to_string(),
        model,
        q,
        v,
        tau,
    }
}

/// The humanoid URDF to benchmark (TALOS if available, else the bundled G1).
fn humanoid_path() -> PathBuf {
    let talos = std::env::var_os("BIPED_BENCH_URDF")
        .map(PathBuf::from)
        .or_else(|| {
            std::env::var_os("ROBOTS")
                .map(|r| PathBuf::from(r).join("talos_data/robots/talos_full_v2.urdf"))
        });
    match talos {
        Some(p) if p.exists() => p,
        _ => PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/g1_29dof_rev_1_0.urdf"),
    }
}

/// The humanoid with a floating base at a fixed pseudo-random state.
fn humanoid_case() -> Case {
    let path = humanoid_path();
    let options = UrdfOptions {
        floating: true,
        reject_mimic: false,
    };
    let model = load_file(&path, &options).expect("URDF loads").model;
    let wave = |k: usize, f: f64| (f * (k as f64 + 1.0)).sin();
    let mut q = DVector::from_fn(model.nq(), |k, _| wave(k, 0.7));
    q.fixed_rows_mut::<4>(3).normalize_mut();
    let v = DVector::from_fn(model.nv(), |k, _| wave(k, 1.3));
    let tau = DVector::from_fn(model.nv(), |k, _| wave(k, 2.1));
    let name = path.file_stem().unwrap().to_string_lossy().into_owned();
    Case {
        name: format!("{name}_floating"),
        model,
        q,
        v,
        tau,
    }
}

/// Benchmarks every algorithm on `case` (alternating its two states).
fn bench_algorithms(group: &mut BenchmarkGroup<'_, criterion::measurement::WallTime>, case: &Case) {
    let (m, tau, states) = (&case.model, &case.tau, case.states());
    let mut data = Data::new(m);
    let mut k = 0;
    for (name, algo) in ALGORITHMS {
        group.bench_function(BenchmarkId::new(name, &case.name), |b| {
            b.iter(|| {
                k ^= 1;
                let (q, v) = &states[k];
                black_box(forward_dynamics(m, &mut data, q, v, tau, None, algo).is_ok())
            })
        });
    }
}

/// Benchmarks the O(n) passes on `case` (alternating its two states): `fw1`, `fw1_bw` (the
/// backward pass accumulates into the articulated inertias the first pass resets, so
/// BW = fw1_bw - fw1), `fw2` (read-only), and the two phases `fd_kinematics` / `fd_solve` of
/// the split forward dynamics.
fn bench_passes(group: &mut BenchmarkGroup<'_, criterion::measurement::WallTime>, case: &Case) {
    let (m, q, v, tau) = (&case.model, &case.q, &case.v, &case.tau);
    let states = case.states();
    let mut data = Data::new(m);
    let mut k = 0;
    forward_dynamics(m, &mut data, q, v, tau, None, Algorithm::On).expect("valid state");
    group.bench_function(BenchmarkId::new("fw1", &case.name), |b| {
        b.iter(|| {
            k ^= 1;
            let (q, v) = &states[k];
            black_box(on::forward_pass_1(m, &mut data, q, v, None).is_ok())
        })
    });
    group.bench_function(BenchmarkId::new("fw1_bw", &case.name), |b| {
        b.iter(|| {
            k ^= 1;
            let (q, v) = &states[k];
            black_box(on::forward_pass_1(m, &mut data, q, v, None).is_ok());
            black_box(on::backward_pass(m, &mut data, tau).is_ok())
        })
    });
    group.bench_function(BenchmarkId::new("fw2", &case.name), |b| {
        b.iter(|| black_box(on::forward_pass_2(m, &mut data).len()))
    });
    // The two-phase API: kinematics alone, and the solve repeated on fixed kinematics.
    group.bench_function(BenchmarkId::new("fd_kinematics", &case.name), |b| {
        b.iter(|| {
            k ^= 1;
            let (q, v) = &states[k];
            black_box(forward_dynamics_kinematics(m, &mut data, q, v).is_ok())
        })
    });
    forward_dynamics_kinematics(m, &mut data, q, v).expect("valid state");
    group.bench_function(BenchmarkId::new("fd_solve", &case.name), |b| {
        b.iter(|| black_box(forward_dynamics_solve(m, &mut data, tau, None, Algorithm::On).is_ok()))
    });
}

/// Dill(1..10), every algorithm (Fig. 2.19).
fn dill_forward_dynamics(c: &mut Criterion) {
    let mut group = c.benchmark_group("dill_fd");
    group
        .sample_size(20)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    for n in 1..=10 {
        bench_algorithms(&mut group, &dill_case(n));
    }
    group.finish();
}

/// The floating humanoid: every algorithm and the O(n) passes.
fn humanoid_forward_dynamics(c: &mut Criterion) {
    let case = humanoid_case();
    let mut group = c.benchmark_group("humanoid_fd");
    group
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    bench_algorithms(&mut group, &case);
    bench_passes(&mut group, &case);
    group.finish();
}

/// The O(n) passes on Dill(4) and Dill(7) (Fig. 2.21).
fn dill_passes(c: &mut Criterion) {
    let mut group = c.benchmark_group("dill_on_passes");
    group
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    for n in [4, 7] {
        bench_passes(&mut group, &dill_case(n));
    }
    group.finish();
}

criterion_group!(
    benches,
    dill_forward_dynamics,
    humanoid_forward_dynamics,
    dill_passes
);
criterion_main!(benches);
