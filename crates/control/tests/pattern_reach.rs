//! Parameters the legs cannot walk are rejected up front with the valid range in the typed
//! error: steps beyond the legs' reach, step times too short for the swing.

use biped_control::pattern::reach::{max_step_length, min_step_time};
use biped_control::pattern::{PatternError, PatternParams, WalkingPattern};

fn out_of_range(p: &PatternParams) -> (&'static str, f64, f64, f64, String) {
    match WalkingPattern::generate(p) {
        Err(e @ PatternError::OutOfRange { .. }) => {
            let text = e.to_string();
            let PatternError::OutOfRange {
                name,
                value,
                min,
                max,
                ..
            } = e
            else {
                unreachable!()
            };
            (name, value, min, max, text)
        }
        other => panic!("expected OutOfRange, got {:?}", other.map(|w| w.len())),
    }
}

#[test]
fn walkable_parameters_are_accepted() {
    let d = PatternParams::default();
    for (len, time) in [(0.4, 0.8), (0.5, 0.8), (0.5, 0.7), (0.2, 1.2), (-0.3, 0.8)] {
        let p = PatternParams {
            step_length: len,
            step_time: time,
            ..d.clone()
        };
        assert!(WalkingPattern::generate(&p).is_ok(), "{len} m in {time} s");
    }
    assert!(max_step_length(&d) > 0.5 && min_step_time(&d) < 0.7);
}

#[test]
fn step_beyond_the_legs_reach_is_rejected_with_the_range() {
    let d = PatternParams::default();
    let p = PatternParams {
        step_length: 0.6,
        ..d.clone()
    };
    let (name, value, min, max, text) = out_of_range(&p);
    assert_eq!((name, value), ("step_length", 0.6));
    let lateral = d.step_width;
    let expected = (d.reach * d.reach - lateral * lateral).sqrt();
    assert!((max - expected).abs() < 1e-12 && (min + expected).abs() < 1e-12);
    // the printed bounds are rounded inwards, so that they are valid themselves
    let shown = (max * 1e3).floor() / 1e3;
    assert!(
        text.contains(&format!("[{:.3}, {shown:.3}]", -shown)),
        "{text}"
    );
    // a side step takes reach from the forward one
    let side = PatternParams {
        step_length: 0.5,
        step_sideways: 0.2,
        ..d
    };
    assert_eq!(out_of_range(&side).0, "step_length");
}

#[test]
fn step_time_too_short_for_the_swing_is_rejected_with_the_range() {
    let d = PatternParams::default();
    let p = PatternParams {
        step_length: 0.5,
        step_time: 0.5,
        ..d.clone()
    };
    let (name, value, min, max, text) = out_of_range(&p);
    assert_eq!((name, value), ("step_time", 0.5));
    // peak speed of the minimum-jerk swing over twice the step: 15/8 * 1.0 m / ss_time
    let expected = 1.875 * 1.0 / d.max_swing_speed / (1.0 - d.ds_ratio);
    assert!((min - expected).abs() < 1e-12, "{min} vs {expected}");
    assert!(max >= 10.0 && text.contains("swing"), "{text}");
    // a faster swing foot allows it
    let fast = PatternParams {
        max_swing_speed: 8.0,
        ..p
    };
    assert!(WalkingPattern::generate(&fast).is_ok());
}
