//! Criterion benchmark of the collision gradient per IK cycle on the Lola-like robot (thesis
//! ch. 5): SSV model update (WithinActivation) plus the `J^T f` products of the active pairs,
//! at a reproducible walking-like pose with a few active pairs, at the neutral pose (no active
//! pair: enlarged-OBB checks only), and the Jacobian columns (`Jacobians::compute`) for scale.

use biped_control::avoidance::{AvoidanceParams, CollisionAvoidance};
use biped_dynamics::{Data, Jacobians};
use biped_robots::lola::{self, lola_collision_model, LolaType};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::DVector;
use rand::{Rng, SeedableRng};
use std::hint::black_box;
use std::time::Duration;

fn bench_avoidance(c: &mut Criterion) {
    let lm = lola::build(LolaType::Type2).expect("shipped parameter file");
    let m = &lm.model;
    let cm = lola_collision_model(&lm).expect("shipped SSV file").model;
    let mut av = CollisionAvoidance::new(m, cm, AvoidanceParams::default()).expect("valid");
    let mut data = Data::new(m);
    let mut jac = Jacobians::new(m);
    let mut grad = DVector::zeros(m.nv());
    // A walking-like pose (joints within 30 % of their ranges) with 2 to 4 active pairs.
    let mut rng = rand::rngs::StdRng::seed_from_u64(2);
    let mut q = m.neutral();
    for _ in 0..100_000 {
        q = m.neutral();
        for l in &lm.limits {
            q[l.q_index] = 0.3 * rng.random_range(l.lower..l.upper);
        }
        jac.compute(m, &mut data, &q).expect("valid pose");
        let s = av.gradient(m, &data, &jac, &mut grad).expect("sizes");
        if (2..=4).contains(&s.active) {
            println!(
                "bench pose: {} active pairs, min distance {:?}",
                s.active, s.min_distance
            );
            break;
        }
    }
    let mut group = c.benchmark_group("avoidance");
    group.measurement_time(Duration::from_secs(3));
    group.bench_function("gradient_active", |b| {
        b.iter(|| black_box(av.gradient(m, &data, &jac, &mut grad).is_ok()))
    });
    group.bench_function("jacobians_compute", |b| {
        b.iter(|| black_box(jac.compute(m, &mut data, &q).is_ok()))
    });
    let q0 = m.neutral();
    jac.compute(m, &mut data, &q0).expect("neutral");
    group.bench_function("gradient_neutral", |b| {
        b.iter(|| black_box(av.gradient(m, &data, &jac, &mut grad).is_ok()))
    });
    group.bench_function("global_minimum", |b| {
        b.iter(|| black_box(av.global_minimum().is_some()))
    });
    group.finish();
}

criterion_group!(benches, bench_avoidance);
criterion_main!(benches);
