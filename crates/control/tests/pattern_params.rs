//! Pattern parameters: typed validation errors, serde, defaults fitted to the Lola model,
//! and robustness of `generate` on arbitrary input.

use biped_control::pattern::{
    fit, FootGeometry, PatternError, PatternParams, WalkingPattern, LOLA_COM_HEIGHT,
    LOLA_STEP_WIDTH,
};
use biped_robots::lola::{build, LolaType};
use proptest::prelude::*;

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
        n in 0usize..5, len in -1.1f64..1.1, side in -0.55f64..0.55, turn in -0.65f64..0.65,
        width in 0.1f64..0.5, st in 0.1f64..2.0, ds in -0.05f64..1.0, dt in prop_oneof![Just(1e-3), Just(5e-3), Just(0.0)],
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
