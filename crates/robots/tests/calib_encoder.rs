//! Encoder conversions of the knee and ankle drives (thesis 3.5, footnote 5) and the SO(3)
//! log map used by the orientation residual.

use biped_dynamics::mechanism::ankle::{AnkleDrive, AnkleDriveParams};
use biped_dynamics::mechanism::knee::{KneeDrive, KneeDriveParams};
use biped_robots::calibration::{
    ankle_angles_from_counts, ankle_counts, knee_angle_from_counts, knee_counts, so3_log,
    IncrementalEncoder,
};
use nalgebra::{Rotation3, Unit, Vector2, Vector3};
use proptest::prelude::*;

fn encoder() -> IncrementalEncoder {
    IncrementalEncoder::new(4.0 * 2048.0).unwrap()
}

proptest! {
    #[test]
    fn knee_round_trip(q in -0.04f64..1.99) {
        let drive = KneeDrive::new(KneeDriveParams::default()).unwrap();
        let enc = encoder();
        let counts = knee_counts(&drive, &enc, q).unwrap();
        let back = knee_angle_from_counts(&drive, &enc, counts).unwrap();
        // Quantisation: half a count of motor angle through the local ratio dmotor/dq.
        let ratio = drive.screw_ratio() * drive.transmission(q).unwrap().dtravel.abs();
        prop_assert!((back - q).abs() <= 0.5 * enc.resolution() / ratio * 1.01 + 1e-12);
        // Counts -> angle -> counts is the identity.
        prop_assert_eq!(knee_counts(&drive, &enc, back).unwrap(), counts);
    }

    #[test]
    fn ankle_round_trip(f in -0.45f64..0.35, a in -0.2f64..0.2) {
        let drive = AnkleDrive::new(AnkleDriveParams::default()).unwrap();
        let enc = encoder();
        let counts = ankle_counts(&drive, &enc, [f, a]).unwrap();
        let back = ankle_angles_from_counts(&drive, &enc, counts, None).unwrap();
        // Bound the error by the inverse 2x2 transmission applied to the quantisation box.
        let t = drive.transmission([f, a], [0.0; 2]).unwrap();
        let inv = (t.jacobian * drive.screw_ratio()).try_inverse().unwrap();
        let bound = inv.abs() * Vector2::new(0.5, 0.5) * enc.resolution();
        prop_assert!((back[0] - f).abs() <= bound.x * 1.05 + 1e-12, "{:?} vs {:?}", back, (f, a));
        prop_assert!((back[1] - a).abs() <= bound.y * 1.05 + 1e-12);
        prop_assert_eq!(ankle_counts(&drive, &enc, back).unwrap(), counts);
    }

    #[test]
    fn so3_log_inverts_exp(x in -1.0f64..1.0, y in -1.0f64..1.0, z in -1.0f64..1.0, angle in 0.0f64..(std::f64::consts::PI - 1e-4)) {
        let Some(axis) = Unit::try_new(Vector3::new(x, y, z), 1e-3) else { return Ok(()); };
        let phi = axis.into_inner() * angle;
        let r = Rotation3::from_scaled_axis(phi);
        let got = so3_log(r.matrix());
        prop_assert!((got - phi).norm() < 1e-9 * (1.0 + angle), "{got} vs {phi}");
    }
}

#[test]
fn so3_log_small_and_near_pi() {
    for angle in [
        0.0,
        1e-12,
        1e-7,
        1e-3,
        std::f64::consts::PI - 1e-6,
        std::f64::consts::PI - 1e-9,
    ] {
        let phi = Vector3::new(0.3, -0.5, 0.8).normalize() * angle;
        let got = so3_log(Rotation3::from_scaled_axis(phi).matrix());
        assert!((got - phi).norm() < 1e-8, "angle {angle}: {got} vs {phi}");
    }
}

#[test]
fn bad_encoder_resolution_is_an_error() {
    assert!(IncrementalEncoder::new(0.0).is_err());
    assert!(IncrementalEncoder::new(f64::NAN).is_err());
    let drive = KneeDrive::new(KneeDriveParams::default()).unwrap();
    assert!(knee_counts(&drive, &encoder(), f64::NAN).is_err());
    assert!(knee_angle_from_counts(&drive, &encoder(), i64::MAX / 2).is_err());
}
