//! Composite-rigid-body algorithm: the joint-space mass matrix `M = sum_i Jbar_i^T M_i Jbar_i`.
//!
//! Works on *joint instances*: every body with a non-empty index set contributes its columns
//! `J_i` to the coordinates of its index set, so geared rotors sharing their driver's
//! coordinate (3.1) are handled exactly (contributions are accumulated).

use crate::model::joint::Joint;
use crate::spatial::{Force, Motion};
use crate::{Data, Model};

/// Column `c` of body `i`'s relative Jacobian `J_i`.
#[inline]
fn column(data: &Data, i: usize, joint: &Joint, c: usize) -> Motion {
    match joint {
        Joint::Revolute(ax) | Joint::Prismatic(ax) | Joint::Rotor(ax) => ax.motion(1.0),
        Joint::Fixed => Motion::zero(),
        Joint::EulerZxz | Joint::Quaternion => {
            Motion::from_vector(&data.jacobian6[i].column(c).into_owned())
        }
    }
}

/// `J_i[:, c]^T f`.
#[inline]
fn column_dot(data: &Data, i: usize, joint: &Joint, c: usize, f: &Force) -> f64 {
    match joint {
        Joint::Revolute(ax) | Joint::Prismatic(ax) | Joint::Rotor(ax) => ax.dot_force(f),
        Joint::Fixed => 0.0,
        Joint::EulerZxz | Joint::Quaternion => data.jacobian6[i].column(c).dot(&f.to_vector()),
    }
}

/// Mass matrix into `data.mass` from the transforms `C_i` already in `data`.
pub(crate) fn crba(model: &Model, data: &mut Data) {
    let n = model.nbodies();
    for (i, body) in model.bodies.iter().enumerate() {
        data.ic[i] = body.inertia.to_articulated();
    }
    for i in (0..n).rev() {
        if let Some(p) = model.bodies[i].parent {
            let add = data.ic[i].tr_transform(&data.x[i]);
            data.ic[p] += add;
        }
    }
    data.mass.fill(0.0);
    for (i, body) in model.bodies.iter().enumerate() {
        let set = body.v_set.as_slice();
        for (c, &col) in set.iter().enumerate() {
            let f = data.ic[i].apply(&column(data, i, &body.joint, c));
            for (c2, &row) in set.iter().enumerate() {
                data.mass[(row, col)] += column_dot(data, i, &body.joint, c2, &f);
            }
            ancestors_column(model, data, i, col, f);
        }
    }
}

/// Walks from body `i` to the root, adding `J_j^T C^T ... f` to rows/columns of ancestors `j`.
fn ancestors_column(model: &Model, data: &mut Data, i: usize, col: usize, mut f: Force) {
    let mut j = i;
    while let Some(p) = model.bodies[j].parent {
        f = data.x[j].tr_apply_force(&f);
        j = p;
        let bj = &model.bodies[j];
        for (c2, &row) in bj.v_set.as_slice().iter().enumerate() {
            let val = column_dot(data, j, &bj.joint, c2, &f);
            data.mass[(row, col)] += val;
            data.mass[(col, row)] += val;
        }
    }
}
