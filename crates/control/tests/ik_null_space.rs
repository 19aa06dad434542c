//! The parts of `Ik`'s null-space term add up: with no joint at its limit box a step's joint
//! velocities are affine in the null-space gradient, so the comfort term's contribution must
//! be the same with and without self-collision avoidance (its gain scales only its own part).

use biped_control::avoidance::RepulsiveLaw;
use biped_control::whole_body::Ik;
use biped_dynamics::{update_placements, Data};
use biped_robots::description::Robot;
use nalgebra::DVector;

/// Joint velocities of one step from `q` with the feet held, optional comfort towards `q0`
/// and optional avoidance of gain `avoid`; also whether a pair was active and none saturated.
fn step(
    robot: &Robot,
    q: &DVector<f64>,
    comfort: bool,
    avoid: Option<f64>,
) -> (DVector<f64>, bool) {
    let model = &robot.urdf.model;
    let mut data = Data::new(model);
    update_placements(model, &mut data, q).unwrap();
    let mut ik = Ik::new(&robot.urdf).unwrap();
    for foot in &robot.description.feet {
        let pose = data.body_pose(ik.frame(&foot.frame).unwrap().body);
        ik.frame_pose(&foot.frame, pose * ik.frame(&foot.frame).unwrap().offset)
            .unwrap();
    }
    if comfort {
        ik.comfort(&robot.comfort, 0.05).unwrap();
    }
    if let Some(gain) = avoid {
        let law = RepulsiveLaw::Blended { s0: 1.0, t: 0.5 };
        ik.avoid_self_collision(robot.collision.clone().unwrap().model, law, gain)
            .unwrap();
    }
    let mut q = q.clone();
    let report = ik.step(&mut q, 1e-3).unwrap();
    let clean = report.saturation.fixed + report.saturation.clamped == 0
        && (avoid.is_none() || report.min_distance.is_some());
    (ik.velocities().unwrap().clone(), clean)
}

#[test]
fn comfort_is_not_scaled_by_the_avoidance_gain() {
    let robot = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
    // the comfort pose keeps the torso and the left shoulder within the activation distance;
    // move a few joints off it so that the comfort term pulls
    let mut q = robot.comfort.clone();
    for (name, dq) in [
        ("waist_yaw_joint", 0.1),
        ("right_elbow_joint", -0.2),
        ("left_wrist_roll_joint", 0.1),
    ] {
        q[robot.joint_index(name).unwrap().0] += dq;
    }
    let (none, ok0) = step(&robot, &q, false, None);
    let (comfort, ok1) = step(&robot, &q, true, None);
    let (avoid, ok2) = step(&robot, &q, false, Some(100.0));
    let (both, ok3) = step(&robot, &q, true, Some(100.0));
    assert!(
        ok0 && ok1 && ok2 && ok3,
        "a joint saturated or no pair was active: {:?}",
        [ok0, ok1, ok2, ok3]
    );
    let by_comfort = &comfort - &none;
    let by_avoidance = &avoid - &none;
    assert!(
        by_comfort.norm() > 1e-3,
        "comfort does nothing: {}",
        by_comfort.norm()
    );
    assert!(
        by_avoidance.norm() > 1e-3,
        "avoidance does nothing: {}",
        by_avoidance.norm()
    );
    let miss = (&both - &none - &by_comfort - &by_avoidance).norm();
    assert!(
        miss < 1e-9 * (1.0 + both.norm()),
        "parts do not add up: {miss}"
    );
}
