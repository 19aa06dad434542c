//! An `whole_body::Ik` step on the G1 allocates nothing once the solver exists (counting global
//! allocator): with feet, CoM, pelvis orientation and posture tasks, joint limits, moving
//! targets, self-collision avoidance and momentum compensation.

use biped_control::avoidance::RepulsiveLaw;
use biped_control::tasks::{TaskHandle, TaskKind};
use biped_control::whole_body::Ik;
use biped_dynamics::{center_of_mass, update_placements, Data};
use biped_robots::description::Robot;
use biped_test_support::alloc::{allocations, Counting};
use nalgebra::Vector3;

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn ik_step_does_not_allocate() {
    let robot = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
    let model = &robot.urdf.model;
    let q0 = robot.comfort.clone();
    let mut data = Data::new(model);
    update_placements(model, &mut data, &q0).unwrap();
    let pose = |name| data.body_pose(model.body_id(name).unwrap());
    let mut ik = Ik::new(&robot.urdf).unwrap();
    let left = pose("left_ankle_roll_link");
    ik.frame_pose("left_ankle_roll_link", left).unwrap();
    ik.frame_pose("right_ankle_roll_link", pose("right_ankle_roll_link"))
        .unwrap();
    let com = center_of_mass(model, &mut Data::new(model), &q0, None).unwrap();
    ik.com(com.position).unwrap();
    let pelvis = pose("pelvis").rotation.to_rotation_matrix().into_inner();
    ik.frame_orientation("pelvis", pelvis).unwrap();
    ik.posture(&q0, 1e-2).unwrap();
    let law = RepulsiveLaw::Blended { s0: 1.0, t: 0.5 };
    ik.avoid_self_collision(robot.collision.clone().unwrap().model, law, 10.0)
        .unwrap();
    let reducing: Vec<&str> = robot
        .description
        .reducing
        .iter()
        .map(String::as_str)
        .collect();
    ik.compensate_momentum(&reducing).unwrap();
    let mut q = q0.clone();
    let mut step = |k: usize, q: &mut nalgebra::DVector<f64>| {
        let task = ik.task_mut(TaskHandle(0)).unwrap();
        if let TaskKind::Pose { target, .. } = &mut task.kind {
            let lift = Vector3::new(0.0, 0.0, 0.03 * (k as f64 * 0.01).sin());
            target.translation.vector = left.translation.vector + lift;
        }
        ik.step(q, 1e-3).unwrap();
    };
    for k in 0..10 {
        step(k, &mut q);
    }
    let before = allocations();
    for k in 10..110 {
        step(k, &mut q);
    }
    let n = allocations() - before;
    assert_eq!(n, 0, "{n} allocations in 100 IK steps");
}
