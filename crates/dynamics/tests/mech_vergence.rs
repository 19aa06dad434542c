//! Camera vergence drive (3.38)-(3.45): lever angle, Jacobian and its derivative against finite
//! differences and a hand-derived form of (3.44); loop closure; out-of-range errors.

mod mech_support;

use biped_dynamics::mechanism::vergence::{VergenceDrive, VergenceParams};
use biped_dynamics::mechanism::MechanismError;
use nalgebra::Vector2;
use proptest::prelude::*;

fn drive() -> VergenceDrive {
    VergenceDrive::new(VergenceParams::default()).unwrap()
}

/// (3.44) derived by hand from (3.40)-(3.42) with `A_tk = A_y(q / 2)`:
/// `dphi/dq = [2 r_bz (r_ax - r_bx) r_bx' + (s - 2 r_bz^2) r_bz'] / (2 l r_bz^2 sqrt(1 - c^2))`.
fn hand_jacobian(p: &VergenceParams, q: f64) -> f64 {
    let (kx, kz) = (p.receptacle_joint.x, p.receptacle_joint.y);
    let (c, s) = ((0.5 * q).cos(), (0.5 * q).sin());
    // A_y(t) (x, 0, z) = (x cos t + z sin t, 0, -x sin t + z cos t).
    let rbx = p.receptacle_pivot.x + kx * c + kz * s;
    let rbz = p.receptacle_pivot.y - kx * s + kz * c;
    let (drbx, drbz) = (0.5 * (-kx * s + kz * c), 0.5 * (-kx * c - kz * s)); // (3.45)
    let l = p.lever_length;
    let sv = (p.lever_axis_x - rbx).powi(2) + l * l - p.coupler_length.powi(2) + rbz * rbz;
    let cv = sv / (2.0 * l * rbz);
    (2.0 * rbz * (p.lever_axis_x - rbx) * drbx + (sv - 2.0 * rbz * rbz) * drbz)
        / (2.0 * l * rbz * rbz * (1.0 - cv * cv).sqrt())
}

#[test]
fn default_lever_is_at_ninety_degrees_and_motor_zero_at_zero_vergence() {
    let k = drive().lever(0.0).unwrap();
    assert!((k.phi - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    assert_eq!(k.motor_angle, 0.0);
}

#[test]
fn loop_closes_over_the_range() {
    let d = drive();
    let p = *d.params();
    for i in 0..=100 {
        let q = p.q_min + (p.q_max - p.q_min) * f64::from(i) / 100.0;
        let (a, b) = d.joint_points(q).unwrap();
        assert!(
            ((a - b).norm() - p.coupler_length).abs() < 1e-12,
            "(3.39) at {q}"
        );
        assert!(b.y.abs() < 1e-15);
        let k = d.lever(q).unwrap();
        assert!((k.motor_angle - p.ratio * (k.phi - d.phi_lever(0.0).unwrap())).abs() < 1e-12);
    }
}

#[test]
fn out_of_range_and_bad_parameters_are_errors() {
    let d = drive();
    assert!(matches!(
        d.lever(3.0),
        Err(MechanismError::OutOfRange { .. })
    ));
    assert!(matches!(
        d.lever(f64::NAN),
        Err(MechanismError::BadInput { .. })
    ));
    let base = VergenceParams::default();
    for bad in [
        VergenceParams {
            lever_length: 0.0,
            ..base
        },
        VergenceParams {
            coupler_length: -1.0,
            ..base
        },
        VergenceParams { ratio: 0.0, ..base },
        VergenceParams {
            q_min: 0.5,
            q_max: 0.0,
            ..base
        },
        VergenceParams { q_max: 3.0, ..base },
        VergenceParams {
            receptacle_joint: Vector2::new(f64::INFINITY, 0.0),
            ..base
        },
    ] {
        assert!(VergenceDrive::new(bad).is_err(), "{bad:?}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]
    #[test]
    fn jacobian_and_derivative_match_finite_differences(q in -0.3..0.6f64) {
        let d = drive();
        let h = 1e-6;
        let k = d.lever(q).unwrap();
        let (kp, km) = (d.lever(q + h).unwrap(), d.lever(q - h).unwrap());
        prop_assert!((k.jacobian - (kp.phi - km.phi) / (2.0 * h)).abs() < 1e-8);
        prop_assert!((k.djacobian - (kp.jacobian - km.jacobian) / (2.0 * h)).abs() < 1e-7);
        prop_assert!((k.jacobian - hand_jacobian(d.params(), q)).abs() < 1e-12);
    }
}
