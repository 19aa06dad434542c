//! The G1 set-up of the generic task tests: the bundled description, random states inside
//! the joint limits, forward kinematics of frames, one-task stacks and central differences.
#![allow(dead_code)]

use biped_control::ik::orientation::rotation_log;
use biped_control::ik::TaskMap;
use biped_control::tasks::{Frame, Task, TaskKind, TaskStack};
use biped_dynamics::{integrate, update_placements, Data, Model};
use biped_robots::description::Robot;
use nalgebra::{DMatrix, DVector, Isometry3, Matrix3, UnitQuaternion, Vector3};
use proptest::prelude::*;
use std::sync::OnceLock;

pub struct G1 {
    pub robot: Robot,
}

pub fn g1() -> &'static G1 {
    static G1: OnceLock<G1> = OnceLock::new();
    G1.get_or_init(|| G1 {
        robot: Robot::load(Robot::bundled("g1").unwrap()).unwrap(),
    })
}

/// The frame of URDF link `name` (body and pose in it).
pub fn frame(name: &str) -> Frame {
    let l = g1().robot.urdf.links.iter().find(|l| l.link == name);
    let l = l.unwrap_or_else(|| panic!("{name}"));
    Frame {
        body: l.body.unwrap(),
        offset: l.pose,
    }
}

/// World rotation and origin of `f` by forward kinematics at `q`.
pub fn fk(model: &Model, q: &DVector<f64>, f: &Frame) -> (Matrix3<f64>, Vector3<f64>) {
    let mut data = Data::new(model);
    update_placements(model, &mut data, q).unwrap();
    let body = Isometry3::from_parts(
        data.world_pos[f.body].into(),
        UnitQuaternion::from_matrix(&data.world_rot[f.body]),
    );
    let pose = body * f.offset;
    (
        pose.rotation.to_rotation_matrix().into_inner(),
        pose.translation.vector,
    )
}

/// A random configuration inside the limits and a random velocity from `u` (values in [0, 1)).
pub fn state(u: &[f64]) -> (DVector<f64>, DVector<f64>) {
    let robot = &g1().robot;
    let model = &robot.urdf.model;
    let mut q = model.neutral();
    let rot = UnitQuaternion::from_euler_angles(u[0] - 0.5, u[1] - 0.5, 6.0 * u[2]);
    let c = rot.quaternion().coords;
    q.fixed_rows_mut::<3>(0)
        .copy_from(&Vector3::new(u[3] - 0.5, u[4] - 0.5, 0.5 + u[5]));
    q.fixed_rows_mut::<4>(3).copy_from(&c);
    for (k, j) in robot.urdf.joints.iter().enumerate() {
        let [lo, hi] = j.range.unwrap();
        let (qi, _) = robot.joint_index(&j.name).unwrap();
        q[qi] = lo + (hi - lo) * u[6 + k];
    }
    let v = DVector::from_iterator(model.nv(), (0..model.nv()).map(|i| 2.0 * u[40 + i] - 1.0));
    (q, v)
}

/// `J v` of a one-task stack at `q`, and its error.
pub fn jv(kind: TaskKind, q: &DVector<f64>, v: &DVector<f64>) -> (DVector<f64>, DVector<f64>) {
    let mut stack = TaskStack::new(&g1().robot.urdf.model);
    stack.push(Task::hard(kind)).unwrap();
    let m = stack.max_rows();
    let (mut err, mut jac) = (DVector::zeros(m), DMatrix::zeros(m, stack.nv()));
    assert_eq!(stack.error_and_jacobian(q, &mut err, &mut jac).unwrap(), m);
    (&jac * v, err)
}

/// Central difference `(f(q (+) h v) - f(q (+) -h v)) / 2h` of a vector quantity.
pub fn fd(
    q: &DVector<f64>,
    v: &DVector<f64>,
    f: impl Fn(&DVector<f64>) -> Vector3<f64>,
) -> Vector3<f64> {
    let model = &g1().robot.urdf.model;
    let h = 1e-6;
    (f(&integrate(model, q, v, h).unwrap()) - f(&integrate(model, q, v, -h).unwrap())) / (2.0 * h)
}

/// Central difference of a rotation: `log(R(+) R(-)^T) / 2h` (the angular velocity, in the
/// axes `R` is expressed in).
pub fn fd_rot(
    q: &DVector<f64>,
    v: &DVector<f64>,
    f: impl Fn(&DVector<f64>) -> Matrix3<f64>,
) -> Vector3<f64> {
    let model = &g1().robot.urdf.model;
    let h = 1e-6;
    let (rp, rm) = (
        f(&integrate(model, q, v, h).unwrap()),
        f(&integrate(model, q, v, -h).unwrap()),
    );
    rotation_log(&(rp * rm.transpose())) / (2.0 * h)
}

pub fn close(a: &[f64], b: &[f64], what: &str) -> Result<(), TestCaseError> {
    let scale = 1.0 + b.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    for (x, y) in a.iter().zip(b) {
        prop_assert!(
            (x - y).abs() < 2e-6 * scale,
            "{what}: J v {a:?} vs FD {b:?}"
        );
    }
    Ok(())
}
