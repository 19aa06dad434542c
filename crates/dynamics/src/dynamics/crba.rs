//! Composite-rigid-body algorithm: the joint-space mass matrix `M = sum_i Jbar_i^T M_i Jbar_i`.
//!
//! Works on *joint instances*: every body with a non-empty index set contributes its columns
//! `J_i` to the coordinates of its index set, so geared rotors sharing their driver's
//! coordinate (3.1) are handled exactly (contributions are accumulated).
//!
//! Evaluated in world axes about a common point (body 0's origin): body inertias and Jacobian columns are
//! mapped there once, so composite inertias accumulate by plain addition and every entry
//! `M_jk = S_j . (I^c_i S_i)` of an ancestor `j` is a single 6-D dot product.

use crate::kinematics::joint_column as column;
use crate::spatial::{Force, SpatialTransform};
use crate::{Data, Model};

/// Mass matrix into `data.mass` from the world poses already in `data`.
pub(crate) fn crba(model: &Model, data: &mut Data) {
    for (i, body) in model.bodies.iter().enumerate() {
        let to_world = SpatialTransform::new(data.world_rot[i].transpose(), data.world_pos[i]);
        data.ic[i] = body
            .inertia
            .to_world(&data.world_rot[i], &data.world_pos[i]);
        let offset = data.col_offset[i];
        for c in 0..body.v_set.len() {
            data.col_world[offset + c] =
                to_world.inv_apply_motion(&column(data, i, &body.joint, c));
        }
    }
    for i in (0..model.nbodies()).rev() {
        if let Some(p) = model.bodies[i].parent {
            let (head, tail) = data.ic.split_at_mut(i);
            head[p] += tail[0];
        }
    }
    data.mass.as_mut_slice().fill(0.0);
    for (i, body) in model.bodies.iter().enumerate() {
        let set = body.v_set.as_slice();
        let offset = data.col_offset[i];
        for (c, &col) in set.iter().enumerate() {
            let f = data.ic[i].apply(&data.col_world[offset + c]);
            for (c2, &row) in set.iter().enumerate() {
                data.mass[(row, col)] += data.col_world[offset + c2].dot(&f);
            }
            ancestors_column(model, data, i, col, &f);
        }
    }
}

/// Adds `S_j . f` to the rows/columns of every ancestor `j` of body `i` (both triangles).
fn ancestors_column(model: &Model, data: &mut Data, i: usize, col: usize, f: &Force) {
    let mut j = i;
    while let Some(p) = model.bodies[j].parent {
        j = p;
        let bj = &model.bodies[j];
        let offset = data.col_offset[j];
        for (c2, &row) in bj.v_set.as_slice().iter().enumerate() {
            let val = data.col_world[offset + c2].dot(f);
            data.mass[(row, col)] += val;
            data.mass[(col, row)] += val;
        }
    }
}
