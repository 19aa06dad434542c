//! The offset task of `tasks::TaskStack` on the Unitree G1 (floating base): the offset of a
//! frame, the CoM or the CoM of a subtree from another such point, in fixed yawed axes. Its
//! Jacobian times a random velocity matches the central finite difference of the offset
//! computed independently (forward kinematics, `biped_dynamics::center_of_mass`, the subtree
//! CoM summed over the bodies below the root); the whole robot's subtree CoM is the model's
//! CoM; inactive tasks have no rows; bad points are rejected.

mod g1_tasks;

use biped_control::ik::TaskMap;
use biped_control::tasks::{Frame, Point, Task, TaskKind, TaskStack};
use biped_dynamics::{center_of_mass, update_placements, Data, Model};
use g1_tasks::*;
use nalgebra::{DMatrix, DVector, Matrix3, Rotation3, Vector3};
use proptest::prelude::*;

/// World position of `p` at `q`, from forward kinematics and the model's inertias.
fn position(model: &Model, q: &DVector<f64>, p: &Point) -> Vector3<f64> {
    let mut data = Data::new(model);
    match p {
        Point::Frame(f) => fk(model, q, f).1,
        Point::Com => center_of_mass(model, &mut data, q, None).unwrap().position,
        Point::SubtreeCom(root) => {
            update_placements(model, &mut data, q).unwrap();
            let below = |mut b: usize| loop {
                if b == *root {
                    break true;
                }
                match model.bodies()[b].parent() {
                    Some(p) => b = p,
                    None => break false,
                }
            };
            let (mut sum, mut mass) = (Vector3::zeros(), 0.0);
            for b in (0..model.nbodies()).filter(|&b| below(b)) {
                let i = model.bodies()[b].inertia();
                sum += i.mass() * (data.world_pos[b] + data.world_rot[b] * i.com());
                mass += i.mass();
            }
            sum / mass
        }
    }
}

fn offset(point: Point, from: Point, axes: Matrix3<f64>) -> TaskKind {
    TaskKind::Offset {
        point,
        from,
        axes,
        target: Vector3::zeros(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn offset_jacobians_match_finite_differences(
        u in prop::collection::vec(0.0..1.0f64, 80),
        yaw in -3.0..3.0f64,
    ) {
        let model = &g1().robot.urdf.model;
        let (q, v) = state(&u);
        let axes = Rotation3::from_axis_angle(&Vector3::z_axis(), yaw).into_inner();
        let hand = Point::Frame(frame("left_rubber_hand"));
        let arm = Point::SubtreeCom(frame("right_shoulder_pitch_link").body);
        let foot = Point::Frame(frame("right_ankle_roll_link"));
        for (point, from, what) in [
            (hand, Point::Com, "hand from CoM"),
            (arm, Point::Com, "arm CoM from CoM"),
            (Point::Com, foot, "CoM from foot"),
            (arm, hand, "arm CoM from hand"),
        ] {
            let x = |q: &DVector<f64>| {
                axes.transpose() * (position(model, q, &point) - position(model, q, &from))
            };
            let (j, err) = jv(offset(point, from, axes), &q, &v);
            close(j.as_slice(), fd(&q, &v, x).as_slice(), what)?;
            // error = target (0) - offset
            close(err.as_slice(), (-x(&q)).as_slice(), what)?;
        }
    }
}

#[test]
fn the_subtree_of_the_root_is_the_whole_robot() {
    let model = &g1().robot.urdf.model;
    let (q, v) = state(&[0.3; 80]);
    let whole = Point::SubtreeCom(0);
    let (jw, ew) = jv(
        offset(whole, Point::Frame(Frame::body(0)), Matrix3::identity()),
        &q,
        &v,
    );
    let (jc, ec) = jv(
        offset(
            Point::Com,
            Point::Frame(Frame::body(0)),
            Matrix3::identity(),
        ),
        &q,
        &v,
    );
    assert!((&jw - &jc).amax() < 1e-12 && (&ew - &ec).amax() < 1e-12);
    let c = center_of_mass(model, &mut Data::new(model), &q, None).unwrap();
    let base = fk(model, &q, &Frame::body(0)).1;
    assert!((-ew - (c.position - base)).amax() < 1e-12);
}

#[test]
fn inactive_tasks_have_no_rows() {
    let model = &g1().robot.urdf.model;
    let mut stack = TaskStack::new(model);
    let com = stack
        .push(Task::hard(TaskKind::Com {
            target: Vector3::zeros(),
        }))
        .unwrap();
    let arm = Point::SubtreeCom(frame("left_shoulder_pitch_link").body);
    stack
        .push(Task::hard(offset(arm, Point::Com, Matrix3::identity())))
        .unwrap();
    let (q, _) = state(&[0.5; 80]);
    let (mut err, mut jac) = (DVector::zeros(6), DMatrix::zeros(6, model.nv()));
    let (_, offset_rows) = jv(
        offset(arm, Point::Com, Matrix3::identity()),
        &q,
        &q.rows(0, model.nv()).into_owned(),
    );
    stack.task_mut(com).unwrap().active = false;
    assert_eq!(stack.error_and_jacobian(&q, &mut err, &mut jac).unwrap(), 3);
    assert!((err.rows(0, 3) - offset_rows).amax() < 1e-12);
    stack.task_mut(com).unwrap().active = true;
    assert_eq!(stack.error_and_jacobian(&q, &mut err, &mut jac).unwrap(), 6);
}

#[test]
fn bad_points_are_rejected() {
    let model = &g1().robot.urdf.model;
    let mut stack = TaskStack::new(model);
    let nb = model.nbodies();
    let bad = [
        offset(Point::SubtreeCom(nb), Point::Com, Matrix3::identity()),
        offset(
            Point::Com,
            Point::Frame(Frame::body(nb)),
            Matrix3::identity(),
        ),
        offset(Point::Com, Point::Com, Matrix3::from_element(f64::NAN)),
    ];
    for kind in bad {
        assert!(stack.push(Task::hard(kind.clone())).is_err(), "{kind:?}");
    }
    assert_eq!(stack.max_rows(), 0);
}

#[test]
fn ik_moves_an_arm_com_to_an_offset_from_the_com() {
    use biped_control::whole_body::Ik;
    let robot = &g1().robot;
    let model = &robot.urdf.model;
    let mut q = robot.comfort.clone();
    let arm = Point::SubtreeCom(frame("left_shoulder_pitch_link").body);
    let yaw = Rotation3::from_axis_angle(&Vector3::z_axis(), 0.3).into_inner();
    let start = yaw.transpose() * (position(model, &q, &arm) - position(model, &q, &Point::Com));
    let target = start + Vector3::new(0.04, 0.0, 0.03);
    let mut ik = Ik::new(&robot.urdf).unwrap();
    for foot in ["left_ankle_roll_link", "right_ankle_roll_link"] {
        ik.frame_pose(foot, g1_pose(model, &q, foot)).unwrap();
    }
    ik.offset("subtree:left_shoulder_pitch_link", "com", yaw, target)
        .unwrap();
    for _ in 0..300 {
        ik.step(&mut q, 0.01).unwrap();
    }
    let reached = yaw.transpose() * (position(model, &q, &arm) - position(model, &q, &Point::Com));
    assert!(
        (reached - target).norm() < 1e-5,
        "{reached:?} vs {target:?}"
    );
    assert!(matches!(ik.point("com"), Ok(Point::Com)));
    assert!(ik.point("subtree:no_such_link").is_err() && ik.point("no_such_link").is_err());
}

/// World pose of link `name` at `q`.
fn g1_pose(model: &Model, q: &DVector<f64>, name: &str) -> nalgebra::Isometry3<f64> {
    let (r, p) = fk(model, q, &frame(name));
    nalgebra::Isometry3::from_parts(p.into(), nalgebra::UnitQuaternion::from_matrix(&r))
}
