//! Second forward recursion of the O(n) algorithm (Algorithm 2.4, (2.66), (2.34)).

use super::six_dof::six_dof_forward;
use crate::model::joint::Joint;
use crate::spatial::{plane, Motion};
use crate::subsystem::{self, NodeKind};
use crate::{Data, Model};
use nalgebra::DVector;

/// Second forward recursion (Algorithm 2.4): `qddot` into `data.ddq` and body accelerations.
pub fn forward_pass_2<'d>(model: &Model, data: &'d mut Data) -> &'d DVector<f64> {
    for node in &model.nodes {
        match node.kind {
            NodeKind::Body(i) => body_forward(model, data, i),
            NodeKind::Subsystem(s) if data.link_rotors[s].is_some() => {
                subsystem::link::forward(data, s)
            }
            NodeKind::Subsystem(s) => subsystem::on::forward(model, data, s),
        }
    }
    &data.ddq
}

/// Second forward step of body `i` outside sub-systems: (2.66), (2.34).
#[inline]
fn body_forward(model: &Model, data: &mut Data, i: usize) {
    let body = &model.bodies[i];
    let ap = match body.parent {
        Some(p) => plane::apply_motion(&data.x[i], data.plane_axis[i], &data.acc[p]),
        None => Motion::zero(),
    };
    let vi = body.v_index;
    let a = match &body.joint {
        Joint::Revolute(ax) | Joint::Prismatic(ax) | Joint::Rotor(ax) => {
            let qdd = data.one_dof[i].qdd(&ap);
            data.ddq.as_mut_slice()[vi] = qdd;
            ap + ax.motion(qdd)
        }
        Joint::Fixed | Joint::Coupled => ap,
        Joint::EulerZxz | Joint::Quaternion => {
            six_dof_forward(data, i, vi, (body.parent.is_some(), ap))
        }
    };
    data.acc[i] = a + data.bias_acc[i];
}
