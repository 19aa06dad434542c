//! Knee roller-screw drive (3.3)-(3.21): parts against finite differences, loop closure,
//! thesis formulas (3.5), (3.15), (3.17) as independent cross-checks, Newton-Raphson inverse.

mod mech_support;

use biped_dynamics::mechanism::knee::{KneeDrive, KneeDriveParams, KneePart};
use biped_dynamics::mechanism::{Coupling, MechanismError};
use mech_support::check_coupling;
use nalgebra::{Rotation3, Vector2, Vector3};
use proptest::prelude::*;

const PARTS: [KneePart; 3] = [KneePart::Housing, KneePart::Nut, KneePart::Rotor];

fn drive(tilt: bool) -> KneeDrive {
    KneeDrive::new(KneeDriveParams {
        screw_tilt: tilt,
        motor_offset: 0.3,
        ..Default::default()
    })
    .unwrap()
}

/// Pin `A` in the thigh frame, computed directly from the parameters.
fn pin_in_thigh(p: &KneeDriveParams, q: f64) -> Vector3<f64> {
    Rotation3::from_axis_angle(&Vector3::z_axis(), q)
        * Vector3::new(p.pin_shank.x, p.pin_shank.y, 0.0)
}

fn pivot(p: &KneeDriveParams) -> Vector3<f64> {
    Vector3::new(p.pivot_thigh.x, p.pivot_thigh.y, 0.0)
}

#[test]
fn default_transmission_is_lola_like() {
    let d = drive(true);
    assert!((d.screw_ratio() - 1256.637).abs() < 1e-3);
    let (lo, hi) = (
        d.transmission(d.params().q_min).unwrap(),
        d.transmission(d.params().q_max).unwrap(),
    );
    let stroke = hi.travel - lo.travel;
    assert!(stroke > 0.03 && stroke < 0.12, "stroke {stroke}");
}

#[test]
fn transmission_derivatives_match_finite_differences_and_thesis() {
    let d = drive(true);
    let p = *d.params();
    let h = 1e-5;
    for i in 0..=40 {
        let q = p.q_min + (p.q_max - p.q_min) * f64::from(i) / 40.0;
        let t = d.transmission(q).unwrap();
        let (tp, tm) = (
            d.transmission(q + h).unwrap(),
            d.transmission(q - h).unwrap(),
        );
        assert!((t.dtravel - (tp.travel - tm.travel) / (2.0 * h)).abs() < 1e-9);
        assert!((t.ddtravel - (tp.dtravel - tm.dtravel) / (2.0 * h)).abs() < 1e-8);
        // (3.4)-(3.5) written out: r = A - B, l = |r|, ldot = r.rdot / l with rdot = e_z x A.
        let a = pin_in_thigh(&p, q);
        let r = a - pivot(&p);
        assert!((t.travel - r.norm()).abs() < 1e-15);
        assert!((t.dtravel - r.dot(&Vector3::z().cross(&a)) / r.norm()).abs() < 1e-14);
        assert!((t.motor_angle - (d.screw_ratio() * t.travel + 0.3)).abs() < 1e-12);
        // (3.6) with the square restored: l_ddot = (rdot.rdot + r.rddot - l_dot^2) / l,
        // rddot = e_z x (e_z x A) = -A (A in the knee plane).
        let rdot = Vector3::z().cross(&a);
        let l2 = (rdot.dot(&rdot) - r.dot(&a) - t.dtravel.powi(2)) / r.norm();
        assert!((t.ddtravel - l2).abs() < 1e-13);
    }
}

#[test]
fn loop_closes_with_tilt_and_housing_axis_passes_through_pin() {
    let d = drive(true);
    let p = *d.params();
    for i in 0..=50 {
        let q = p.q_min + (p.q_max - p.q_min) * f64::from(i) / 50.0;
        let nut = d.part(KneePart::Nut).motion(&[q], &[0.0]).unwrap().pose;
        let a = pin_in_thigh(&p, q);
        assert!(
            (nut.translation.vector - a).norm() < 1e-12,
            "nut meets the shank pin"
        );
        let housing = d.part(KneePart::Housing).motion(&[q], &[0.0]).unwrap().pose;
        let axis = housing.rotation * Vector3::z();
        let from_pivot = a - housing.translation.vector;
        assert!(
            axis.cross(&from_pivot).norm() < 1e-12,
            "screw axis through A"
        );
        assert!(
            (housing.rotation * Vector3::y() - Vector3::z()).norm() < 1e-12,
            "y = knee axis"
        );
    }
}

#[test]
fn tilt_rate_matches_thesis_alpha() {
    // (3.15): alpha = atan(r_x / r_y) relative to the thigh y axis; its rate must equal the
    // housing's angular velocity about the knee axis (body y), and (3.17) alpha_dot.
    let d = drive(true);
    let p = *d.params();
    let alpha = |q: f64| {
        let r = pin_in_thigh(&p, q) - pivot(&p);
        (r.x / r.y).atan()
    };
    let h = 1e-6;
    for q in [0.0, 0.5, 1.0, 1.7] {
        let m = d.part(KneePart::Housing).motion(&[q], &[1.0]).unwrap();
        let fd = (alpha(q + h) - alpha(q - h)) / (2.0 * h);
        let r = pin_in_thigh(&p, q) - pivot(&p);
        let rdot = Vector3::z().cross(&pin_in_thigh(&p, q));
        let alpha_dot = r.cross(&rdot).z / r.norm_squared(); // (3.17)
                                                             // The body y axis is +t_z; alpha of (3.15) is measured about -t_z (atan(r_x / r_y)
                                                             // with r_y < 0), hence the sign.
        assert!(
            (m.jacobian[0][1] + fd).abs() < 1e-8,
            "{} vs {}",
            m.jacobian[0][1],
            fd
        );
        assert!((m.jacobian[0][1] - alpha_dot).abs() < 1e-12);
    }
}

#[test]
fn tilt_off_agrees_with_tilt_on_in_the_degenerate_limit() {
    let (on, off) = (drive(true), drive(false));
    let q_ref = on.params().q_ref;
    // At q_ref the screw axes coincide, so all poses agree.
    for part in PARTS {
        let a = on.part(part).motion(&[q_ref], &[1.0]).unwrap();
        let b = off.part(part).motion(&[q_ref], &[1.0]).unwrap();
        assert!((a.pose.translation.vector - b.pose.translation.vector).norm() < 1e-14);
        assert!(a.pose.rotation.angle_to(&b.pose.rotation) < 1e-12);
        // Spin about the screw axis (3.8)-(3.11) vs (3.19)-(3.21): identical.
        assert!((a.jacobian[0][2] - b.jacobian[0][2]).abs() < 1e-9);
    }
    // ||r_a|| / ||r_b|| -> 0 (thesis argument for neglecting the tilt): the pivot moves far
    // away along the screw axis, and the tilt terms vanish like the ratio.
    let mut errs = Vec::new();
    for scale in [1.0, 10.0, 100.0] {
        let base = KneeDriveParams::default();
        let far = KneeDriveParams {
            pivot_thigh: base.pivot_thigh * scale,
            ..base
        };
        let on = KneeDrive::new(KneeDriveParams {
            screw_tilt: true,
            ..far
        })
        .unwrap();
        let off = KneeDrive::new(KneeDriveParams {
            screw_tilt: false,
            ..far
        })
        .unwrap();
        let q = 1.2;
        let a = on.part(KneePart::Rotor).motion(&[q], &[1.0]).unwrap();
        let b = off.part(KneePart::Rotor).motion(&[q], &[1.0]).unwrap();
        let rel = (a.jacobian[0] - b.jacobian[0]).norm() / b.jacobian[0].norm();
        errs.push(rel);
    }
    assert!(
        errs[1] < errs[0] / 5.0 && errs[2] < errs[1] / 5.0,
        "{errs:?}"
    );
    assert!(errs[2] < 1e-4, "{errs:?}");
}

#[test]
fn newton_inverse_round_trips_and_reports_errors() {
    let d = drive(true);
    let p = *d.params();
    for i in 0..=200 {
        let q = p.q_min + (p.q_max - p.q_min) * f64::from(i) / 200.0;
        let phi = d.motor_angle(q).unwrap();
        let back = d.knee_angle(phi).unwrap();
        assert!((back - q).abs() < 1e-12, "q {q} back {back}");
    }
    let too_far = d.motor_angle(p.q_max).unwrap() + 10.0;
    assert!(matches!(
        d.knee_angle(too_far),
        Err(MechanismError::OutOfRange { .. })
    ));
    let too_low = d.motor_angle(p.q_min).unwrap() - 10.0;
    assert!(matches!(
        d.knee_angle(too_low),
        Err(MechanismError::OutOfRange { .. })
    ));
    assert!(matches!(
        d.knee_angle(f64::NAN),
        Err(MechanismError::BadInput { .. })
    ));
}

#[test]
fn invalid_parameters_and_inputs_are_errors() {
    let base = KneeDriveParams::default();
    for bad in [
        KneeDriveParams { lead: 0.0, ..base },
        KneeDriveParams {
            lead: f64::NAN,
            ..base
        },
        KneeDriveParams {
            q_min: 1.0,
            q_max: 0.5,
            ..base
        },
        KneeDriveParams { q_ref: 3.0, ..base },
        // Range through the dead point (A, O, B collinear): not monotone.
        KneeDriveParams { q_max: 3.0, ..base },
        KneeDriveParams {
            pin_shank: Vector2::zeros(),
            ..base
        },
    ] {
        assert!(KneeDrive::new(bad).is_err(), "{bad:?}");
    }
    let d = drive(true);
    let c = d.part(KneePart::Nut);
    assert!(c.motion(&[], &[]).is_err());
    assert!(c.motion(&[f64::INFINITY], &[0.0]).is_err());
    assert!(c.motion(&[0.1], &[f64::NAN]).is_err());
}

/// Regression: the fastest rotor spins of the proptest range (formerly a 6e-6 miss of the
/// plain central difference at q = 0.6024, qd = 3.34 with the screw tilt).
#[test]
fn fast_rotor_spin_matches_finite_differences() {
    for &(q, qd) in &[(0.6024, 3.34), (0.05, 4.0), (1.9, -4.0)] {
        for tilt in [false, true] {
            for part in PARTS {
                check_coupling(&drive(tilt).part(part), &[q], &[qd], 1e-6);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]
    #[test]
    fn parts_match_finite_differences(q in -0.05..2.0f64, qd in -4.0..4.0f64, tilt: bool, k in 0usize..3) {
        let d = drive(tilt);
        check_coupling(&d.part(PARTS[k]), &[q], &[qd], 1e-6);
    }

    #[test]
    fn newton_round_trip_random(q in -0.05..2.0f64) {
        let d = drive(false);
        let back = d.knee_angle(d.motor_angle(q).unwrap()).unwrap();
        prop_assert!((back - q).abs() < 1e-12);
    }

    #[test]
    fn newton_never_panics_and_ok_means_solved(motor in 300.0..460.0f64, tilt: bool) {
        let d = drive(tilt);
        match d.knee_angle(motor) {
            Ok(q) => {
                prop_assert!(q >= d.params().q_min && q <= d.params().q_max);
                prop_assert!((d.motor_angle(q).unwrap() - motor).abs() < 1e-9);
            }
            Err(e) => {
                let expected = matches!(e, MechanismError::OutOfRange { .. });
                prop_assert!(expected, "{:?}", e);
            }
        }
    }

    #[test]
    fn random_geometries_match_finite_differences(
        bx in -0.1..0.1f64, by in 0.2..0.4f64, ax in -0.08..-0.02f64, ay in -0.02..0.05f64,
        t in 0.0..1.0f64, qd in -3.0..3.0f64, tilt: bool, k in 0usize..3,
    ) {
        let p = KneeDriveParams {
            pivot_thigh: Vector2::new(bx, by),
            pin_shank: Vector2::new(ax, ay),
            screw_tilt: tilt,
            q_min: 0.0,
            q_max: 1.0,
            q_ref: 0.5,
            ..Default::default()
        };
        if let Ok(d) = KneeDrive::new(p) {
            check_coupling(&d.part(PARTS[k]), &[t], &[qd], 1e-6);
            let back = d.knee_angle(d.motor_angle(t).unwrap()).unwrap();
            prop_assert!((back - t).abs() < 1e-12);
        }
    }
}
