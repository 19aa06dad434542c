//! Issue 6 point 8: in a sideways walk the free arms (compensation method) hit the thighs
//! without self-collision avoidance (smallest SSV distance < 0), and with avoidance every
//! segment pair stays apart.

use biped_control::pattern::WalkingPattern;
use biped_control::walk::{run_walk, walk_pattern_params, Method, WalkParams};
use biped_robots::lola::{self, LolaType};

fn min_distance(avoidance: bool) -> f64 {
    let lola = lola::build(LolaType::Type2).unwrap();
    let params = biped_control::pattern::PatternParams {
        step_sideways: 0.12,
        ..walk_pattern_params(&lola, 4, 0.0, 0.8).unwrap()
    };
    let pattern = WalkingPattern::generate(&params).unwrap();
    let walk = WalkParams {
        avoidance,
        // arms hanging close to the body, nearly straight (the scenario's start posture)
        arm_pose: [0.0, -0.07, -0.3],
        ..WalkParams::default()
    };
    let run = run_walk(&lola, &pattern, Method::Compensation, walk).unwrap();
    println!("avoidance {avoidance}: {:?}", run.summary);
    assert!(run.summary.max_task_error < 0.02);
    // the arms start clear of everything: any contact is caused by the walk
    println!("first {}", run.series.min_distance[0]);
    assert!(run.series.min_distance[0] > 0.0);
    run.summary.min_distance
}

#[test]
fn sideways_walk_keeps_arms_off_the_thighs_only_with_avoidance() {
    let off = min_distance(false);
    let on = min_distance(true);
    assert!(off < 0.0, "without avoidance the arms must hit: {off}");
    assert!(
        on > 0.0,
        "with avoidance every distance stays positive: {on}"
    );
}
