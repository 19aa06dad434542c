//! `whole_body::Ik` on the Unitree G1 URDF: a reachable target is reached (checked by forward
//! kinematics), and targets that ask to leave the joint ranges leave every joint inside its
//! range with the margin and below its URDF velocity limit at every step, while the same
//! tasks without limits do leave the ranges; with self-collision avoidance on, a posture that
//! swings the arm into the torso leaves every segment pair apart (distances computed
//! independently from the forward kinematics), while without it the arm enters the torso;
//! and the arms' momentum compensation (7.3.2) cancels the vertical momentum of a leg swing.

use biped_control::avoidance::RepulsiveLaw;
use biped_control::ik::{ClosedLoopIk, CycleInput, LimitSettings, Weight};
use biped_control::tasks::{TaskHandle, TaskKind};
use biped_control::whole_body::Ik;
use biped_dynamics::centroidal_momentum;
use biped_dynamics::urdf::{load_file, UrdfModel, UrdfOptions};
use biped_dynamics::{center_of_mass, update_placements, Data, Model};
use biped_robots::description::Robot;
use nalgebra::{DVector, Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};

const FEET: [&str; 2] = ["left_ankle_roll_link", "right_ankle_roll_link"];

fn g1() -> Robot {
    Robot::load(Robot::bundled("g1").unwrap()).unwrap()
}

/// World pose of body `name` and the CoM at `q`, by forward kinematics.
fn pose(model: &Model, q: &DVector<f64>, name: &str) -> Isometry3<f64> {
    let mut data = Data::new(model);
    update_placements(model, &mut data, q).unwrap();
    let b = model.body_id(name).unwrap();
    Isometry3::from_parts(
        Translation3::from(data.world_pos[b]),
        UnitQuaternion::from_matrix(&data.world_rot[b]),
    )
}

fn com(model: &Model, q: &DVector<f64>) -> Vector3<f64> {
    center_of_mass(model, &mut Data::new(model), q, None)
        .unwrap()
        .position
}

/// Feet and CoM tasks at their values at `q`, the left foot moved by `lift`, posture soft.
fn feet_and_com(robot: &Robot, q: &DVector<f64>, lift: Vector3<f64>) -> Ik {
    let model = &robot.urdf.model;
    let mut ik = Ik::new(&robot.urdf).unwrap();
    let left = pose(model, q, FEET[0]);
    let target = Isometry3::from_parts(
        Translation3::from(left.translation.vector + lift),
        left.rotation,
    );
    ik.frame_pose(FEET[0], target).unwrap();
    ik.frame_pose(FEET[1], pose(model, q, FEET[1])).unwrap();
    ik.com(com(model, q)).unwrap();
    ik.posture(q, 1e-2).unwrap();
    ik
}

#[test]
fn reaches_a_reachable_foot_target() {
    let robot = g1();
    let model = &robot.urdf.model;
    let q0 = robot.comfort.clone();
    let lift = Vector3::new(0.05, 0.02, 0.06);
    let mut ik = feet_and_com(&robot, &q0, lift);
    let mut q = q0.clone();
    for _ in 0..200 {
        ik.step(&mut q, 0.01).unwrap();
    }
    let (l0, l1) = (pose(model, &q0, FEET[0]), pose(model, &q, FEET[0]));
    let moved = l1.translation.vector - l0.translation.vector;
    assert!((moved - lift).norm() < 1e-6, "left foot moved {moved:?}");
    assert!(l1.rotation.angle_to(&l0.rotation) < 1e-6);
    let (r0, r1) = (pose(model, &q0, FEET[1]), pose(model, &q, FEET[1]));
    assert!((r1.translation.vector - r0.translation.vector).norm() < 1e-6);
    assert!(r1.rotation.angle_to(&r0.rotation) < 1e-6);
    assert!((com(model, &q) - com(model, &q0)).norm() < 1e-6);
    assert!(ik.limits().min_margin(&q) > 0.0);
}

/// Runs `steps` IK steps of `dt` and checks the position and velocity limits after each one;
/// returns the smallest distance of a joint to its shrunk range and the largest ratio of a
/// joint speed to its velocity limit.
fn run_within_limits(ik: &mut Ik, q: &mut DVector<f64>, steps: usize, dt: f64) -> (f64, f64) {
    let margin = ik.limits().settings().margin;
    let (mut closest, mut fastest) = (f64::INFINITY, 0.0_f64);
    for step in 0..steps {
        ik.step(q, dt).unwrap();
        let qd = ik.velocities().unwrap();
        let limits = ik.limits();
        for (r, &vmax) in limits.ranges().iter().zip(limits.velocity_limits()) {
            let x = q[r.q_index];
            let room = (x - r.lower - margin).min(r.upper - margin - x);
            assert!(
                room > -1e-9,
                "step {step}: joint at q {} left [{}, {}] by {room}",
                r.q_index,
                r.lower,
                r.upper
            );
            closest = closest.min(room);
            let speed = qd[r.v_index].abs();
            assert!(
                speed <= vmax * (1.0 + 1e-12),
                "step {step}: v index {} at {speed} > {vmax}",
                r.v_index
            );
            fastest = fastest.max(speed / vmax);
        }
    }
    (closest, fastest)
}

#[test]
fn a_foot_target_half_a_metre_away_keeps_every_joint_inside_its_limits() {
    let robot = g1();
    let model = &robot.urdf.model;
    let q0 = robot.comfort.clone();
    // 0.5 m across, under the other foot: past the hip roll's inward range
    let far = Vector3::new(0.1, -0.5, 0.05);
    let mut ik = feet_and_com(&robot, &q0, far);
    let mut q = q0.clone();
    let (closest, fastest) = run_within_limits(&mut ik, &mut q, 1500, 1e-3);
    // the limits did bind: some joint ends on its shrunk range, some step at its speed limit
    assert!(closest < 1e-6, "no joint reached its range: {closest}");
    assert!(
        fastest > 1.0 - 1e-9,
        "no joint reached its velocity limit: {fastest}"
    );
    // the right foot and the CoM, still feasible, are kept
    let (r0, r1) = (pose(model, &q0, FEET[1]), pose(model, &q, FEET[1]));
    assert!((r1.translation.vector - r0.translation.vector).norm() < 1e-3);

    // without limits the same tasks drive joints out of their ranges
    let mut tasks = ik.tasks().clone();
    let mut free = ClosedLoopIk::new(&tasks);
    let weight = Weight::Identity;
    let input = CycleInput {
        gain: 0.5 / 1e-3,
        weight: &weight,
        null_space: None,
        damping: 1e-8,
        dt: 1e-3,
    };
    let mut q = q0.clone();
    let mut worst = f64::INFINITY;
    for _ in 0..1500 {
        if free.step(&mut tasks, &mut q, &input).is_err() {
            break;
        }
        worst = worst.min(ik.limits().min_margin(&q));
    }
    assert!(worst < -0.05, "the unlimited IK stays inside: {worst}");
}

#[test]
fn fixed_base_foot_asked_past_the_hip_range_stays_in_range() {
    // pelvis welded to the world: the left foot asked 0.5 m across, past the hip roll range
    let path = Robot::bundled("g1")
        .unwrap()
        .parent()
        .unwrap()
        .join("../../dynamics/data/g1_29dof_rev_1_0.urdf");
    let urdf: UrdfModel = load_file(path, &UrdfOptions::default()).unwrap();
    let model = &urdf.model;
    let mut q = model.neutral();
    let settings = LimitSettings {
        margin: 0.02,
        ..LimitSettings::default()
    };
    let mut ik = Ik::with_limits(&urdf, settings).unwrap();
    let start = pose(model, &q, FEET[0]);
    let target = Translation3::from(start.translation.vector + Vector3::new(0.0, -0.5, 0.1));
    ik.frame_position(FEET[0], target.vector).unwrap();
    ik.frame_orientation(FEET[0], Matrix3::identity()).unwrap();
    let (closest, _) = run_within_limits(&mut ik, &mut q, 2000, 1e-3);
    assert!(closest < 1e-6, "no joint reached its range: {closest}");
    assert!(ik.limits().min_margin(&q) >= 0.02 - 1e-9);
}

#[test]
fn bad_names_and_steps_are_errors() {
    let robot = g1();
    let mut ik = Ik::new(&robot.urdf).unwrap();
    assert!(ik.frame_pose("left_foot", Isometry3::identity()).is_err());
    assert!(ik.joint("left_kne_joint", 0.0).is_err());
    let h = ik.joint("left_knee_joint", 0.5).unwrap();
    assert!(ik.set_weight(h, Some(f64::NAN)).is_err());
    let mut q = robot.comfort.clone();
    assert!(ik.step(&mut q, 0.0).is_err());
    assert!(ik.step(&mut DVector::zeros(3), 0.01).is_err());
    ik.step(&mut q, 0.01).unwrap();
}

/// Smallest distance over all checked segment pairs of the G1 at `q` (every pair computed).
fn min_distance(robot: &Robot, q: &DVector<f64>) -> f64 {
    let mut c = robot.collision.clone().unwrap();
    let model = &robot.urdf.model;
    let mut data = Data::new(model);
    update_placements(model, &mut data, q).unwrap();
    let poses: Vec<_> = c
        .model_bodies
        .iter()
        .map(|b| data.body_pose(b.unwrap()))
        .collect();
    c.model.set_pair_query(biped_ssv::PairQuery::Closest);
    c.model.update(&poses).unwrap();
    c.model.min_distance().unwrap().1.result.distance
}

#[test]
fn self_collision_avoidance_keeps_the_arm_off_the_torso() {
    let robot = g1();
    let q0 = robot.comfort.clone();
    assert!(min_distance(&robot, &q0) > 0.0);
    // a posture with the left arm swung in front of and into the torso
    let mut arm_in = q0.clone();
    for (n, v) in [
        ("left_shoulder_roll_joint", -0.5),
        ("left_elbow_joint", 1.2),
        ("left_shoulder_pitch_joint", -0.3),
    ] {
        arm_in[robot.joint_index(n).unwrap().0] = v;
    }
    assert!(min_distance(&robot, &arm_in) < -0.05);
    let worst = |avoid: bool| {
        let mut ik = feet_and_com(&robot, &q0, Vector3::zeros());
        ik.posture(&arm_in, 1e-2).unwrap();
        if avoid {
            let law = RepulsiveLaw::Blended { s0: 1.0, t: 0.5 };
            ik.avoid_self_collision(robot.collision.clone().unwrap().model, law, 100.0)
                .unwrap();
        }
        let mut q = q0.clone();
        let mut worst = f64::INFINITY;
        for _ in 0..1000 {
            let report = ik.step(&mut q, 0.005).unwrap();
            if !avoid {
                assert_eq!(report.min_distance, None);
            }
            worst = worst.min(min_distance(&robot, &q));
        }
        worst
    };
    let (without, with) = (worst(false), worst(true));
    assert!(without < -0.05, "without avoidance: {without}");
    assert!(with > 0.0, "with avoidance: {with}");
}

/// Peak `|L_z|` (from `biped_dynamics::centroidal_momentum` at each step's `q` and `qdot`)
/// while the left foot swings 0.1 m fore and aft at 1 Hz, the right foot and CoM held; with
/// or without the arms' momentum compensation.
fn peak_lz_of_a_leg_swing(robot: &Robot, compensate: bool) -> f64 {
    let model = &robot.urdf.model;
    let q0 = robot.comfort.clone();
    let mut ik = feet_and_com(robot, &q0, Vector3::zeros());
    // a light posture (task 3), so that the arms are nearly free of tasks (7.3.2: q_r = q_free)
    ik.set_weight(TaskHandle(3), Some(1e-4)).unwrap();
    if compensate {
        let reducing: Vec<&str> = robot
            .description
            .reducing
            .iter()
            .map(|s| s.as_str())
            .collect();
        ik.compensate_momentum(&reducing).unwrap();
        ik.set_momentum_target(0.0);
    }
    let start = pose(model, &q0, FEET[0]);
    let (mut q, mut data, dt) = (q0.clone(), Data::new(model), 1e-3);
    let mut peak = 0.0_f64;
    for k in 0..1000 {
        let x = 0.1 * (2.0 * std::f64::consts::PI * k as f64 * dt).sin();
        let task = ik.task_mut(TaskHandle(0)).unwrap();
        if let TaskKind::Pose { target, .. } = &mut task.kind {
            target.translation.vector = start.translation.vector + Vector3::new(x, 0.0, 0.03);
        }
        ik.step(&mut q, dt).unwrap();
        let qdot = ik.velocities().unwrap().clone();
        let h = centroidal_momentum(model, &mut data, &q, &qdot).unwrap();
        if k > 100 {
            peak = peak.max(h.momentum.ang.z.abs());
        }
    }
    peak
}

#[test]
fn momentum_compensation_by_the_arms_cuts_the_vertical_momentum_of_a_leg_swing() {
    let robot = g1();
    let (without, with) = (
        peak_lz_of_a_leg_swing(&robot, false),
        peak_lz_of_a_leg_swing(&robot, true),
    );
    println!("peak |L_z|: {without} without, {with} with compensation");
    assert!(without > 0.05, "the swing produces no momentum: {without}");
    assert!(with < 0.1 * without, "compensation: {with} vs {without}");
}

#[test]
fn comfort_moves_free_joints_in_the_null_space_without_disturbing_the_tasks() {
    let robot = g1();
    let model = &robot.urdf.model;
    let q0 = robot.comfort.clone();
    let mut ik = Ik::new(&robot.urdf).unwrap();
    for f in FEET {
        ik.frame_pose(f, pose(model, &q0, f)).unwrap();
    }
    ik.com(com(model, &q0)).unwrap();
    let (elbow, _) = robot.joint_index("left_elbow_joint").unwrap();
    let mut comfy = q0.clone();
    comfy[elbow] = 1.0; // from 0.5
    ik.comfort(&comfy, 5.0).unwrap();
    assert!(ik.comfort(&DVector::zeros(3), 5.0).is_err());
    let mut q = q0.clone();
    for _ in 0..400 {
        ik.step(&mut q, 0.01).unwrap();
    }
    // the elbow moves the CoM, so the others deviate a little: nearly, not exactly, at 1.0
    assert!((q[elbow] - 1.0).abs() < 0.01, "elbow at {}", q[elbow]);
    for f in FEET {
        let (a, b) = (pose(model, &q0, f), pose(model, &q, f));
        assert!(
            (a.translation.vector - b.translation.vector).norm() < 1e-6,
            "{f}"
        );
    }
    assert!((com(model, &q) - com(model, &q0)).norm() < 1e-6);
}
