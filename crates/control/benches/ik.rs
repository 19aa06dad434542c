//! Criterion benchmark of one RMRC cycle on Lola Type 2 with all tasks but the arm CoGs
//! (25 rows, 31 DoF): centroidal + Jacobian passes, task stacking, joint-cost gradient and
//! the Klein-Huang solve (Algorithm 4.3), plus the parts separately.

use biped_control::ik::{
    ClosedLoopIk, CycleInput, Rmrc, RmrcProblem, TaskBuffers, TaskMap, Weight,
};
use biped_control::tasks::{lola_joint_cost, standing_configuration, LolaTasks, TaskId};
use biped_robots::lola::{build, LolaType};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::{DVector, Vector3};
use std::hint::black_box;

fn bench_ik(c: &mut Criterion) {
    let lola = build(LolaType::Type2).expect("shipped parameter file");
    let mut tasks = LolaTasks::new(&lola, 0.2).expect("Lola task set");
    let q = standing_configuration(&lola);
    tasks.set_targets_from(&q).expect("valid pose");
    tasks.targets.cog += Vector3::new(0.01, 0.02, -0.01);
    tasks.set_active_now(TaskId::RightArmCoG, false);
    tasks.set_active_now(TaskId::LeftArmCoG, false);
    let cost = lola_joint_cost(&lola, &q, 1.0, 0.1, 0.1).expect("valid cost");
    let mut grad = DVector::zeros(tasks.nv());
    let mut cl = ClosedLoopIk::new(&tasks);
    let weight = Weight::Diagonal(DVector::from_element(tasks.nv(), 1.0));
    c.bench_function("ik_rmrc_cycle_lola_no_arms", |b| {
        b.iter(|| {
            cost.gradient_into(&q, &mut grad).expect("sizes");
            let input = CycleInput {
                gain: 100.0,
                weight: &weight,
                null_space: Some((&grad, 0.1)),
                damping: 0.0,
                dt: 1e-3,
            };
            black_box(
                cl.velocities(&mut tasks, black_box(&q), &input)
                    .expect("solvable")[0],
            )
        })
    });
    let mut buf = TaskBuffers::new(&tasks);
    c.bench_function("ik_lola_tasks_evaluate_no_arms", |b| {
        b.iter(|| buf.evaluate(&mut tasks, black_box(&q)).expect("valid pose"))
    });
    let mut rmrc = Rmrc::new(buf.jac.nrows(), tasks.nv());
    let mut qd = DVector::zeros(tasks.nv());
    c.bench_function("ik_klein_huang_solve_25x31", |b| {
        b.iter(|| {
            let mut p = RmrcProblem::new(&buf.jac, buf.rows, &buf.err, &weight);
            p.null_space = Some((&grad, 0.1));
            rmrc.solve(&p, &mut qd).expect("solvable");
            black_box(qd[0])
        })
    });
}

criterion_group!(benches, bench_ik);
criterion_main!(benches);
