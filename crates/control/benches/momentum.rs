//! Criterion benchmarks of the per-cycle angular momentum work on Lola Type 2 (thesis ch. 7):
//! `J_L`/`J_Lz` (centroidal computation at `q`, incl. kinematics, and the copy alone), the
//! minimisation weight update (7.13) and its `W^-1 x` (7.15); the CoM Jacobian as the
//! baseline the IK cycle pays anyway. The compensation is solved within the IK cycle and
//! timed with it (`benches/cycle.rs`).

use biped_control::momentum::{MomentumMinimisation, VerticalMomentum};
use biped_dynamics::{Centroidal, Data};
use biped_robots::lola::{self, LolaType};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::DVector;
use rand::{Rng, SeedableRng};
use std::hint::black_box;
use std::time::Duration;

fn bench_momentum(c: &mut Criterion) {
    let lm = lola::build(LolaType::Type2).expect("shipped parameter file");
    let m = &lm.model;
    let mut rng = rand::rngs::StdRng::seed_from_u64(1);
    let (q, v) = lm.random_state(&mut |a, b| rng.random_range(a..b));
    let mut data = Data::new(m);
    let mut centroidal = Centroidal::new(m);
    let mut vm = VerticalMomentum::new(m);
    let minimise = MomentumMinimisation::new(0.5).expect("delta > 0");
    let mut w = minimise.weight(m.nv()).expect("weight");
    let mut out = DVector::zeros(m.nv());
    vm.compute(m, &mut data, &mut centroidal, &q).expect("J_L");

    let mut group = c.benchmark_group("momentum_lola_type2");
    group.measurement_time(Duration::from_secs(2));
    group.bench_function("jlz_compute", |b| {
        b.iter(|| vm.compute(m, &mut data, &mut centroidal, black_box(&q)))
    });
    // Baseline: the CoM Jacobian the CoM task needs anyway (same kinematics and columns).
    let mut jc = nalgebra::DMatrix::zeros(3, m.nv());
    group.bench_function("com_jacobian_baseline", |b| {
        b.iter(|| centroidal.com_jacobian(m, &mut data, black_box(&q), &mut jc))
    });
    group.bench_function("jlz_update_only", |b| {
        b.iter(|| vm.update(black_box(&centroidal)))
    });
    group.bench_function("weight_update", |b| {
        b.iter(|| minimise.update(black_box(vm.jacobian_z()), &mut w))
    });
    group.bench_function("weight_solve", |b| {
        b.iter(|| w.solve_into(black_box(&v), &mut out))
    });
    group.bench_function("cycle_total", |b| {
        b.iter(|| {
            vm.compute(m, &mut data, &mut centroidal, black_box(&q))?;
            minimise.update(vm.jacobian_z(), &mut w)
        })
    });
    group.finish();
}

criterion_group!(benches, bench_momentum);
criterion_main!(benches);
