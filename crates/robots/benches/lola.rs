//! Criterion benchmarks of forward dynamics on the Lola-like models Type 2 and Type 3 (thesis
//! 2.10.2, Table 2.6 / Fig. 2.21): O(n) with sub-systems, CRBA + Cholesky, CRBA + sparse
//! `L^T L`, and the three O(n) passes, alternating two reproducible random states inside the joint ranges (a repeated state would
//! reuse the forward-dynamics kinematics);
//! plus the inverse-kinematics path: forward kinematics, world Jacobian columns and the
//! centroidal momentum matrix `A_G`.

use biped_dynamics::{
    forward_dynamics, forward_kinematics, on, Algorithm, Centroidal, Data, Jacobians,
};
use biped_robots::lola::{self, LolaType};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::DVector;
use rand::{Rng, SeedableRng};
use std::hint::black_box;
use std::time::Duration;

/// The three forward-dynamics algorithms with their benchmark names.
const ALGORITHMS: [(&str, Algorithm); 3] = [
    ("on", Algorithm::On),
    ("crba", Algorithm::Crba),
    ("sparse", Algorithm::Sparse),
];

/// Whole calls per algorithm and the O(n) passes, per model type.
fn bench_lola(c: &mut Criterion) {
    for (name, kind) in [("type2", LolaType::Type2), ("type3", LolaType::Type3)] {
        let lm = lola::build(kind).expect("shipped parameter file");
        let m = &lm.model;
        let mut rng = rand::rngs::StdRng::seed_from_u64(1);
        let (q, v) = lm.random_state(&mut |a, b| rng.random_range(a..b));
        let states = [
            (q.clone(), v.clone()),
            lm.random_state(&mut |a, b| rng.random_range(a..b)),
        ];
        let mut k = 0;
        let tau = DVector::from_fn(m.nv(), |_, _| rng.random_range(-1.0..1.0));
        let mut data = Data::new(m);
        let mut group = c.benchmark_group(format!("lola_{name}"));
        group.measurement_time(Duration::from_secs(2));
        for (algo_name, algo) in ALGORITHMS {
            group.bench_function(algo_name, |b| {
                b.iter(|| {
                    k ^= 1;
                    let (q, v) = &states[k];
                    black_box(forward_dynamics(m, &mut data, q, v, &tau, None, algo).is_ok())
                })
            });
        }
        group.bench_function("on_fw1", |b| {
            b.iter(|| {
                k ^= 1;
                let (q, v) = &states[k];
                black_box(on::forward_pass_1(m, &mut data, q, v, None).is_ok())
            })
        });
        group.bench_function("on_fw1_bw", |b| {
            b.iter(|| {
                k ^= 1;
                let (q, v) = &states[k];
                black_box(on::forward_pass_1(m, &mut data, q, v, None).is_ok());
                black_box(on::backward_pass(m, &mut data, &tau).is_ok())
            })
        });
        group.bench_function("on_fw2", |b| {
            b.iter(|| black_box(on::forward_pass_2(m, &mut data).len()))
        });
        let mut jac = Jacobians::new(m);
        let mut cen = Centroidal::new(m);
        group.bench_function("fk", |b| {
            b.iter(|| black_box(forward_kinematics(m, &mut data, &q, &v, &tau).is_ok()))
        });
        group.bench_function("jacobians", |b| {
            b.iter(|| black_box(jac.compute(m, &mut data, &q).is_ok()))
        });
        group.bench_function("centroidal_matrix", |b| {
            b.iter(|| black_box(cen.compute_matrix(m, &mut data, &q).is_ok()))
        });
        group.finish();
    }
}

criterion_group!(benches, bench_lola);
criterion_main!(benches);
