//! Toe-off and heel strike in the walking pattern: the heel lifts while the toe segment stands
//! still on the ground, the landing foot rolls flat about its heel edge, the toe joint angle
//! keeps the toe flat, and the toe axis of the pattern is the model's.

use biped_control::pattern::fit::toe_axis;
use biped_control::pattern::{
    Contact, FootGeometry, FootRoll, PatternError, PatternParams, PatternSample, WalkingPattern,
};
use biped_robots::lola::{build, LolaType};
use nalgebra::{Isometry3, Point3, Vector3};

fn pattern(p: &PatternParams) -> WalkingPattern {
    WalkingPattern::generate(p).unwrap()
}

/// World height of a point `(x, 0, z)` of a sole frame.
fn height(pose: &Isometry3<f64>, x: f64, z: f64) -> f64 {
    (pose * Point3::new(x, 0.0, z)).z
}

/// Both feet of every sample with their states.
fn feet(w: &WalkingPattern) -> impl Iterator<Item = (&PatternSample, usize)> {
    w.iter().flat_map(|s| [(s, 0), (s, 1)])
}

#[test]
fn toe_off_lifts_the_heel_while_the_toe_stands_on_the_ground() {
    let p = PatternParams::default();
    let (w, g) = (pattern(&p), p.foot);
    let mut toe_samples = 0;
    let mut max_heel: f64 = 0.0;
    for (s, i) in feet(&w) {
        let f = &s.feet[i];
        if f.contact != Contact::Toe {
            continue;
        }
        toe_samples += 1;
        let heel = height(&f.pose, -g.back, 0.0);
        max_heel = max_heel.max(heel);
        let (toe, lin, ang) = f.toe_frame(&g);
        // the toe segment lies flat on the ground, at rest, and the toe joint keeps it so
        assert!(
            (toe.translation.z - g.toe_height).abs() < 1e-12,
            "t {}",
            s.t
        );
        let (roll, tilt, _) = toe.rotation.euler_angles();
        assert!(roll.abs() < 1e-9 && tilt.abs() < 1e-9, "toe segment flat");
        assert!(
            lin.norm() < 1e-9 && ang.norm() < 1e-9,
            "t {}: {lin} {ang}",
            s.t
        );
        let pitch = f.pose.rotation.euler_angles().1;
        assert!((f.toe_angle + pitch).abs() < 1e-9);
        assert!(heel >= -1e-12 && pitch >= -1e-12);
    }
    assert!(toe_samples > 100, "{toe_samples} toe-off samples");
    // the heel is lifted by the full angle before lift-off: h = back-to-axis lever x sin
    let lever = g.front + g.back;
    let theta = w.roll().toe_off.iter().cloned().fold(0.0, f64::max);
    assert!(theta > 0.25, "largest heel lift {theta}");
    assert!(
        max_heel > 0.9 * lever * theta.sin(),
        "heel height {max_heel}"
    );
    // the first step lifts from beside the CoM: no toe-off
    assert_eq!(w.roll().toe_off[0], 0.0);
}

#[test]
fn heel_strike_lands_on_the_heel_edge_and_rolls_flat() {
    let p = PatternParams::default();
    let (w, g) = (pattern(&p), p.foot);
    let mut heel_samples = 0;
    for (s, i) in feet(&w) {
        let f = &s.feet[i];
        if f.contact != Contact::Heel {
            continue;
        }
        heel_samples += 1;
        let pitch = f.pose.rotation.euler_angles().1;
        assert!(pitch <= 1e-12, "toes up while on the heel");
        assert!(
            height(&f.pose, -g.back, 0.0).abs() < 1e-12,
            "heel edge on the ground"
        );
        assert!(height(&f.pose, g.front, 0.0) >= -1e-12);
        // the heel edge does not slide: v + w x r = 0 at the edge
        let edge = f.pose.rotation * Vector3::new(-g.back, 0.0, 0.0);
        assert!(
            (f.linear + f.angular.cross(&edge)).norm() < 1e-9,
            "t {}",
            s.t
        );
        assert_eq!(f.toe_angle, 0.0);
    }
    assert!(heel_samples > 100, "{heel_samples} heel-strike samples");
    let h = &w.roll().heel_strike;
    assert!(h[1] > 0.25, "{h:?}");
    // the closing step lands beside the stance foot, nearly under the CoM: hardly any roll
    assert!(h[h.len() - 1] < 0.1 * h[1], "{h:?}");
}

#[test]
fn rolled_foot_rests_flat_on_its_footstep() {
    let w = pattern(&PatternParams::default());
    let s = w.samples();
    let mut flat = 0;
    for step in &w.footsteps().steps {
        let i = step.foot.index();
        // first sample after the landing in which the foot is flat again
        let landing = s.iter().position(|x| {
            x.feet[i].contact == Contact::Heel
                && (x.feet[i].pose.translation.x - step.to.x).abs() < 0.2
                && (x.feet[i].pose.translation.y - step.to.y).abs() < 0.05
        });
        let Some(k) = landing else { continue };
        let k = k + s[k..]
            .iter()
            .position(|x| x.feet[i].contact == Contact::Flat)
            .unwrap();
        let f = &s[k].feet[i];
        let target = step.to.isometry(0.0);
        assert!((f.pose.translation.vector - target.translation.vector).norm() < 1e-12);
        assert!(f.pose.rotation.angle_to(&target.rotation) < 1e-12);
        assert!(f.linear.norm() == 0.0 && f.angular.norm() == 0.0);
        assert!(s[k - 1].feet[i].angular.norm() < 0.05, "roll ends at rest");
        flat += 1;
    }
    assert!(flat >= 8, "{flat} heel strikes ending flat");
}

#[test]
fn toe_rate_is_the_finite_difference_of_the_toe_angle() {
    let p = PatternParams::default();
    let w = pattern(&p);
    let s = w.samples();
    for k in 1..s.len() - 1 {
        for i in 0..2 {
            let d = (s[k + 1].feet[i].toe_angle - s[k - 1].feet[i].toe_angle) / (2.0 * p.dt);
            assert!((d - s[k].feet[i].toe_rate).abs() < 2e-2, "k {k} foot {i}");
        }
    }
}

#[test]
fn flat_roll_keeps_the_feet_flat() {
    let p = PatternParams {
        roll: FootRoll::flat(),
        ..PatternParams::default()
    };
    let w = pattern(&p);
    for (s, i) in feet(&w) {
        let f = &s.feet[i];
        assert!(matches!(f.contact, Contact::Flat | Contact::Swing));
        assert_eq!(f.toe_angle, 0.0);
        assert!(f.pose.rotation.euler_angles().1.abs() < 1e-12);
    }
}

#[test]
fn toe_axis_of_the_defaults_is_the_models() {
    let lola = build(LolaType::Type2).unwrap();
    let (x, z) = toe_axis(&lola).unwrap();
    let g = FootGeometry::default();
    assert!(
        (x - g.front).abs() < 1e-12 && (z - g.toe_height).abs() < 1e-12,
        "{x} {z}"
    );
}

#[test]
fn bad_roll_parameters_are_typed_errors() {
    let d = PatternParams::default();
    let cases = [
        (
            "roll.toe_off_angle",
            FootRoll {
                toe_off_angle: -0.1,
                ..d.roll
            },
        ),
        (
            "roll.heel_roll_fraction",
            FootRoll {
                heel_roll_fraction: 1.5,
                ..d.roll
            },
        ),
        (
            "roll.full_distance",
            FootRoll {
                full_distance: 0.0,
                ..d.roll
            },
        ),
        (
            "roll.swing_hold",
            FootRoll {
                swing_hold: f64::NAN,
                ..d.roll
            },
        ),
    ];
    for (field, roll) in cases {
        let p = PatternParams { roll, ..d.clone() };
        match WalkingPattern::generate(&p) {
            Err(PatternError::InvalidParameter { name, .. }) => assert_eq!(name, field),
            other => panic!("{field}: {:?}", other.map(|w| w.len())),
        }
    }
}
