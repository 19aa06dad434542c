//! Repulsive laws (5.11), (5.12), (5.15): continuity, limits, potentials, validation.

use biped_control::avoidance::{AvoidanceError, RepulsiveLaw};
use proptest::prelude::*;

const D_A: f64 = 0.04;

fn blended(s0: f64, t: f64) -> RepulsiveLaw {
    RepulsiveLaw::Blended { s0, t }
}

proptest! {
    /// g_m is continuous with a continuous slope at t d_a: one-sided difference quotients from
    /// both sides agree (no value derived by hand).
    #[test]
    fn blended_is_c1_at_the_junction(s0 in 0.1f64..10.0, t in 0.05f64..0.95, d_a in 0.01f64..0.2) {
        let law = blended(s0, t);
        let (x, h) = (t * d_a, 1e-7 * d_a);
        let (left, right) = (law.g(x - h, d_a), law.g(x + h, d_a));
        prop_assert!((left - right).abs() <= 1e-5 * s0);
        let slope_left = (law.g(x - h, d_a) - law.g(x - 2.0 * h, d_a)) / h;
        let slope_right = (law.g(x + 2.0 * h, d_a) - law.g(x + h, d_a)) / h;
        prop_assert!((slope_left - slope_right).abs() <= 1e-4 * slope_left.abs());
    }

    /// g >= 0, non-increasing, zero from d_a on; and dH/dd = -g by central differences. The
    /// difference quotient is minus the mean of g over [d - h, d + h], so for a monotone g it
    /// is within g(d - h) - g(d + h) of -g(d) (exact also where g's slope jumps, e.g. at d_a),
    /// plus rounding.
    #[test]
    fn laws_are_positive_decreasing_and_potentials_integrate_them(
        s0 in 0.1f64..10.0, t in 0.0f64..=1.0, d in -0.05f64..0.06,
    ) {
        for law in [blended(s0, t), RepulsiveLaw::Linear { m: -s0 / D_A },
                    RepulsiveLaw::Quadratic { s: s0 / (D_A * D_A) }] {
            let (g, g2) = (law.g(d, D_A), law.g(d + 1e-4, D_A));
            prop_assert!(g >= 0.0 && g2 <= g + 1e-15);
            prop_assert!(law.potential(d, D_A) >= 0.0);
            if d >= D_A {
                prop_assert_eq!(g, 0.0);
                prop_assert_eq!(law.potential(d, D_A), 0.0);
            }
            let h = 1e-6;
            let fd = (law.potential(d + h, D_A) - law.potential(d - h, D_A)) / (2.0 * h);
            let spread = law.g(d - h, D_A) - law.g(d + h, D_A);
            prop_assert!(
                (fd + g).abs() <= spread + 1e-6 * (1.0 + g),
                "{law:?} d={d} fd={fd} g={g} spread={spread}"
            );
        }
    }
}

/// The law vanishes at d_a and its potential too (both sides of d_a).
#[test]
fn zero_at_activation_distance() {
    for law in [
        blended(2.0, 0.5),
        RepulsiveLaw::Linear { m: -3.0 },
        RepulsiveLaw::Quadratic { s: 5.0 },
    ] {
        assert_eq!(law.g(D_A, D_A), 0.0);
        assert!(law.g(D_A * (1.0 - 1e-9), D_A) < 1e-6);
        assert_eq!(law.potential(D_A, D_A), 0.0);
        assert!(law.g(0.5 * D_A, D_A) > 0.0);
    }
}

/// t = 0 gives the quadratic law s (d - d_a)^2 with s = s0 / d_a^2 on [0, d_a]; t = 1 the
/// linear law m (d - d_a) with m = -s0 / d_a (both from g(0) = s0 and g(d_a) = 0), and the
/// potentials agree as well.
#[test]
fn blend_limits_are_the_quadratic_and_linear_laws() {
    let s0 = 3.0;
    let quadratic = RepulsiveLaw::Quadratic {
        s: s0 / (D_A * D_A),
    };
    let linear = RepulsiveLaw::Linear { m: -s0 / D_A };
    for k in 0..=100 {
        let d = D_A * (k as f64 / 100.0);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + a.abs());
        assert!(close(blended(s0, 0.0).g(d, D_A), quadratic.g(d, D_A)));
        assert!(close(blended(s0, 1.0).g(d, D_A), linear.g(d, D_A)));
        let q = blended(s0, 0.0).potential(d, D_A);
        assert!(close(q, quadratic.potential(d, D_A)));
        let l = blended(s0, 1.0).potential(d, D_A);
        assert!(close(l, linear.potential(d, D_A)));
        // The penetration side d < 0 of the linear law continues the line.
        assert!(close(blended(s0, 1.0).g(-d, D_A), linear.g(-d, D_A)));
    }
    assert_eq!(blended(s0, 0.5).g(0.0, D_A), s0);
}

#[test]
fn bad_parameters_are_rejected() {
    for law in [
        blended(0.0, 0.5),
        blended(1.0, -0.1),
        blended(1.0, 1.5),
        blended(f64::NAN, 0.5),
        blended(1.0, f64::NAN),
        RepulsiveLaw::Linear { m: 1.0 },
        RepulsiveLaw::Linear {
            m: f64::NEG_INFINITY,
        },
        RepulsiveLaw::Quadratic { s: -1.0 },
    ] {
        assert!(
            matches!(law.validate(), Err(AvoidanceError::BadLaw(_))),
            "{law:?}"
        );
    }
    assert!(RepulsiveLaw::default().validate().is_ok());
}
