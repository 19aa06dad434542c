//! Footstep planner: straight, sideways and turning placements, foot-rectangle overlap.

use biped_control::pattern::footsteps::feet_overlap;
use biped_control::pattern::{
    Foot, FootGeometry, FootstepPlan, PatternError, PatternParams, Pose2, LOLA_STEP_WIDTH,
};

fn plan(p: &PatternParams) -> FootstepPlan {
    FootstepPlan::new(p).unwrap()
}

#[test]
fn straight_walk_places_each_footprint_one_step_length_ahead() {
    let p = PatternParams::default();
    let steps = plan(&p).steps;
    assert_eq!(steps.len(), 10);
    for (i, s) in steps.iter().enumerate() {
        let k = (i + 1) as f64;
        let x = if i + 1 < p.n_steps {
            k * p.step_length
        } else {
            (k - 1.0) * p.step_length
        };
        let foot = if i % 2 == 0 { Foot::Left } else { Foot::Right };
        assert_eq!(s.foot, foot);
        assert!((s.to.x - x).abs() < 1e-12 && (s.to.y - foot.sign() * 0.09).abs() < 1e-12);
        assert_eq!(s.to.yaw, 0.0);
    }
    // First step is a half step: the foot travels one step length, later ones two.
    assert!((steps[0].to.x - steps[0].from.x - 0.4).abs() < 1e-12);
    assert!((steps[1].to.x - steps[1].from.x - 0.8).abs() < 1e-12);
    assert!(
        (steps[9].to.x - steps[9].from.x - 0.4).abs() < 1e-12,
        "closing half step"
    );
}

#[test]
fn sideways_walk_leading_foot_steps_out_trailing_foot_closes() {
    let (w, dy) = (LOLA_STEP_WIDTH, 0.1);
    for sign in [1.0, -1.0] {
        let p = PatternParams {
            step_length: 0.0,
            step_sideways: sign * dy,
            n_steps: 6,
            ..Default::default()
        };
        let pl = plan(&p);
        let lead = if sign > 0.0 { Foot::Left } else { Foot::Right };
        assert_eq!(pl.steps[0].foot, lead);
        for (i, s) in pl.steps.iter().enumerate() {
            let moved = s.to.y - s.from.y;
            let expect = if i == 5 && s.foot == lead {
                0.0
            } else {
                sign * dy
            };
            assert!((moved - expect).abs() < 1e-12, "step {i}: {moved}");
            assert!(s.to.x.abs() < 1e-12 && s.to.yaw == 0.0);
        }
        // Widths alternate between w + dy (after the leading step) and w.
        for k in 1..=6 {
            let f = pl.stance_after(k);
            let width = f[0].y - f[1].y;
            let expect = if k % 2 == 1 && k < 6 { w + dy } else { w };
            assert!((width - expect).abs() < 1e-12, "after step {k}: {width}");
        }
        let f = pl.stance_after(6);
        assert!(
            (0.5 * (f[0].y + f[1].y) - sign * 3.0 * dy).abs() < 1e-12,
            "3 side steps"
        );
    }
}

#[test]
fn turning_walk_rotates_each_footprint_and_ends_parallel() {
    for (len, turn) in [(0.0, 0.2), (0.2, 0.15), (0.1, -0.25)] {
        let p = PatternParams {
            step_length: len,
            turn_angle: turn,
            n_steps: 9,
            ..Default::default()
        };
        let pl = plan(&p);
        assert_eq!(
            pl.steps[0].foot,
            if turn > 0.0 { Foot::Left } else { Foot::Right }
        );
        for (i, s) in pl.steps.iter().enumerate().take(8) {
            assert!((s.to.yaw - (i + 1) as f64 * turn).abs() < 1e-12);
            // Relative to the stance foot: (length, +-width, turn) in the stance frame.
            let stance = pl.stance_after(i)[s.foot.other().index()];
            let rel = stance.to_local(&s.to.position());
            assert!((rel.x - len).abs() < 1e-12, "step {i}");
            assert!(
                (rel.y - s.foot.sign() * p.step_width).abs() < 1e-12,
                "step {i}"
            );
        }
        let f = pl.stance_after(9);
        assert!((f[0].yaw - 8.0 * turn).abs() < 1e-12 && f[0].yaw == f[1].yaw);
        // Turning on the spot (len = 0) keeps the feet midpoint near the start.
        if len == 0.0 {
            let mid = 0.5 * (f[0].position() + f[1].position());
            assert!(
                mid.norm() < p.step_width,
                "turn on the spot drifts {}",
                mid.norm()
            );
        }
    }
}

#[test]
fn overlap_test_on_foot_rectangles() {
    let foot = FootGeometry::default();
    let at = |x, y, yaw| Pose2 { x, y, yaw };
    assert!(!feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.0, 0.121, 0.0),
        &foot
    ));
    assert!(feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.0, 0.119, 0.0),
        &foot
    ));
    assert!(!feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.221, 0.0, 0.0),
        &foot
    ));
    assert!(feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.219, 0.0, 0.0),
        &foot
    ));
    // Rotated by 90 degrees: the heel (0.09 m) of the other foot points towards -y.
    assert!(feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.0, 0.14, std::f64::consts::FRAC_PI_2),
        &foot
    ));
    assert!(!feet_overlap(
        &at(0.0, 0.0, 0.0),
        &at(0.0, 0.16, std::f64::consts::FRAC_PI_2),
        &foot
    ));
    let narrow = PatternParams {
        step_width: 0.1,
        ..Default::default()
    };
    assert_eq!(
        FootstepPlan::new(&narrow),
        Err(PatternError::FeetOverlap { step: 0 })
    );
    let crossing = PatternParams {
        step_sideways: -0.1,
        step_length: 0.0,
        step_width: 0.15,
        ..Default::default()
    };
    assert!(
        FootstepPlan::new(&crossing).is_ok(),
        "trailing foot closes to the width"
    );
}
