//! Input validation of the SSV constructors: non-finite coordinates or radius and negative
//! radii give a typed `SsvError`, never a panic; valid input is accepted.

use biped_ssv::{distance, Lss, Pss, Ssv, SsvError, Tss};
use nalgebra::Point3;
use proptest::prelude::*;

const BAD: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

/// Builds an SSV with `n` vertices from 3n coordinates and a radius.
fn build(n: usize, c: &[f64; 9], r: f64) -> Result<Ssv, SsvError> {
    let v = |i: usize| Point3::new(c[3 * i], c[3 * i + 1], c[3 * i + 2]);
    Ok(match n {
        1 => Pss::new(v(0), r)?.into(),
        2 => Lss::new(v(0), v(1), r)?.into(),
        _ => Tss::new(v(0), v(1), v(2), r)?.into(),
    })
}

/// Same value, NaN included.
fn same(x: f64, y: f64) -> bool {
    x == y || (x.is_nan() && y.is_nan())
}

#[test]
fn every_non_finite_coordinate_is_rejected_and_named() {
    for n in 1..=3 {
        for slot in 0..3 * n {
            for bad in BAD {
                let mut c = [0.5; 9];
                c[slot] = bad;
                match build(n, &c, 1.0) {
                    Err(SsvError::NonFinite { what, value }) => {
                        assert!(same(value, bad), "value {value} for {bad}");
                        let axis = ["x", "y", "z"][slot % 3];
                        assert!(what.ends_with(axis), "{what} should name axis {axis}");
                        let item = if n == 1 {
                            "center".to_string()
                        } else {
                            format!("vertex {}", slot / 3)
                        };
                        assert!(what.starts_with(&item), "{what} should name {item}");
                    }
                    other => panic!("n={n} slot={slot} bad={bad}: {other:?}"),
                }
            }
        }
    }
}

#[test]
fn non_finite_and_negative_radii_are_rejected() {
    for n in 1..=3 {
        for bad in BAD {
            match build(n, &[0.0; 9], bad) {
                Err(SsvError::NonFinite { what, value }) => {
                    assert_eq!(what, "radius");
                    assert!(same(value, bad));
                }
                other => panic!("n={n} r={bad}: {other:?}"),
            }
        }
        for neg in [-1.0, -1e-300, -f64::MIN_POSITIVE, -5e-324, -f64::MAX] {
            assert_eq!(
                build(n, &[0.0; 9], neg).unwrap_err(),
                SsvError::NegativeRadius(neg)
            );
        }
    }
}

#[test]
fn boundary_values_are_accepted() {
    // Zero radius (either sign of zero), subnormal and the largest supported values are valid.
    let max = biped_ssv::primitives::MAX_MAGNITUDE;
    for n in 1..=3 {
        for r in [0.0, -0.0, 5e-324, max] {
            assert!(build(n, &[0.0; 9], r).is_ok(), "n={n} r={r}");
        }
        assert!(build(n, &[max; 9], 1.0).is_ok());
        assert!(build(n, &[-5e-324; 9], 1.0).is_ok());
    }
}

#[test]
fn error_messages_name_the_problem() {
    let e = Pss::new(Point3::new(0.0, f64::NAN, 0.0), 1.0).unwrap_err();
    assert_eq!(e.to_string(), "center y is not finite (NaN)");
    let e = Lss::new(Point3::origin(), Point3::origin(), -2.0).unwrap_err();
    assert_eq!(e.to_string(), "radius must be >= 0, got -2");
}

/// A coordinate: mostly finite, sometimes NaN or infinite.
fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -1e6..1e6f64,
        1 => prop::sample::select(BAD.to_vec()),
    ]
}

/// A radius: mostly valid, sometimes negative or non-finite.
fn rad() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => 0.0..1e3f64,
        1 => -1e3..0.0f64,
        1 => prop::sample::select(BAD.to_vec()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20_000))]
    /// Err exactly when some input is invalid; valid SSVs then give finite distances.
    #[test]
    fn constructors_never_panic(
        n in 1usize..=3,
        c in prop::array::uniform9(coord()),
        r in rad(),
        m in 1usize..=3,
        d in prop::array::uniform9(-1e6..1e6f64),
    ) {
        let used = &c[..3 * n];
        let valid = used.iter().all(|x| x.is_finite()) && r.is_finite() && r >= 0.0;
        let built = build(n, &c, r);
        prop_assert_eq!(built.is_ok(), valid, "{:?}", built);
        if let Ok(a) = built {
            let b = build(m, &d, 1.0).expect("valid");
            let res = distance(&a, &b);
            prop_assert!(res.distance.is_finite() && (res.normal.norm() - 1.0).abs() < 1e-12);
        }
    }
}

/// Magnitudes up to `MAX_MAGNITUDE` give finite results; larger ones are rejected by the
/// constructors (the formulas form fourth powers of coordinates).
#[test]
fn huge_finite_coordinates_give_finite_results_or_errors() {
    for m in [1e20, 1e40, biped_ssv::primitives::MAX_MAGNITUDE] {
        check_huge(m);
    }
    for m in [1e51, 1e155, f64::MAX] {
        let err = Pss::new(Point3::new(m, 0.0, 0.0), 0.0).unwrap_err();
        assert!(
            matches!(err, biped_ssv::SsvError::OutOfRange { .. }),
            "{err}"
        );
        let err = Lss::new(Point3::origin(), Point3::origin(), m).unwrap_err();
        assert!(
            matches!(err, biped_ssv::SsvError::OutOfRange { .. }),
            "{err}"
        );
    }
}

fn check_huge(m: f64) {
    let p = Point3::new;
    let shapes: [Ssv; 3] = [
        Pss::new(p(m, m, m), 0.0).unwrap().into(),
        Lss::new(p(-m, 0.0, 0.0), p(m, 1.0, 0.0), 0.0)
            .unwrap()
            .into(),
        Tss::new(p(0.0, -m, 1.0), p(0.0, m, 1.0), p(m, 0.0, m), 0.0)
            .unwrap()
            .into(),
    ];
    for a in &shapes {
        for b in &shapes {
            let r = distance(a, b);
            assert!(r.distance.is_finite(), "m={m:e}: {r:?}");
            assert!((r.normal.norm() - 1.0).abs() < 1e-12, "m={m:e}: {r:?}");
        }
    }
}
