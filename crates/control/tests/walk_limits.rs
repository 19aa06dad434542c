//! Joint limits kept by the walk: the default walk of every arm method stays inside every
//! joint range (`min_joint_margin >= 0`) with its segments apart, and random walks (step
//! length 0.2-0.5 m, step time 0.7-1.2 s, turning) never take a joint past its range.

use biped_control::pattern::WalkingPattern;
use biped_control::walk::{run_walk, walk_pattern_params, Method, WalkController, WalkParams};
use biped_robots::lola::{self, LolaModel, LolaType};
use proptest::prelude::*;

/// Smallest distance of a joint of `lola` to its nearer limit at `q`.
fn margin(lola: &LolaModel, q: &nalgebra::DVector<f64>) -> f64 {
    lola.limits
        .iter()
        .map(|l| (q[l.q_index] - l.lower).min(l.upper - q[l.q_index]))
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn default_walk_keeps_every_joint_in_range_for_every_method() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let params = walk_pattern_params(&lola, 10, 0.4, 0.8).unwrap();
    let pattern = WalkingPattern::generate(&params).unwrap();
    for method in Method::ALL {
        let s = run_walk(&lola, &pattern, method, WalkParams::default())
            .unwrap()
            .summary;
        println!("{method}: {s:?}");
        assert!(
            s.min_joint_margin >= 0.0,
            "{method}: margin {}",
            s.min_joint_margin
        );
        assert!(
            s.min_distance > 0.0,
            "{method}: min distance {}",
            s.min_distance
        );
        assert!(
            s.max_task_error < 0.01,
            "{method}: task error {}",
            s.max_task_error
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]
    /// Random walks of 4 steps (16 cases): every cycle keeps every joint inside its range.
    #[test]
    fn random_walks_keep_the_joint_ranges(
        len in 0.2f64..0.5, time in 0.7f64..1.2, turn in -0.6f64..0.6, m in 0usize..4,
    ) {
        let lola = lola::build(LolaType::Type2).unwrap();
        let mut params = walk_pattern_params(&lola, 4, len, time).unwrap();
        params.turn_angle = turn;
        let pattern = WalkingPattern::generate(&params);
        prop_assume!(pattern.is_ok());
        let pattern = pattern.unwrap();
        let method = Method::ALL[m];
        let mut ctrl = WalkController::new(&lola, method, WalkParams::default(), &pattern).unwrap();
        let mut worst = f64::INFINITY;
        for s in pattern.iter() {
            ctrl.cycle(s, params.dt).unwrap();
            worst = worst.min(margin(&lola, ctrl.q()));
        }
        prop_assert!(worst >= 0.0, "{method} len {len} time {time} turn {turn}: margin {worst}");
    }
}
