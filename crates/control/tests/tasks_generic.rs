//! The generic tasks of `tasks::TaskStack` on the Unitree G1 (floating base): every task's
//! Jacobian times a random velocity matches the central finite difference of the task quantity
//! computed independently (forward kinematics and CoM of `biped_dynamics`, motion by
//! `biped_dynamics::integrate`), over random configurations inside the joint limits; the task
//! errors have the documented sign; the stack's rows are the tasks' rows in order.

use biped_control::ik::orientation::rotation_log;
use biped_control::ik::TaskMap;
use biped_control::tasks::{MomentumAxes, Task, TaskKind, TaskStack};
use biped_dynamics::{center_of_mass, integrate, update_placements, Data, Model};
use nalgebra::{DMatrix, DVector, Isometry3, Matrix3, UnitQuaternion, Vector3};
use proptest::prelude::*;

mod g1_tasks;
use g1_tasks::*;

/// Angular momentum about the CoM from finite differences of the body poses: the sum of
/// `R I_c R^T w + m (c_b - c) x cdot_b` with `w` and `cdot_b` differenced.
fn momentum_fd(model: &Model, q: &DVector<f64>, v: &DVector<f64>, h: f64) -> Vector3<f64> {
    let (qp, qm) = (
        integrate(model, q, v, h).unwrap(),
        integrate(model, q, v, -h).unwrap(),
    );
    let (mut d0, mut dp, mut dm) = (Data::new(model), Data::new(model), Data::new(model));
    update_placements(model, &mut d0, q).unwrap();
    update_placements(model, &mut dp, &qp).unwrap();
    update_placements(model, &mut dm, &qm).unwrap();
    let c = center_of_mass(model, &mut d0, q, None).unwrap().position;
    let mut l = Vector3::zeros();
    for (b, body) in model.bodies().iter().enumerate() {
        let i = body.inertia();
        let com = |d: &Data| d.world_pos[b] + d.world_rot[b] * i.com();
        let cdot = (com(&dp) - com(&dm)) / (2.0 * h);
        let w = rotation_log(&(dp.world_rot[b] * dm.world_rot[b].transpose())) / (2.0 * h);
        let r = d0.world_rot[b];
        l += r * i.inertia_about_com() * r.transpose() * w + i.mass() * (com(&d0) - c).cross(&cdot);
    }
    l
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn jacobians_match_finite_differences(u in prop::collection::vec(0.0..1.0f64, 80)) {
        let model = &g1().robot.urdf.model;
        let (q, v) = state(&u);
        // a link merged into its body by a fixed joint (offset), and a body frame
        let hand = frame("left_rubber_hand");
        let foot = frame("right_ankle_roll_link");
        let pelvis = frame("pelvis");

        let (j, _) = jv(TaskKind::Position { frame: hand, target: Vector3::zeros() }, &q, &v);
        close(j.as_slice(), fd(&q, &v, |q| fk(model, q, &hand).1).as_slice(), "position")?;

        let (j, _) = jv(TaskKind::Orientation { frame: hand, target: Matrix3::identity() }, &q, &v);
        close(j.as_slice(), fd_rot(&q, &v, |q| fk(model, q, &hand).0).as_slice(), "orientation")?;

        let (j, _) = jv(TaskKind::Pose { frame: foot, target: Isometry3::identity() }, &q, &v);
        close(&j.as_slice()[..3], fd(&q, &v, |q| fk(model, q, &foot).1).as_slice(), "pose position")?;
        close(&j.as_slice()[3..], fd_rot(&q, &v, |q| fk(model, q, &foot).0).as_slice(), "pose rotation")?;

        let rel = |q: &DVector<f64>| {
            let ((ar, pr), (_, p)) = (fk(model, q, &pelvis), fk(model, q, &hand));
            ar.transpose() * (p - pr)
        };
        let kind = TaskKind::RelativePosition { frame: hand, reference: pelvis, target: Vector3::zeros() };
        let (j, _) = jv(kind, &q, &v);
        close(j.as_slice(), fd(&q, &v, rel).as_slice(), "relative position")?;
        // ... and in the frame of a rotated offset on another branch
        let camera = frame("d435_link");
        let rel = |q: &DVector<f64>| {
            let ((ar, pr), (_, p)) = (fk(model, q, &camera), fk(model, q, &hand));
            ar.transpose() * (p - pr)
        };
        let kind = TaskKind::RelativePosition { frame: hand, reference: camera, target: Vector3::zeros() };
        let (j, _) = jv(kind, &q, &v);
        close(j.as_slice(), fd(&q, &v, rel).as_slice(), "relative position")?;

        // relative orientation of the foot in the frame of the camera (a rotated offset)
        let camera = frame("d435_link");
        let rel_rot = |q: &DVector<f64>| fk(model, q, &camera).0.transpose() * fk(model, q, &foot).0;
        let kind = TaskKind::RelativeOrientation { frame: foot, reference: camera, target: Matrix3::identity() };
        let (j, _) = jv(kind, &q, &v);
        close(j.as_slice(), fd_rot(&q, &v, rel_rot).as_slice(), "relative orientation")?;

        let com = |q: &DVector<f64>| center_of_mass(model, &mut Data::new(model), q, None).unwrap().position;
        let (j, _) = jv(TaskKind::Com { target: Vector3::zeros() }, &q, &v);
        close(j.as_slice(), fd(&q, &v, com).as_slice(), "CoM")?;

        let lfd = momentum_fd(model, &q, &v, 1e-6);
        let kind = TaskKind::AngularMomentum { axes: MomentumAxes::All, target: Vector3::zeros() };
        let (j, err) = jv(kind, &q, &v);
        close(j.as_slice(), lfd.as_slice(), "angular momentum")?;
        prop_assert_eq!(err.norm(), 0.0); // a velocity task: no position error
        let kind = TaskKind::AngularMomentum { axes: MomentumAxes::Vertical, target: Vector3::zeros() };
        let (j, _) = jv(kind, &q, &v);
        close(j.as_slice(), &[lfd.z], "J_Lz")?;

        let (qi, vi) = g1().robot.joint_index("left_knee_joint").unwrap();
        let knee = |q: &DVector<f64>| Vector3::new(q[qi], 0.0, 0.0);
        let (j, err) = jv(TaskKind::Joint { q_index: qi, v_index: vi, target: 0.3 }, &q, &v);
        close(j.as_slice(), &fd(&q, &v, knee).as_slice()[..1], "joint")?;
        prop_assert!((err[0] - (0.3 - q[qi])).abs() < 1e-15);
    }
}

#[test]
fn errors_point_from_the_current_value_to_the_target() {
    let robot = &g1().robot;
    let model = &robot.urdf.model;
    let q = robot.comfort.clone();
    let hand = frame("left_rubber_hand");
    let (rot, pos) = fk(model, &q, &hand);
    let dx = Vector3::new(0.01, -0.02, 0.03);
    let (_, err) = jv(
        TaskKind::Position {
            frame: hand,
            target: pos + dx,
        },
        &q,
        &v0(),
    );
    assert!((Vector3::new(err[0], err[1], err[2]) - dx).norm() < 1e-12);
    // a target turned by dw (world axes) gives the error dw
    let dw = Vector3::new(0.02, 0.01, -0.03);
    let target = UnitQuaternion::from_scaled_axis(dw)
        .to_rotation_matrix()
        .into_inner()
        * rot;
    let (_, err) = jv(
        TaskKind::Orientation {
            frame: hand,
            target,
        },
        &q,
        &v0(),
    );
    assert!((Vector3::new(err[0], err[1], err[2]) - dw).norm() < 1e-12);
    let c = center_of_mass(model, &mut Data::new(model), &q, None)
        .unwrap()
        .position;
    let (_, err) = jv(TaskKind::Com { target: c + dx }, &q, &v0());
    assert!((Vector3::new(err[0], err[1], err[2]) - dx).norm() < 1e-12);
}

fn v0() -> DVector<f64> {
    DVector::zeros(g1().robot.urdf.model.nv())
}

#[test]
fn the_stack_is_the_tasks_rows_in_order_with_weights_as_softness() {
    let robot = &g1().robot;
    let model = &robot.urdf.model;
    let q = robot.comfort.clone();
    let hand = frame("left_rubber_hand");
    let kinds = [
        TaskKind::Com {
            target: Vector3::new(0.0, 0.0, 0.7),
        },
        TaskKind::Pose {
            frame: hand,
            target: Isometry3::translation(0.3, 0.2, 1.0),
        },
        TaskKind::AngularMomentum {
            axes: MomentumAxes::Vertical,
            target: Vector3::new(0.0, 0.0, 0.4),
        },
    ];
    let mut stack = TaskStack::new(model);
    let mut rows = Vec::new();
    for (k, kind) in kinds.iter().enumerate() {
        let task = if k == 1 {
            Task::soft(kind.clone(), 4.0)
        } else {
            Task::hard(kind.clone())
        };
        stack.push(task).unwrap();
        let mut v = DVector::zeros(model.nv());
        v[7 + k] = 1.0; // some joint velocity
        rows.push(jv(kind.clone(), &q, &v));
    }
    let m = stack.max_rows();
    assert_eq!(m, 3 + 6 + 1);
    let (mut err, mut jac) = (DVector::zeros(m), DMatrix::zeros(m, model.nv()));
    stack.error_and_jacobian(&q, &mut err, &mut jac).unwrap();
    let mut r = 0;
    for (k, (jvk, ek)) in rows.iter().enumerate() {
        let mut v = DVector::zeros(model.nv());
        v[7 + k] = 1.0;
        let part = (&jac * v).rows(r, jvk.len()).clone_owned();
        assert!((part - jvk).norm() < 1e-12, "task {k}");
        assert!((err.rows(r, ek.len()) - ek).norm() < 1e-12, "task {k}");
        r += jvk.len();
    }
    let soft = stack.softness().unwrap();
    assert_eq!(&soft[..3], &[0.0; 3]);
    assert_eq!(&soft[3..9], &[0.25; 6]);
    let mut ff = DVector::zeros(m);
    stack.feedforward(&mut ff);
    assert_eq!(ff[9], 0.4); // the momentum target is the task velocity
                            // bad tasks are rejected
    let bad = TaskKind::Joint {
        q_index: 99,
        v_index: 0,
        target: 0.0,
    };
    assert!(stack.push(Task::hard(bad)).is_err());
    assert!(stack.push(Task::soft(kinds[0].clone(), -1.0)).is_err());
}
