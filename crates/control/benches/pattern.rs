//! Walking pattern generation: a full 10-step pattern (default parameters, 1 ms samples) and
//! its parts (preview servo setup, CoM tracking of one axis).

use biped_control::pattern::preview::PreviewController;
use biped_control::pattern::{PatternParams, WalkingPattern};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::Vector3;
use std::hint::black_box;

fn bench_pattern(c: &mut Criterion) {
    let p = PatternParams::default();
    let mut g = c.benchmark_group("pattern");
    g.sample_size(20);
    g.bench_function("generate_10_steps", |b| {
        b.iter(|| WalkingPattern::generate(black_box(&p)).map(|w| w.len()))
    });
    let weights = (p.zmp_weight, p.state_weight, p.input_weight);
    let horizon = (p.preview_time / p.dt).round() as usize;
    g.bench_function("preview_controller_new", |b| {
        b.iter(|| {
            PreviewController::new(p.com_height, p.gravity, p.dt, weights, black_box(horizon))
        })
    });
    let walk = WalkingPattern::generate(&p).expect("default pattern");
    let reference: Vec<f64> = walk.iter().map(|s| s.zmp_ref.x).collect();
    let ctrl = walk.controller();
    let mut out = Vec::with_capacity(reference.len());
    g.bench_function("track_one_axis", |b| {
        b.iter(|| ctrl.track(black_box(&reference), &Vector3::zeros(), &mut out))
    });
    g.finish();
}

criterion_group!(benches, bench_pattern);
criterion_main!(benches);
