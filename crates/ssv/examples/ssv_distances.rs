//! Swept-sphere-volume distances: a few primitive pairs with their hand-computed values, then
//! the bundled humanoid collision model (`data/humanoid.toml`) in its standing posture.
//!
//! Run with `cargo run -p biped_ssv --example ssv_distances` (add `--release` for
//! representative update times; the debug build leaves this crate unoptimised).

use biped_ssv::{distance, format, Lss, PairDistance, Pss, Ssv, Tss};
use nalgebra::Point3;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let p = |x, y, z| Point3::new(x, y, z);
    let ball = Ssv::from(Pss::new(p(0.0, 0.0, 0.0), 1.0)?);
    let bar = Ssv::from(Lss::new(p(3.0, -1.0, 0.0), p(3.0, 1.0, 0.0), 0.5)?);
    let crossing = Ssv::from(Lss::new(p(2.0, 0.0, -1.0), p(2.0, 0.0, 1.0), 0.25)?);
    let plate = Ssv::from(Tss::new(
        p(0.0, 0.0, 0.0),
        p(1.0, 0.0, 0.0),
        p(0.0, 1.0, 0.0),
        0.5,
    )?);
    let arm = Ssv::from(Lss::new(p(0.1, 0.1, 2.0), p(0.2, 0.1, 2.0), 0.5)?);

    // (name, a, b, the distance worked out by hand)
    let cases = [
        ("sphere - capsule", &ball, &bar, 3.0 - 1.0 - 0.5),
        (
            "capsule - capsule (crossed axes)",
            &bar,
            &crossing,
            1.0 - 0.5 - 0.25,
        ),
        ("plate - capsule above it", &plate, &arm, 2.0 - 0.5 - 0.5),
        (
            "sphere - plate (overlapping)",
            &ball,
            &plate,
            0.0 - 1.0 - 0.5,
        ),
    ];
    for (name, a, b, by_hand) in cases {
        let r = distance(a, b);
        println!(
            "{name:34} d = {:+.6} m (by hand {by_hand:+.6}), normal [{:+.3} {:+.3} {:+.3}]",
            r.distance,
            r.normal.x + 0.0, // + 0.0 prints -0 as 0
            r.normal.y + 0.0,
            r.normal.z + 0.0
        );
        assert!((r.distance - by_hand).abs() < 1e-12);
    }

    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/humanoid.toml");
    let mut loaded = format::load(path)?;
    let model = &mut loaded.model;
    println!(
        "data/humanoid.toml: {} segments, {} SSVs, {} pairs, d_a = {} m",
        model.segments().len(),
        model.ssv_count(),
        model.pairs().len(),
        model.activation_distance()
    );
    let standing = &loaded.poses["standing"];
    let updates = 1000;
    let start = Instant::now();
    for _ in 0..updates {
        model.update(standing)?;
    }
    let us = start.elapsed().as_secs_f64() * 1e6 / updates as f64;
    let beyond = model
        .results()
        .iter()
        .filter(|r| matches!(r, PairDistance::Beyond))
        .count();
    let (k, closest) = model.min_distance().ok_or("no pair within d_a")?;
    let pair = model.pairs()[k];
    let name = |i: usize| model.segments()[i].name();
    println!(
        "standing: closest pair {} - {} at {:.6} m, {beyond} pairs beyond d_a, {us:.2} us per update",
        name(pair.a),
        name(pair.b),
        closest.result.distance
    );
    Ok(())
}
