//! The dynamic walk of a described robot (the bundled G1): its parts come from the description
//! (ankle axes as the URDF gives them, the sole's contact law, the plant's end stops at the
//! URDF ranges), and it walks 10 steps of its natural step length with every arm method without
//! falling, hopping, slipping, pushing a joint beyond its range or letting segments
//! interpenetrate.

use biped_control::walk::dynamic::{robot_plant, SOLE_ROLL_MARGIN};
use biped_control::walk::{
    run_dynamic_walk_robot, DynamicRobot, DynamicWalkParams, Method, WalkRobot,
};
use biped_robots::description::Robot;

fn g1() -> DynamicRobot {
    let loaded = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
    let walk = WalkRobot::from_description(&loaded).unwrap();
    DynamicRobot::from_description(&loaded, walk).unwrap()
}

/// The URDF's ankle axes (`<axis xyz="0 1 0"/>` pitch, `"1 0 0"` roll on both legs) and the
/// contact law's roll stiffness of a sole, `k * sum y_i^2` over its 8 points (6 of them on
/// the long edges at `+-w/2`), against the robot's `m g h`.
#[test]
fn g1_parts_follow_from_its_description() {
    let r = g1();
    for (leg, side) in r.legs.iter().zip(["left", "right"]) {
        let pitch = (format!("{side}_ankle_pitch_joint"), 1.0);
        let roll = (format!("{side}_ankle_roll_joint"), 1.0);
        assert_eq!(leg.ankle, [pitch, roll]);
        assert_eq!(leg.joints[0], format!("{side}_hip_pitch_joint"));
    }
    let half_width = 0.5 * 0.055;
    let roll = 6.0 * r.contact.stiffness * half_width * half_width;
    let topple = r.mass * 9.81 * r.walk.com_height;
    assert!(
        (roll / topple - SOLE_ROLL_MARGIN).abs() < 0.01 * SOLE_ROLL_MARGIN,
        "{roll} vs {topple}"
    );
    assert!((r.mass - 33.3).abs() < 0.1, "{}", r.mass);
    let p = DynamicWalkParams::for_robot(&r).unwrap();
    assert!(p.end_stops);
    let plant = robot_plant(&r, &p).unwrap();
    assert_eq!(plant.actuators().len(), 29);
    assert!(
        plant.model().nbodies() > r.walk.model.nbodies(),
        "drive rotors added"
    );
    assert_eq!(plant.model().nv(), r.walk.model.nv());
}

#[test]
fn g1_walks_ten_natural_steps_with_every_method() {
    let r = g1();
    for method in Method::ALL {
        let p = DynamicWalkParams {
            method,
            step_length: r.walk.natural_step_length,
            ..DynamicWalkParams::for_robot(&r).unwrap()
        };
        assert_eq!(p.steps, 10);
        let s = run_dynamic_walk_robot(&r, &p).unwrap().summary;
        let planned = 9.0 * p.step_length;
        assert!(
            s.walked && s.fell_at.is_none() && !s.diverged,
            "{method}: {s:?}"
        );
        assert!(
            (s.planned_distance - planned).abs() < 0.05 * planned,
            "{s:?}"
        );
        assert!(s.progress > 0.95, "{method}: {s:?}");
        assert!(s.contact_kept && s.friction_kept, "{method}: {s:?}");
        assert!(s.end_stops && s.limit_excess <= 0.0, "{method}: {s:?}");
        assert!(s.limits_kept && s.min_joint_margin > 0.0, "{method}: {s:?}");
        assert!(s.collision_free && s.min_distance > 0.0, "{method}: {s:?}");
        assert!(s.max_tilt < 0.05, "{method}: {s:?}");
        let weight = r.weight();
        assert!((s.mean_ground_force / weight - 1.0).abs() < 0.05, "{s:?}");
    }
}
