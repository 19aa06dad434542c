//! Backward recursion of the O(n) algorithm (Algorithm 2.3, (2.67)-(2.72)) over the rewired
//! body list: bodies outside sub-systems here, sub-systems by [`crate::subsystem`].

use super::six_dof::six_dof_backward;
use super::OneDofStep;
use crate::check;
use crate::model::joint::Joint;
use crate::spatial::Force;
use crate::subsystem::{self, NodeKind};
use crate::{Data, DynamicsError, Model};
use nalgebra::DVector;

/// Backward recursion (Algorithm 2.3): `P_i, p_i, K_i, k_i` from the leaves to the root, with
/// generalized forces `tau` (`Q_i`).
pub fn backward_pass(
    model: &Model,
    data: &mut Data,
    tau: &DVector<f64>,
) -> Result<(), DynamicsError> {
    check::data(model, data)?;
    check::vector("tau", tau, model.nv())?;
    backward_unchecked(model, data, tau)
}

/// [`backward_pass`] for inputs already checked by the caller ([`solve`]: no second scan of
/// `tau` for non-finite entries).
pub(super) fn backward_unchecked(
    model: &Model,
    data: &mut Data,
    tau: &DVector<f64>,
) -> Result<(), DynamicsError> {
    for node in model.nodes.iter().rev() {
        match node.kind {
            NodeKind::Body(i) => body_backward(model, data, i, tau)?,
            NodeKind::Subsystem(s) if data.link_rotors[s].is_some() => {
                subsystem::link::backward(data, s, tau)?
            }
            NodeKind::Subsystem(s) => subsystem::on::backward(model, data, s, tau)?,
        }
    }
    Ok(())
}

/// Backward step of body `i` outside sub-systems: `P_i, p_i, K_i, k_i` (2.67)-(2.72).
#[inline]
fn body_backward(
    model: &Model,
    data: &mut Data,
    i: usize,
    tau: &DVector<f64>,
) -> Result<(), DynamicsError> {
    let body = &model.bodies[i];
    // Each arm leaves M-bar_i - U D^-1 U^T in `mbar[i]` (no longer needed) and returns k_i.
    let k = match &body.joint {
        Joint::Revolute(ax) | Joint::Prismatic(ax) => {
            let mbar = &mut data.mbar[i];
            let u = ax.apply_inertia(mbar);
            let d = ax.dot_force(&u);
            check::positive_pivot(body.v_index, d)?;
            let dinv = 1.0 / d;
            let b = &data.bias_acc[i];
            let fbar = &data.fbar[i];
            let p = dinv * (tau.as_slice()[body.v_index] - u.dot(b) + ax.dot_force(fbar));
            let k = mbar.apply(b) + u * p - *fbar;
            mbar.sub_outer(&u, dinv);
            data.one_dof[i] = OneDofStep { u, dinv, p };
            k
        }
        Joint::Fixed if data.massless_leaf[i] => Force::zero() - data.fbar[i],
        Joint::Fixed => data.mbar[i].apply(&data.bias_acc[i]) - data.fbar[i],
        Joint::EulerZxz | Joint::Quaternion => {
            let free = matches!(body.joint, Joint::Quaternion);
            six_dof_backward(data, i, body.v_index, tau, (body.parent.is_some(), free))?
        }
        Joint::Rotor(_) | Joint::Coupled => {
            return Err(DynamicsError::Unsupported(
                "a coupled body outside a sub-system (the model was not built by ModelBuilder)",
            ))
        }
    };
    if let Some(p) = body.parent {
        let x = &data.x[i];
        let (head, tail) = data.mbar.split_at_mut(i);
        match data.plane_axis[i] {
            _ if data.massless_leaf[i] => {} // M-bar_i = 0: nothing to add.
            Some(k) => tail[0].add_tr_transform_axis_to(k, x, &mut head[p]),
            None => tail[0].add_tr_transform_to(x, &mut head[p]),
        }
        data.fbar[p] -= x.tr_apply_force(&k);
    }
    Ok(())
}
