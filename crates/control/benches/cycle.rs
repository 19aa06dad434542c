//! One full walking IK cycle on Lola Type 2 (FK, all task Jacobians, SSV update + collision
//! gradient, J_Lz + momentum term, Klein-Huang solve, integration) per method.

use biped_control::ik::{Rmrc, RmrcProblem, TaskBuffers, Weight};
use biped_control::pattern::WalkingPattern;
use biped_control::tasks::{standing_configuration, LolaTasks, TaskId};
use biped_control::walk::{walk_pattern_params, Method, WalkController, WalkParams};
use biped_robots::lola::{self, LolaType};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::DVector;
use std::hint::black_box;

fn cycle(c: &mut Criterion) {
    let lola = lola::build(LolaType::Type2).expect("model");
    let pattern =
        WalkingPattern::generate(&walk_pattern_params(&lola, 2, 0.4, 0.8).expect("params"))
            .expect("pattern");
    // a mid-step sample (single support, arms swinging)
    let k = pattern.len() / 2;
    let sample = pattern.sample(k).expect("sample");
    for method in [Method::Minimization, Method::Compensation] {
        let mut ctrl = WalkController::new(&lola, method, WalkParams::default(), &pattern)
            .expect("controller");
        for s in pattern.samples()[..k].iter() {
            ctrl.cycle(s, 1e-3).expect("cycle");
        }
        // repeated cycles on the same mid-step sample: the full work of a walking cycle
        // (the state stays at the mid-step pose), without per-iteration setup
        c.bench_function(&format!("walk_cycle_{method}"), |b| {
            b.iter(|| black_box(ctrl.cycle(sample, 1e-3).expect("cycle")))
        });
    }
}

/// Parts of the cycle: task evaluation (both kinematics passes, all task Jacobians) and the
/// Klein-Huang solve of the 25 x 31 walking problem.
fn parts(c: &mut Criterion) {
    let lola = lola::build(LolaType::Type2).expect("model");
    let mut tasks = LolaTasks::new(&lola, 0.2).expect("tasks");
    let q = standing_configuration(&lola);
    tasks.set_active_now(TaskId::RightArmCoG, false);
    tasks.set_active_now(TaskId::LeftArmCoG, false);
    let mut buf = TaskBuffers::new(&tasks);
    c.bench_function("walk_tasks_evaluate", |b| {
        b.iter(|| buf.evaluate(&mut tasks, black_box(&q)).expect("evaluate"))
    });
    buf.evaluate(&mut tasks, &q).expect("evaluate");
    let n = lola.model.nv();
    let xd = DVector::from_element(TaskId::TOTAL_ROWS, 0.1);
    let grad = DVector::from_element(n, 0.01);
    let mut w = Weight::rank_one(n, 0.003).expect("weight");
    let u: Vec<f64> = (0..n).map(|i| 0.1 * i as f64).collect();
    w.set_rank_one(0.003, &u).expect("u");
    let mut rmrc = Rmrc::new(TaskId::TOTAL_ROWS, n);
    let mut qd = DVector::zeros(n);
    c.bench_function("rmrc_solve_25x31_rank_one", |b| {
        b.iter(|| {
            let p = RmrcProblem {
                null_space: Some((&grad, 1.0)),
                ..RmrcProblem::new(&buf.jac, buf.rows, &xd, &w)
            };
            rmrc.solve(black_box(&p), &mut qd).expect("solve")
        })
    });
}

criterion_group!(benches, cycle, parts);
criterion_main!(benches);
