//! One full walking IK cycle on Lola Type 2 (FK, all task Jacobians, SSV update + collision
//! gradient, J_Lz + momentum term, Klein-Huang solve, integration) per method.

use biped_control::pattern::WalkingPattern;
use biped_control::walk::{walk_pattern_params, Method, WalkController, WalkParams};
use biped_robots::lola::{self, LolaType};
use criterion::{criterion_group, criterion_main, Criterion};
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

criterion_group!(benches, cycle);
criterion_main!(benches);
