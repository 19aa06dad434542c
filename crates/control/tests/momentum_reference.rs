//! Reference trajectory (7.10)-(7.12) and reference arm swing (7.3.1): boundary values,
//! C^1 continuity across steps, rates against central differences, linearity of the arm map.

use biped_control::momentum::{
    ArmSwing, ArmSwingNominal, MomentumError, MomentumReference, PointTarget,
};
use nalgebra::Vector3;
use proptest::prelude::*;

/// Central difference of the reference value.
fn rate_fd(r: &MomentumReference, t: f64) -> f64 {
    let h = 1e-6;
    (r.sample(t + h).0 - r.sample(t - h).0) / (2.0 * h)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, failure_persistence: None, ..ProptestConfig::default() })]

    /// Each step ends at `I_zz dphi / T` with zero rate (7.11)-(7.12), starts from the previous
    /// reference (value and rate continuous), and its rate is the derivative of its value.
    #[test]
    fn cubic_boundary_values_and_continuity(
        izz in 0.5f64..20.0,
        steps in prop::collection::vec((0.3f64..1.5, -0.5f64..0.5, 0.1f64..1.0), 1..5),
    ) {
        let mut r = MomentumReference::new(izz).unwrap();
        let mut t = 0.0;
        for (t_step, dphi, cut) in steps {
            // Replan part-way through the previous step: initial values come from it.
            let t_b = t + cut * 0.2;
            let before = r.sample(t_b);
            r.start_step(t_b, t_step, dphi).unwrap();
            let start = r.sample(t_b);
            prop_assert!((start.0 - before.0).abs() < 1e-12 && (start.1 - before.1).abs() < 1e-9);
            let t_e = t_b + t_step;
            let end = r.sample(t_e);
            prop_assert!((end.0 - izz * dphi / t_step).abs() < 1e-9 * izz.max(1.0));
            prop_assert!(end.1.abs() < 1e-9 * izz.max(1.0));
            for k in 1..10 {
                let tk = t_b + t_step * k as f64 / 10.0;
                prop_assert!((r.sample(tk).1 - rate_fd(&r, tk)).abs() < 1e-5 * izz.max(1.0));
            }
            t = t_e;
        }
        // Straight walking drives the reference to zero and holds it.
        r.start_step(t, 0.8, 0.0).unwrap();
        prop_assert!(r.sample(t + 0.8).0.abs() < 1e-12 && r.sample(t + 5.0) == (r.sample(t + 0.8).0, 0.0));
    }
}

#[test]
fn general_boundary_form_and_hold_outside() {
    let mut r = MomentumReference::new(2.0).unwrap();
    assert_eq!(r.sample(-1.0), (0.0, 0.0));
    r.start_step_to(1.0, 2.0, 3.0, 0.5).unwrap();
    let (l, d) = r.sample(3.0);
    assert!((l - 3.0).abs() < 1e-12 && (d - 0.5).abs() < 1e-12);
    assert_eq!(r.sample(10.0), (r.sample(3.0).0, 0.0));
    assert_eq!(r.sample(0.0), (0.0, 0.0));
    assert_eq!(r.izz(), 2.0);
}

#[test]
fn reference_errors() {
    assert!(matches!(
        MomentumReference::new(0.0),
        Err(MomentumError::InvalidParameter { .. })
    ));
    let mut r = MomentumReference::new(1.0).unwrap();
    assert!(r.start_step(0.0, 0.0, 0.1).is_err());
    assert!(r.start_step(0.0, 1.0, f64::NAN).is_err());
    assert!(r.start_step_to(f64::INFINITY, 1.0, 0.0, 0.0).is_err());
    assert_eq!(r.sample(f64::NAN), (0.0, 0.0));
}

fn nominal() -> ArmSwingNominal {
    ArmSwingNominal {
        left_arm: Vector3::new(0.0, 0.25, 0.35),
        right_arm: Vector3::new(0.0, -0.25, 0.35),
        left_leg: Vector3::new(0.0, 0.1, -0.9),
        right_leg: Vector3::new(0.0, -0.1, -0.9),
    }
}

fn point(p: Vector3<f64>, v: Vector3<f64>) -> PointTarget {
    PointTarget {
        position: p,
        velocity: v,
    }
}

#[test]
fn arm_swing_follows_the_opposite_leg_scaled() {
    let n = nominal();
    let swing = ArmSwing::new(0.4, n).unwrap();
    let still = swing
        .targets(
            &point(n.left_leg, Vector3::zeros()),
            &point(n.right_leg, Vector3::zeros()),
        )
        .unwrap();
    assert_eq!(still.left.position, n.left_arm);
    assert_eq!(still.right.position, n.right_arm);
    // Left foot 0.2 m forward and lifted 0.1 m: the right arm swings 0.08 m forward, not up.
    let step = Vector3::new(0.2, 0.0, 0.1);
    let t = swing
        .targets(
            &point(n.left_leg + step, step),
            &point(n.right_leg, Vector3::zeros()),
        )
        .unwrap();
    assert!((t.right.position - n.right_arm - Vector3::new(0.08, 0.0, 0.0)).norm() < 1e-15);
    assert_eq!(t.left.position, n.left_arm);
    assert!((t.right.velocity - Vector3::new(0.08, 0.0, 0.0)).norm() < 1e-15);
}

#[test]
fn arm_swing_velocity_is_the_derivative_of_its_position() {
    let n = nominal();
    let swing = ArmSwing::with_mask(0.35, Vector3::new(1.0, 1.0, 1.0), n).unwrap();
    // Feet on a smooth path relative to the CoG.
    let foot = |t: f64, side: f64| {
        let p = Vector3::new(
            0.2 * (3.0 * t).sin(),
            side * (0.1 + 0.02 * t),
            -0.9 + 0.05 * t * t,
        );
        let v = Vector3::new(0.6 * (3.0 * t).cos(), side * 0.02, 0.1 * t);
        point(p, v)
    };
    let at = |t: f64| swing.targets(&foot(t, 1.0), &foot(-t, -1.0)).unwrap();
    let (t, h) = (0.3, 1e-6);
    let fd = (at(t + h).right.position - at(t - h).right.position) / (2.0 * h);
    assert!((fd - at(t).right.velocity).norm() < 1e-8);
}

#[test]
fn arm_swing_errors() {
    let mut n = nominal();
    assert!(ArmSwing::new(f64::NAN, n).is_err());
    assert!(ArmSwing::with_mask(0.4, Vector3::new(f64::INFINITY, 0.0, 0.0), n).is_err());
    let swing = ArmSwing::new(0.4, n).unwrap();
    let bad = point(Vector3::new(f64::NAN, 0.0, 0.0), Vector3::zeros());
    let good = point(Vector3::zeros(), Vector3::zeros());
    assert!(matches!(
        swing.targets(&bad, &good),
        Err(MomentumError::NonFinite { .. })
    ));
    n.left_arm.x = f64::NAN;
    assert!(ArmSwing::new(0.4, n).is_err());
}
