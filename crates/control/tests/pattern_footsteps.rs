//! Footstep planner, parameter validation, serde and the defaults fitted to the Lola model.

use biped_control::pattern::footsteps::feet_overlap;
use biped_control::pattern::FootstepPlan;
use biped_control::pattern::{
    fit, Foot, FootGeometry, PatternError, PatternParams, Pose2, WalkingPattern, LOLA_COM_HEIGHT,
    LOLA_STEP_WIDTH,
};
use biped_robots::lola::{build, LolaType};
use proptest::prelude::*;

fn plan(p: &PatternParams) -> FootstepPlan {
    FootstepPlan::new(p).unwrap()
}

#[test]
fn straight_walk_places_each_footprint_one_step_length_ahead() {
    let p = PatternParams::default();
    let steps = plan(&p).steps;
    assert_eq!(steps.len(), 10);
    for (i, s) in steps.iter().enumerate() {
        let k = (i + 1) as f64;
        let x = if i + 1 < p.n_steps {
            k * p.step_length
        } else {
            (k - 1.0) * p.step_length
        };
        let foot = if i % 2 == 0 { Foot::Left } else { Foot::Right };
        assert_eq!(s.foot, foot);
        assert!((s.to.x - x).abs() < 1e-12 && (s.to.y - foot.sign() * 0.09).abs() < 1e-12);
        assert_eq!(s.to.yaw, 0.0);
    }
    // First step is a half step: the foot travels one step length, later ones two.
    assert!((steps[0].to.x - steps[0].from.x - 0.4).abs() < 1e-12);
    assert!((steps[1].to.x - steps[1].from.x - 0.8).abs() < 1e-12);
    assert!(
        (steps[9].to.x - steps[9].from.x - 0.4).abs() < 1e-12,
        "closing half step"
    );
}

#[test]
fn sideways_walk_leading_foot_steps_out_trailing_foot_closes() {
    let (w, dy) = (LOLA_STEP_WIDTH, 0.1);
    for sign in [1.0, -1.0] {
        let p = PatternParams {
            step_length: 0.0,
            step_sideways: sign * dy,
            n_steps: 6,
            ..Default::default()
        };
        let pl = plan(&p);
        let lead = if sign > 0.0 { Foot::Left } else { Foot::Right };
        assert_eq!(pl.steps[0].foot, lead);
        for (i, s) in pl.steps.iter().enumerate() {
            let moved = s.to.y - s.from.y;
            let expect = if i == 5 && s.foot == lead {
                0.0
            } else {
                sign * dy
            };
            assert!((moved - expect).abs() < 1e-12, "step {i}: {moved}");
            assert!(s.to.x.abs() < 1e-12 && s.to.yaw == 0.0);
        }
        // Widths alternate between w + dy (after the leading step) and w.
        for k in 1..=6 {
            let f = pl.stance_after(k);
            let width = f[0].y - f[1].y;
            let expect = if k % 2 == 1 && k < 6 { w + dy } else { w };
            assert!((width - expect).abs() < 1e-12, "after step {k}: {width}");
        }
        let f = pl.stance_after(6);
        assert!(
            (0.5 * (f[0].y + f[1].y) - sign * 3.0 * dy).abs() < 1e-12,
            "3 side steps"
        );
    }
}

#[test]
fn turning_walk_rotates_each_footprint_and_ends_parallel() {
    for (len, turn) in [(0.0, 0.2), (0.2, 0.15), (0.1, -0.25)] {
        let p = PatternParams {
            step_length: len,
            turn_angle: turn,
            n_steps: 9,
            ..Default::default()
        };
        let pl = plan(&p);
        assert_eq!(
            pl.steps[0].foot,
            if turn > 0.0 { Foot::Left } else { Foot::Right }
        );
        for (i, s) in pl.steps.iter().enumerate().take(8) {
            assert!((s.to.yaw - (i + 1) as f64 * turn).abs() < 1e-12);
            // Relative to the stance foot: (length, +-width, turn) in the stance frame.
            let stance = pl.stance_after(i)[s.foot.other().index()];
            let rel = stance.to_local(&s.to.position());
            assert!((rel.x - len).abs() < 1e-12, "step {i}");
            assert!(
                (rel.y - s.foot.sign() * p.step_width).abs() < 1e-12,
                "step {i}"
            );
        }
        let f = pl.stance_after(9);
        assert!((f[0].yaw - 8.0 * turn).abs() < 1e-12 && f[0].yaw == f[1].yaw);
        // Turning on the spot (len = 0) keeps the feet midpoint near the start.
        if len == 0.0 {
            let mid = 0.5 * (f[0].position() + f[1].position());
            assert!(
                mid.norm() < p.step_width,
                "turn on the spot drifts {}",
                mid.norm()
            );
        }
    }
}

#[test]
fn overlap_test_on_foot_rectangles() {
    let foot = FootGeometry::default();
    let at = |x, y, yaw| Pose2 { x, y, yaw };
    assert!(!feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.0, 0.121, 0.0),
        &foot
    ));
    assert!(feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.0, 0.119, 0.0),
        &foot
    ));
    assert!(!feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.221, 0.0, 0.0),
        &foot
    ));
    assert!(feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.219, 0.0, 0.0),
        &foot
    ));
    // Rotated by 90 degrees: the heel (0.09 m) of the other foot points towards -y.
    assert!(feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.0, 0.14, std::f64::consts::FRAC_PI_2),
        &foot
    ));
    assert!(!feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.0, 0.16, std::f64::consts::FRAC_PI_2),
        &foot
    ));
    let narrow = PatternParams {
        step_width: 0.1,
        ..Default::default()
    };
    assert_eq!(
        FootstepPlan::new(&narrow),
        Err(PatternError::FeetOverlap { step: 0 })
    );
    let crossing = PatternParams {
        step_sideways: -0.1,
        step_length: 0.0,
        step_width: 0.15,
        ..Default::default()
    };
    assert!(
        FootstepPlan::new(&crossing).is_ok(),
        "trailing foot closes to the width"
    );
}

#[test]
fn invalid_parameters_are_typed_errors() {
    let d = PatternParams::default();
    let cases: Vec<(&str, PatternParams)> = vec![
        (
            "n_steps",
            PatternParams {
                n_steps: 0,
                ..d.clone()
            },
        ),
        (
            "step_time",
            PatternParams {
                step_time: 0.0,
                ..d.clone()
            },
        ),
        (
            "step_time",
            PatternParams {
                step_time: -0.8,
                ..d.clone()
            },
        ),
        (
            "step_time",
            PatternParams {
                step_time: f64::NAN,
                ..d.clone()
            },
        ),
        (
            "dt",
            PatternParams {
                dt: 0.0,
                ..d.clone()
            },
        ),
        (
            "dt",
            PatternParams {
                dt: -1e-3,
                ..d.clone()
            },
        ),
        (
            "ds_ratio",
            PatternParams {
                ds_ratio: 1.0,
                ..d.clone()
            },
        ),
        (
            "ds_ratio",
            PatternParams {
                ds_ratio: 0.0,
                ..d.clone()
            },
        ),
        (
            "step_length",
            PatternParams {
                step_length: 3.0,
                ..d.clone()
            },
        ),
        (
            "step_sideways",
            PatternParams {
                step_sideways: f64::INFINITY,
                ..d.clone()
            },
        ),
        (
            "turn_angle",
            PatternParams {
                turn_angle: 1.5,
                ..d.clone()
            },
        ),
        (
            "step_height",
            PatternParams {
                step_height: -0.01,
                ..d.clone()
            },
        ),
        (
            "com_height",
            PatternParams {
                com_height: 0.0,
                ..d.clone()
            },
        ),
        (
            "gravity",
            PatternParams {
                gravity: -9.81,
                ..d.clone()
            },
        ),
        (
            "preview_time",
            PatternParams {
                preview_time: 0.0,
                ..d.clone()
            },
        ),
        (
            "input_weight",
            PatternParams {
                input_weight: 0.0,
                ..d.clone()
            },
        ),
        (
            "zmp_weight",
            PatternParams {
                zmp_weight: -1.0,
                ..d.clone()
            },
        ),
        (
            "start_time",
            PatternParams {
                start_time: -1.0,
                ..d.clone()
            },
        ),
        (
            "foot.half_width",
            PatternParams {
                foot: FootGeometry {
                    half_width: f64::NAN,
                    ..d.foot
                },
                ..d.clone()
            },
        ),
        (
            "dt",
            PatternParams {
                dt: 1e-5,
                n_steps: 1000,
                step_time: 10.0,
                ..d.clone()
            },
        ),
    ];
    for (field, p) in cases {
        match WalkingPattern::generate(&p) {
            Err(PatternError::InvalidParameter { name, .. }) => assert_eq!(name, field),
            other => panic!(
                "{field}: expected InvalidParameter, got {:?}",
                other.map(|w| w.len())
            ),
        }
    }
}

#[test]
fn params_serde_round_trip_and_partial_files() {
    let d = PatternParams::default();
    let json = serde_json::to_string(&d).unwrap();
    assert_eq!(serde_json::from_str::<PatternParams>(&json).unwrap(), d);
    let t = toml::to_string(&d).unwrap();
    assert_eq!(toml::from_str::<PatternParams>(&t).unwrap(), d);
    let partial: PatternParams =
        toml::from_str("n_steps = 4\nturn_angle = 0.1\n[foot]\nfront = 0.15\n").unwrap();
    assert_eq!(partial.n_steps, 4);
    assert_eq!(partial.foot.front, 0.15);
    assert_eq!(partial.foot.back, d.foot.back);
    assert_eq!(partial.step_time, 0.8);
    assert!(
        toml::from_str::<PatternParams>("step_lenght = 0.3").is_err(),
        "typo rejected"
    );
}

#[test]
fn defaults_are_fitted_to_the_lola_model() {
    let lola = build(LolaType::Type2).unwrap();
    let h = fit::standing_com_height(&lola, 0.4).unwrap();
    assert!(
        (h - LOLA_COM_HEIGHT).abs() < 5e-3,
        "standing CoM height {h}"
    );
    // Straighter knees raise the CoM.
    assert!(fit::standing_com_height(&lola, 0.2).unwrap() > h);
    assert!((fit::hip_spacing(&lola).unwrap() - LOLA_STEP_WIDTH).abs() < 1e-12);
    let d = PatternParams::default();
    assert_eq!((d.n_steps, d.step_length, d.step_time), (10, 0.4, 0.8));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    /// Any parameter set gives a finite pattern or a typed error, never a panic or NaN.
    #[test]
    fn generate_never_panics_or_returns_nan(
        n in 0usize..5, len in -1.5f64..1.5, side in -0.6f64..0.6, turn in -0.8f64..0.8,
        width in 0.0f64..0.5, st in -0.5f64..2.0, ds in -0.2f64..1.2, dt in prop_oneof![Just(1e-3), Just(5e-3), Just(0.0)],
    ) {
        let p = PatternParams { n_steps: n, step_length: len, step_sideways: side, turn_angle: turn,
            step_width: width, step_time: st, ds_ratio: ds, dt, ..Default::default() };
        if let Ok(w) = WalkingPattern::generate(&p) {
            prop_assert!(w.iter().all(|s| s.com.iter().chain(s.com_acc.iter()).chain(s.zmp.iter())
                .chain(s.feet[0].linear.iter()).chain(s.feet[1].pose.translation.vector.iter())
                .all(|v| v.is_finite())));
        }
    }
}
