//! Whole walking patterns: ZMP from the CoM, support polygon, rest at start and end,
//! feet and torso kinematics against finite differences.

use biped_control::pattern::footsteps::{foot_corners, Pose2};
use biped_control::pattern::{
    Foot, FootGeometry, FootRoll, PatternParams, PatternSample, Phase, WalkingPattern,
};
use nalgebra::{Vector2, Vector3};

fn walks() -> Vec<(&'static str, PatternParams)> {
    let d = PatternParams::default();
    vec![
        ("straight", d.clone()),
        (
            "sideways",
            PatternParams {
                step_length: 0.0,
                step_sideways: 0.1,
                n_steps: 8,
                ..d.clone()
            },
        ),
        (
            "turning",
            PatternParams {
                step_length: 0.2,
                turn_angle: 0.2,
                ..d.clone()
            },
        ),
        (
            "right-turn",
            PatternParams {
                step_length: 0.1,
                turn_angle: -0.25,
                n_steps: 7,
                ..d.clone()
            },
        ),
    ]
}

/// Signed distance of `p` inside the convex hull of `pts` (negative outside): the minimum over
/// hull edges (pairs with every point on one side) of the distance to the edge line.
fn hull_margin(pts: &[Vector2<f64>], p: &Vector2<f64>) -> f64 {
    let mut margin = f64::INFINITY;
    for i in 0..pts.len() {
        for j in 0..pts.len() {
            let e = pts[j] - pts[i];
            if e.norm() < 1e-12 {
                continue;
            }
            let n = Vector2::new(e.y, -e.x).normalize();
            if pts.iter().all(|q| n.dot(&(q - pts[i])) <= 1e-12) {
                margin = margin.min(-n.dot(&(p - pts[i])));
            }
        }
    }
    margin
}

/// Corners of both foot rectangles of a sample.
fn support_corners(s: &PatternSample, foot: &FootGeometry) -> Vec<Vector2<f64>> {
    let mut pts = Vec::new();
    for f in [Foot::Left, Foot::Right] {
        let t = s.foot(f).pose.translation;
        let sole = Pose2 {
            x: t.x,
            y: t.y,
            yaw: yaw_of(s, f),
        };
        pts.extend(foot_corners(&sole, foot).iter().map(|c| c.coords));
    }
    pts
}

fn yaw_of(s: &PatternSample, foot: Foot) -> f64 {
    s.foot(foot).pose.rotation.euler_angles().2
}

#[test]
fn zmp_from_com_finite_differences_tracks_reference_inside_the_support_polygon() {
    for (name, p) in walks() {
        let w = WalkingPattern::generate(&p).unwrap();
        let s = w.samples();
        let (h, g, dt) = (p.com_height, p.gravity, p.dt);
        let mut max_ref_err: f64 = 0.0;
        let mut min_margin = f64::INFINITY;
        for k in 1..s.len() - 1 {
            let acc = (s[k + 1].com - 2.0 * s[k].com + s[k - 1].com) / (dt * dt);
            let zmp = s[k].com.xy() - h / g * acc.xy();
            // Finite-difference ZMP equals the reported one up to O(dt * jerk change) < 1 mm.
            assert!((zmp - s[k].zmp).norm() < 1e-3, "{name} k {k}");
            max_ref_err = max_ref_err.max((zmp - s[k].zmp_ref).norm());
            if let Some(foot) = s[k].phase.stance_foot() {
                let pose = s[k].foot(foot).pose;
                let sole = Pose2 {
                    x: pose.translation.x,
                    y: pose.translation.y,
                    yaw: yaw_of(&s[k], foot),
                };
                let local = sole.to_local(&zmp);
                let m = [
                    p.foot.front - local.x,
                    local.x + p.foot.back,
                    p.foot.half_width - local.y.abs(),
                ];
                min_margin = min_margin.min(m.iter().cloned().fold(f64::INFINITY, f64::min));
            } else {
                let hull = hull_margin(&support_corners(&s[k], &p.foot), &zmp);
                assert!(
                    hull > 0.0,
                    "{name} k {k}: ZMP outside the double-support polygon"
                );
            }
        }
        assert!(
            max_ref_err < 0.025,
            "{name}: max |p - p_ref| = {max_ref_err}"
        );
        assert!(
            min_margin > 0.02,
            "{name}: ZMP margin in single support {min_margin}"
        );
    }
}

#[test]
fn com_at_rest_at_start_and_end_with_constant_height() {
    for (name, p) in walks() {
        let w = WalkingPattern::generate(&p).unwrap();
        let (first, last) = (w.sample(0).unwrap(), w.samples().last().unwrap());
        assert_eq!(first.com_vel.norm(), 0.0);
        assert!(
            last.com_vel.norm() < 2e-3,
            "{name}: end velocity {}",
            last.com_vel.norm()
        );
        assert!(last.com_acc.norm() < 1e-2, "{name}");
        let feet_mid =
            0.5 * (last.feet[0].pose.translation.vector + last.feet[1].pose.translation.vector);
        assert!(
            (last.com.xy() - feet_mid.xy()).norm() < 2e-3,
            "{name}: CoM over the feet"
        );
        assert!(w
            .iter()
            .all(|s| s.com.z == p.com_height && s.com_vel.z == 0.0));
        assert!(w.sample(w.len()).is_none());
        // CoM velocity and acceleration are the derivatives of position and velocity.
        let s = w.samples();
        for k in 1..s.len() - 1 {
            let v = (s[k + 1].com - s[k - 1].com) / (2.0 * p.dt);
            let a = (s[k + 1].com_vel - s[k - 1].com_vel) / (2.0 * p.dt);
            assert!((v - s[k].com_vel).norm() < 1e-4, "{name} k {k}");
            assert!((a - s[k].com_acc).norm() < 5e-3, "{name} k {k}");
        }
    }
}

#[test]
fn feet_and_torso_velocities_are_finite_differences() {
    for (name, p) in walks() {
        let w = WalkingPattern::generate(&p).unwrap();
        let s = w.samples();
        for k in 1..s.len() - 1 {
            for foot in [Foot::Left, Foot::Right] {
                let (a, b, c) = (s[k - 1].foot(foot), s[k].foot(foot), s[k + 1].foot(foot));
                let v = (c.pose.translation.vector - a.pose.translation.vector) / (2.0 * p.dt);
                assert!(
                    (v - b.linear).norm() < 2e-3,
                    "{name} k {k} {foot:?}: {v} vs {}",
                    b.linear
                );
                let dq = a.pose.rotation.rotation_to(&c.pose.rotation).scaled_axis() / (2.0 * p.dt);
                // heel lift and roll pitch the feet with jerks up to ~3e4 rad/s^3: the
                // central difference is off by dt^2/6 * that ~ 4e-3 rad/s
                assert!((dq - b.angular).norm() < 5e-3, "{name} k {k}");
            }
            let dq = s[k - 1].torso.rotation_to(&s[k + 1].torso).scaled_axis() / (2.0 * p.dt);
            assert!((dq - s[k].torso_angular).norm() < 2e-3, "{name} k {k}");
            let mean = 0.5 * (yaw_of(&s[k], Foot::Left) + yaw_of(&s[k], Foot::Right));
            let (roll, pitch, yaw) = s[k].torso.euler_angles();
            assert!(roll == 0.0 && pitch == 0.0);
            assert!(
                (yaw - mean).abs() < 1e-12 || (yaw - mean).abs() > 6.0,
                "{name} k {k}"
            );
        }
    }
}

#[test]
fn swing_foot_lands_exactly_on_the_planned_footstep_at_rest() {
    // flat feet: with heel strike the foot touches down on its heel and is flat on the
    // footstep at the end of the roll, and toe-off raises the sole origin above the lift
    // profile (both checked in pattern_roll.rs)
    for (name, p) in walks() {
        let p = PatternParams {
            roll: FootRoll::flat(),
            ..p
        };
        let w = WalkingPattern::generate(&p).unwrap();
        let s = w.samples();
        let plan = w.footsteps();
        let mut touchdowns = 0;
        let mut peak: f64 = 0.0;
        for k in 1..s.len() {
            peak = peak.max(
                s[k].feet[0]
                    .pose
                    .translation
                    .z
                    .max(s[k].feet[1].pose.translation.z),
            );
            let (prev, now) = (s[k - 1].phase, s[k].phase);
            if prev != Phase::Double && now == Phase::Double {
                let step = &plan.steps[touchdowns];
                let f = s[k].foot(step.foot);
                let target = step.to.isometry(0.0);
                assert!(
                    (f.pose.translation.vector - target.translation.vector).norm() == 0.0,
                    "{name}"
                );
                assert!(f.pose.rotation.angle_to(&target.rotation) < 1e-12, "{name}");
                assert!(f.linear.norm() == 0.0 && f.angular.norm() == 0.0);
                // Approaching touch-down the velocity goes to zero (O(dt^2)).
                assert!(s[k - 1].foot(step.foot).linear.norm() < 1e-3, "{name}");
                touchdowns += 1;
            }
            // The stance foot never moves.
            if let Some(foot) = now.stance_foot() {
                assert_eq!(s[k].foot(foot).linear.norm(), 0.0);
                assert_eq!(s[k].foot(foot).pose, s[k - 1].foot(foot).pose);
            }
        }
        assert_eq!(touchdowns, p.n_steps, "{name}");
        assert!((peak - p.step_height).abs() < 1e-5, "{name}: peak {peak}");
    }
}

#[test]
fn phases_alternate_and_last_stance_is_side_by_side() {
    let p = PatternParams::default();
    let w = WalkingPattern::generate(&p).unwrap();
    let mut singles = Vec::new();
    for s in w.iter() {
        if s.phase != Phase::Double && singles.last() != Some(&s.phase) {
            singles.push(s.phase);
        }
    }
    assert_eq!(singles.len(), p.n_steps);
    assert!(singles.windows(2).all(|w| w[0] != w[1]));
    assert_eq!(singles[0], Phase::RightStance, "left foot swings first");
    let t = w.samples().last().unwrap().t;
    assert!((t - p.duration()).abs() < 1e-9);
    let last = w.samples().last().unwrap();
    let d: Vector3<f64> =
        last.feet[0].pose.translation.vector - last.feet[1].pose.translation.vector;
    assert!((d - Vector3::new(0.0, p.step_width, 0.0)).norm() < 1e-12);
    let zmp_end: Vector2<f64> = last.zmp_ref;
    assert!((zmp_end - Vector2::new((p.n_steps - 1) as f64 * p.step_length, 0.0)).norm() < 1e-12);
}

#[test]
fn hull_margin_of_a_square_with_an_inner_point() {
    let sq: Vec<Vector2<f64>> = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.5, 0.5)]
        .iter()
        .map(|&(x, y)| Vector2::new(x, y))
        .collect();
    assert!((hull_margin(&sq, &Vector2::new(0.5, 0.25)) - 0.25).abs() < 1e-12);
    assert!((hull_margin(&sq, &Vector2::new(1.5, 0.5)) + 0.5).abs() < 1e-12);
}
