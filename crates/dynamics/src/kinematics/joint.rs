//! Relative kinematics of one joint (2.35)-(2.36): transform `C_i`, relative motion
//! `J_i qdot_i` and joint bias `Jdot_i qdot_i`, and the products with `J_i` used by the
//! recursions.

use super::coupled::coupled_kinematics;
use crate::model::joint::{
    euler_zxz_jacobian, euler_zxz_jr_dot_qd, euler_zxz_rotation, quaternion_rotation,
    six_dof_motion, Joint,
};
use crate::model::Body;
use crate::spatial::{sin_cos, Force, Motion, SpatialTransform};
use crate::{Data, Model};
use nalgebra::{DVector, Matrix3, Vector3, Vector6};

/// `J_i w_i` for the slice of a generalized vector `w` (velocity or acceleration) of body `i`.
#[inline]
pub(crate) fn relative_motion(data: &Data, i: usize, body: &Body, w: &DVector<f64>) -> Motion {
    let vi = body.v_index;
    match &body.joint {
        Joint::Coupled => {
            let mut m = Motion::zero();
            for (c, &k) in body.v_set.as_slice().iter().enumerate() {
                m += joint_column(data, i, &body.joint, c) * w[k];
            }
            m
        }
        Joint::Revolute(ax) | Joint::Prismatic(ax) | Joint::Rotor(ax) => ax.motion(w[vi]),
        Joint::Fixed => Motion::zero(),
        Joint::EulerZxz | Joint::Quaternion => six_dof_motion(&data.jacobian6[i], &six(w, vi)),
    }
}

/// Column `c` of body `i`'s relative Jacobian `J_i` (2.35) in body coordinates.
#[inline]
pub(crate) fn joint_column(data: &Data, i: usize, joint: &Joint, c: usize) -> Motion {
    match joint {
        Joint::Revolute(ax) | Joint::Prismatic(ax) | Joint::Rotor(ax) => ax.motion(1.0),
        Joint::Fixed => Motion::zero(),
        Joint::EulerZxz | Joint::Quaternion | Joint::Coupled => {
            let m = &data.jacobian6[i];
            Motion::new(
                Vector3::new(m[(0, c)], m[(1, c)], m[(2, c)]),
                Vector3::new(m[(3, c)], m[(4, c)], m[(5, c)]),
            )
        }
    }
}

/// `J_i^T f` accumulated into `out` at the body's index set.
#[inline]
pub(crate) fn add_projected_force(
    data: &Data,
    i: usize,
    body: &Body,
    f: &Force,
    out: &mut DVector<f64>,
) {
    let vi = body.v_index;
    match &body.joint {
        Joint::Coupled => {
            for (c, &k) in body.v_set.as_slice().iter().enumerate() {
                out[k] += joint_column(data, i, &body.joint, c).dot(f);
            }
        }
        Joint::Revolute(ax) | Joint::Prismatic(ax) | Joint::Rotor(ax) => out[vi] += ax.dot_force(f),
        Joint::Fixed => {}
        Joint::EulerZxz | Joint::Quaternion => {
            let t = data.jacobian6[i].tr_mul(&f.to_vector());
            for (c, tc) in t.iter().enumerate() {
                out[vi + c] += tc;
            }
        }
    }
}

/// Six consecutive entries of a vector starting at `start`.
#[inline]
pub(crate) fn six(w: &DVector<f64>, start: usize) -> Vector6<f64> {
    Vector6::from_iterator(w.rows(start, 6).iter().copied())
}

/// Relative transform, relative motion `J_i qdot_i` and joint bias `Jdot_i qdot_i` of body `i`.
#[inline]
pub(super) fn joint_kinematics(
    model: &Model,
    data: &mut Data,
    i: usize,
    q: &[f64],
    v: Option<&[f64]>,
) -> (SpatialTransform, Motion, Motion) {
    let body = &model.bodies[i];
    let pl = &body.placement_x;
    let (qi, vi) = (body.q_index, body.v_index);
    match &body.joint {
        Joint::Revolute(ax) | Joint::Rotor(ax) => {
            let (s, c) = sin_cos(q[qi] * ax.scale);
            let x = SpatialTransform::new(ax.axis.rot_tr_mul(s, c, &pl.rot), pl.trans);
            let rel = v.map_or(Motion::zero(), |v| ax.motion(v[vi]));
            (x, rel, Motion::zero())
        }
        Joint::Prismatic(ax) => {
            let t = ax.axis.vector() * q[qi];
            let x = SpatialTransform::new(pl.rot, pl.trans + pl.rot.tr_mul(&t));
            let rel = v.map_or(Motion::zero(), |v| ax.motion(v[vi]));
            (x, rel, Motion::zero())
        }
        Joint::Fixed => (*pl, Motion::zero(), Motion::zero()),
        Joint::Coupled => coupled_kinematics(body, data, i, q, v),
        Joint::EulerZxz => {
            let t = Vector3::new(q[qi], q[qi + 1], q[qi + 2]);
            let (phi, theta, psi) = (q[qi + 3], q[qi + 4], q[qi + 5]);
            let rq = euler_zxz_rotation(phi, theta, psi);
            let x = SpatialTransform::new(rq.tr_mul(&pl.rot), pl.trans + pl.rot.tr_mul(&t));
            data.jacobian6[i] = euler_zxz_jacobian(&rq, theta, psi);
            let Some(v) = v else {
                return (x, Motion::zero(), Motion::zero());
            };
            let qd = Vector6::from_column_slice(&v[vi..vi + 6]);
            let rel = six_dof_motion(&data.jacobian6[i], &qd);
            let dr = Vector3::new(qd[3], qd[4], qd[5]);
            let cj = Motion::new(euler_zxz_jr_dot_qd(theta, psi, &dr), Vector3::zeros());
            (x, rel, cj)
        }
        Joint::Quaternion => {
            let t = Vector3::new(q[qi], q[qi + 1], q[qi + 2]);
            let rq = quaternion_rotation(q[qi + 3], q[qi + 4], q[qi + 5], q[qi + 6])
                .unwrap_or_else(Matrix3::identity);
            let x = SpatialTransform::new(rq.tr_mul(&pl.rot), pl.trans + pl.rot.tr_mul(&t));
            let Some(v) = v else {
                return (x, Motion::zero(), Motion::zero());
            };
            let lin = Vector3::new(v[vi], v[vi + 1], v[vi + 2]);
            let ang = Vector3::new(v[vi + 3], v[vi + 4], v[vi + 5]);
            (
                x,
                Motion::new(ang, lin),
                Motion::new(Vector3::zeros(), ang.cross(&lin)),
            )
        }
    }
}
