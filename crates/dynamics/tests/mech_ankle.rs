//! Ankle drive (3.22)-(3.37): two spatial slider-cranks. Parts and transmission against finite
//! differences, the thesis's projection vector (3.34) as an independent formula, loop closure,
//! the assembly branch, and the 2x2 Newton-Raphson inverse.

mod mech_support;

use biped_dynamics::mechanism::ankle::{AnkleDrive, AnkleDriveParams, AnklePart};
use biped_dynamics::mechanism::{Coupling, MechanismError};
use mech_support::check_coupling;
use nalgebra::{Matrix3, Rotation3, Vector2, Vector3};
use proptest::prelude::*;

const PARTS: [AnklePart; 3] = [AnklePart::Nut, AnklePart::Rotor, AnklePart::Rod];

fn drive() -> AnkleDrive {
    let mut p = AnkleDriveParams::default();
    p.actuators[0].motor_offset = 0.7;
    p.actuators[1].motor_offset = -1.3;
    // A slightly inclined screw for generality (normalized by validation).
    p.actuators[1].screw_axis = Vector3::new(0.05, -0.02, -1.0);
    AnkleDrive::new(p).unwrap()
}

/// Foot ball centre in the shank frame, written out independently: C + A_y(q1) A_x(q2) f.
fn foot_ball(p: &AnkleDriveParams, i: usize, q: [f64; 2]) -> Vector3<f64> {
    let r = Rotation3::from_axis_angle(&Vector3::y_axis(), q[0])
        * Rotation3::from_axis_angle(&Vector3::x_axis(), q[1]);
    p.ankle_center + r * p.actuators[i].foot_ball
}

fn grid(p: &AnkleDriveParams, n: usize) -> Vec<[f64; 2]> {
    let t = |j: usize, s: usize| p.q_min[j] + (p.q_max[j] - p.q_min[j]) * s as f64 / n as f64;
    (0..=n)
        .flat_map(|i| (0..=n).map(move |k| [t(0, i), t(1, k)]))
        .collect()
}

#[test]
fn jacobian_matches_thesis_projection_vector_and_finite_differences() {
    let d = drive();
    let p = *d.params();
    let h = 1e-6;
    for q in grid(&p, 8) {
        let tr = d.transmission(q, [0.0; 2]).unwrap();
        for i in 0..2 {
            let a = &p.actuators[i];
            let (e, r) = (a.screw_axis, foot_ball(&p, i, q) - a.screw_top);
            let pm = e * e.transpose() - Matrix3::identity(); // (3.28c)
            let dd = (a.rod_length.powi(2) + r.dot(&(pm * r))).sqrt(); // (3.29)
            assert!((tr.travel[i] - (e.dot(&r) - dd)).abs() < 1e-14);
            let pv = e - pm * r / dd; // (3.34)
            for j in 0..2 {
                let mut qp = q;
                let mut qm = q;
                qp[j] += h;
                qm[j] -= h;
                let rdot = (foot_ball(&p, i, qp) - foot_ball(&p, i, qm)) / (2.0 * h);
                assert!((tr.jacobian[(i, j)] - pv.dot(&rdot)).abs() < 1e-9, "(3.32)"); // (3.30)
                let fd = (d.transmission(qp, [0.0; 2]).unwrap().travel[i]
                    - d.transmission(qm, [0.0; 2]).unwrap().travel[i])
                    / (2.0 * h);
                assert!((tr.jacobian[(i, j)] - fd).abs() < 1e-9);
            }
        }
        let n = d.screw_ratio();
        assert!((tr.motor_angles[0] - (n * tr.travel[0] + 0.7)).abs() < 1e-12);
        assert!((tr.motor_angles[1] - (n * tr.travel[1] - 1.3)).abs() < 1e-12);
    }
}

#[test]
fn assembly_branch_puts_the_nut_above_the_foot() {
    let d = drive();
    let p = *d.params();
    for q in grid(&p, 6) {
        for i in 0..2 {
            let c = d.part(i, AnklePart::Rod).unwrap();
            let (foot, nut) = c.ball_centres(q).unwrap();
            let e = p.actuators[i].screw_axis;
            // The nut lies before the foot ball along the screw axis (minus root of (3.25)),
            // and the other root (plus sign) would be beyond it.
            assert!(e.dot(&(foot - nut)) > 0.0);
            assert!(nut.z > foot.z);
            let travel = d.transmission(q, [0.0; 2]).unwrap().travel[i];
            assert!(travel > 0.0 && travel < 0.3);
        }
    }
}

#[test]
fn loop_closure_rod_length_is_constant() {
    let d = drive();
    let p = *d.params();
    for q in grid(&p, 12) {
        for i in 0..2 {
            let c = d.part(i, AnklePart::Rod).unwrap();
            let (foot, nut) = c.ball_centres(q).unwrap();
            assert!((foot - foot_ball(&p, i, q)).norm() < 1e-15);
            assert!(((foot - nut).norm() - p.actuators[i].rod_length).abs() < 1e-12);
            // The rod frame: origin at the nut ball, z towards the foot ball.
            let rod = c.motion(&q, &[0.0; 2]).unwrap().pose;
            let tip = rod * nalgebra::Point3::new(0.0, 0.0, p.actuators[i].rod_length);
            assert!((tip.coords - foot).norm() < 1e-12);
            let nut_pose = d
                .part(i, AnklePart::Nut)
                .unwrap()
                .motion(&q, &[0.0; 2])
                .unwrap()
                .pose;
            assert!((nut_pose.translation.vector - nut).norm() < 1e-15);
            // Roll convention: rod x axis is perpendicular to the shank y axis.
            assert!((rod.rotation * Vector3::x()).y.abs() < 1e-12);
        }
    }
}

#[test]
fn newton_inverse_round_trips() {
    let d = drive();
    let p = *d.params();
    let mut worst = 0.0f64;
    for q in grid(&p, 20) {
        let phi = d.transmission(q, [0.0; 2]).unwrap().motor_angles;
        let back = d.ankle_angles([phi.x, phi.y], None).unwrap();
        worst = worst
            .max((back[0] - q[0]).abs())
            .max((back[1] - q[1]).abs());
        let guessed = d.ankle_angles([phi.x, phi.y], Some([0.1, -0.1])).unwrap();
        assert!((guessed[0] - q[0]).abs() < 1e-12 && (guessed[1] - q[1]).abs() < 1e-12);
    }
    assert!(worst < 1e-12, "worst round-trip error {worst:e}");
}

#[test]
fn out_of_range_and_bad_inputs_are_errors_not_panics() {
    let d = drive();
    let phi = d.transmission([0.0, 0.0], [0.0; 2]).unwrap().motor_angles;
    for motor in [
        [phi.x + 500.0, phi.y],
        [phi.x - 400.0, phi.y + 400.0],
        [1e9, -1e9],
    ] {
        let r = d.ankle_angles(motor, None);
        assert!(
            matches!(
                r,
                Err(MechanismError::OutOfRange { .. } | MechanismError::NoConvergence { .. })
            ),
            "{motor:?}: {r:?}"
        );
    }
    assert!(matches!(
        d.ankle_angles([f64::NAN, 0.0], None),
        Err(MechanismError::BadInput { .. })
    ));
    assert!(d.part(2, AnklePart::Nut).is_err());
    let c = d.part(0, AnklePart::Rod).unwrap();
    assert!(matches!(
        c.motion(&[0.0], &[0.0]),
        Err(MechanismError::BadInput { .. })
    ));
    // A short rod: assembled near q = 0 but no real root of (3.25) at large flexion.
    let mut p = AnkleDriveParams::default();
    for a in &mut p.actuators {
        a.rod_length = 0.03;
    }
    p.q_min = [-0.1, -0.1];
    p.q_max = [0.1, 0.1];
    let short = AnkleDrive::new(p).unwrap();
    let r = short.transmission([1.0, 0.0], [0.0; 2]);
    assert!(matches!(r, Err(MechanismError::OutOfRange { .. })), "{r:?}");
    let r = short
        .part(0, AnklePart::Rotor)
        .unwrap()
        .motion(&[1.0, 0.0], &[0.0; 2]);
    assert!(matches!(r, Err(MechanismError::OutOfRange { .. })));
    // Invalid parameters.
    let base = AnkleDriveParams::default();
    let mut bad = [base; 5];
    bad[0].lead = -1.0;
    bad[1].actuators[0].rod_length = 0.0;
    bad[2].actuators[1].screw_axis = Vector3::y();
    bad[3].q_min = [1.0, 0.0];
    bad[4].ankle_center.x = f64::NAN;
    for b in bad {
        assert!(AnkleDrive::new(b).is_err());
    }
}

#[test]
fn bias_matches_thesis_formulas_3_31_and_3_35() {
    // l_ddot(qdd = 0) = p . r_ddot + p_dot . r_dot, p_dot = (r_dot' P r) P r / d^3 - P r_dot / d.
    let d = drive();
    let p = *d.params();
    let qd = [0.8, -1.3];
    let h = 1e-5;
    for q in grid(&p, 6) {
        let tr = d.transmission(q, qd).unwrap();
        for i in 0..2 {
            let a = &p.actuators[i];
            let e = a.screw_axis;
            let r_at =
                |t: f64| foot_ball(&p, i, [q[0] + qd[0] * t, q[1] + qd[1] * t]) - a.screw_top;
            let r = r_at(0.0);
            let rdot = (r_at(h) - r_at(-h)) / (2.0 * h);
            let rddot = (r_at(h) - 2.0 * r + r_at(-h)) / (h * h);
            let pm = e * e.transpose() - Matrix3::identity();
            let dd = (a.rod_length.powi(2) + r.dot(&(pm * r))).sqrt();
            let pv = e - pm * r / dd;
            let pdot = (rdot.dot(&(pm * r))) * (pm * r) / dd.powi(3) - pm * rdot / dd;
            let expected = pv.dot(&rddot) + pdot.dot(&rdot);
            assert!(
                (tr.jdot_qd[i] - expected).abs() < 1e-5 * (1.0 + expected.abs()),
                "{} vs {expected}",
                tr.jdot_qd[i]
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]
    #[test]
    fn parts_match_finite_differences(
        q0 in -0.5..0.4f64, q1 in -0.25..0.25f64,
        qd0 in -3.0..3.0f64, qd1 in -3.0..3.0f64, i in 0usize..2, k in 0usize..3,
    ) {
        let c = drive().part(i, PARTS[k]).unwrap();
        check_coupling(&c, &[q0, q1], &[qd0, qd1], 1e-6);
    }

    #[test]
    fn transmission_bias_matches_finite_differences(
        q0 in -0.5..0.4f64, q1 in -0.25..0.25f64, qd0 in -3.0..3.0f64, qd1 in -3.0..3.0f64,
    ) {
        let d = drive();
        let qd = Vector2::new(qd0, qd1);
        let tr = d.transmission([q0, q1], [qd0, qd1]).unwrap();
        let h = 1e-6;
        let jq = |t: f64| d.transmission([q0 + qd0 * t, q1 + qd1 * t], [0.0; 2]).unwrap().jacobian * qd;
        let fd = (jq(h) - jq(-h)) / (2.0 * h);
        prop_assert!((tr.jdot_qd - fd).amax() < 1e-7 * (1.0 + fd.amax()), "{:?} vs {:?}", tr.jdot_qd, fd);
    }

    #[test]
    fn newton_round_trip_random(q0 in -0.5..0.4f64, q1 in -0.25..0.25f64) {
        let d = drive();
        let phi = d.transmission([q0, q1], [0.0; 2]).unwrap().motor_angles;
        let back = d.ankle_angles([phi.x, phi.y], None).unwrap();
        prop_assert!((back[0] - q0).abs() < 1e-12 && (back[1] - q1).abs() < 1e-12);
    }

    #[test]
    fn newton_never_panics_and_ok_means_solved(m0 in 80.0..220.0f64, m1 in 80.0..220.0f64) {
        let d = drive();
        match d.ankle_angles([m0, m1], None) {
            Ok(q) => {
                let p = d.params();
                prop_assert!((0..2).all(|j| q[j] >= p.q_min[j] - 1e-9 && q[j] <= p.q_max[j] + 1e-9));
                let phi = d.transmission(q, [0.0; 2]).unwrap().motor_angles;
                prop_assert!((phi.x - m0).abs() < 1e-8 && (phi.y - m1).abs() < 1e-8);
            }
            Err(e) => {
                let expected = matches!(
                    e,
                    MechanismError::OutOfRange { .. } | MechanismError::NoConvergence { .. }
                );
                prop_assert!(expected, "{:?}", e);
            }
        }
    }

    #[test]
    fn random_geometries_match_finite_differences(
        dx in -0.03..0.03f64, dy in -0.01..0.01f64, ex in -0.2..0.2f64, ey in -0.2..0.2f64,
        fz in -0.02..0.05f64, rod in 0.15..0.25f64,
        q0 in -0.3..0.3f64, q1 in -0.2..0.2f64, qd0 in -3.0..3.0f64, qd1 in -3.0..3.0f64,
        k in 0usize..3,
    ) {
        let mut p = AnkleDriveParams::default();
        p.actuators[0].screw_top += Vector3::new(dx, dy, 0.0);
        p.actuators[0].screw_axis = Vector3::new(ex, ey, -1.0);
        p.actuators[1].foot_ball.z = fz;
        p.actuators[1].rod_length = rod;
        p.q_min = [-0.3, -0.2];
        p.q_max = [0.3, 0.2];
        if let Ok(d) = AnkleDrive::new(p) {
            for i in 0..2 {
                check_coupling(&d.part(i, PARTS[k]).unwrap(), &[q0, q1], &[qd0, qd1], 1e-6);
            }
            let phi = d.transmission([q0, q1], [0.0; 2]).unwrap().motor_angles;
            let back = d.ankle_angles([phi.x, phi.y], None).unwrap();
            prop_assert!((back[0] - q0).abs() < 1e-12 && (back[1] - q1).abs() < 1e-12);
        }
    }
}
