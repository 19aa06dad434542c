//! Harmonic Drive rotor (3.1)-(3.2): pose, Jacobian and bias against finite differences.

mod mech_support;

use biped_dynamics::mechanism::harmonic_drive::{HarmonicDriveParams, HarmonicDriveRotor};
use biped_dynamics::mechanism::{Coupling, MechanismError};
use mech_support::check_coupling;
use nalgebra::{UnitQuaternion, Vector3, Vector6};
use proptest::prelude::*;

fn rotor() -> HarmonicDriveRotor {
    HarmonicDriveRotor::new(HarmonicDriveParams {
        ratio: -100.0,
        orientation: UnitQuaternion::from_euler_angles(0.3, -0.2, 1.1),
        position: Vector3::new(0.01, -0.02, 0.3),
        offset: 0.4,
    })
    .unwrap()
}

#[test]
fn pose_is_initial_orientation_times_spin() {
    let r = rotor();
    let m = r.motion(&[0.25], &[1.0]).unwrap();
    let p = r.params();
    // Independent: the rotor z axis is the initial z axis; the rotor x axis is turned by N q + offset.
    let angle = p.ratio * 0.25 + p.offset;
    let x_expected = p.orientation * Vector3::new(angle.cos(), angle.sin(), 0.0);
    assert!((m.pose.rotation * Vector3::x() - x_expected).norm() < 1e-12);
    assert!((m.pose.rotation * Vector3::z() - p.orientation * Vector3::z()).norm() < 1e-12);
    assert_eq!(m.pose.translation.vector, p.position);
    assert_eq!(
        m.jacobian[0],
        Vector6::new(0.0, 0.0, p.ratio, 0.0, 0.0, 0.0)
    );
    assert_eq!(m.bias, Vector6::zeros());
    assert!((r.joint_angle(r.rotor_angle(0.7)) - 0.7).abs() < 1e-15);
}

#[test]
fn bad_inputs_are_errors() {
    let r = rotor();
    assert!(matches!(
        r.motion(&[0.1, 0.2], &[0.0, 0.0]),
        Err(MechanismError::BadInput { .. })
    ));
    assert!(matches!(
        r.motion(&[f64::NAN], &[0.0]),
        Err(MechanismError::BadInput { .. })
    ));
    let bad = HarmonicDriveParams {
        ratio: 0.0,
        ..Default::default()
    };
    assert!(HarmonicDriveRotor::new(bad).is_err());
    let bad = HarmonicDriveParams {
        ratio: f64::INFINITY,
        ..Default::default()
    };
    assert!(HarmonicDriveRotor::new(bad).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn jacobian_and_bias_match_finite_differences(q in -3.0..3.0f64, qd in -5.0..5.0f64) {
        check_coupling(&rotor(), &[q], &[qd], 1e-6);
    }
}
