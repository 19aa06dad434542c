//! One-DoF sub-systems made of a single link on the sub-system's parent and spin-invariant
//! Harmonic Drive rotors (the Lola drive trains of section 3.1): the O(n) branches (2.75)-(2.90)
//! reduced to the ordinary one-DoF body step plus constant rotor terms.
//!
//! With the link's `U = M-bar J`, `f-hat = M-bar b - f-bar` (link frame) and the rotors'
//! constants ([`super::axial`]) summed, `M_S = J^T U + sum s^T K s` (a scalar `D`),
//! `B_S = C^T U + sum K s` (parent frame), `p_S = (Q - J^T f-hat - sum s . h) / D` with the
//! rotors' parent-frame `h = C^T (M b - f)` (their loads `s . h`, `Data::axial_load`),
//! `K_S = C^T M-bar C + sum K - B_S B_S^T / D` (the constant `sum K` is in the parent's start
//! value `Data::mbar_init`) and `k_S = C^T f-hat + sum h + B_S p_S` (the `sum h` is in the
//! parent's `f-bar` from the first pass, `Data::force_inertia`). No member kinematics (2.77)-(2.79) are formed: the
//! link's `C-hat`, `J-hat`, `b-hat` are its own `C`, `J`, `b`.

use super::axial::AxialKind;
use super::on::add_rigid_congruence;
use crate::dynamics::on::OneDofStep;
use crate::model::joint::Joint;
use crate::spatial::{plane, Force, JointAxis, Motion, RigidInertia};
use crate::{Data, DynamicsError, Model};
use nalgebra::DVector;

/// Most spin-invariant rotors one link-with-rotors sub-system holds (more: generic branch).
const MAX_LINK_ROTORS: usize = 4;

/// Constant data of a link-with-rotors sub-system (see the module doc).
#[derive(Clone, Copy, Debug)]
pub(crate) struct LinkRotors {
    /// The link body.
    pub(crate) link: usize,
    /// The link's joint column `J`.
    axis: JointAxis,
    /// Velocity index of the sub-system's coordinate.
    v_index: usize,
    /// The sub-system's parent body.
    parent: Option<usize>,
    /// The rotor bodies (first `nrotors` entries).
    rotors: [usize; MAX_LINK_ROTORS],
    /// Number of rotors.
    nrotors: usize,
    /// `sum K s` of the rotors.
    pub(crate) ks: Force,
    /// `sum s^T K s` of the rotors.
    pub(crate) sks: f64,
    /// The link's rigid-body inertia if it has no children outside the sub-system (its
    /// `M-bar`, applied directly).
    rigid: Option<RigidInertia>,
    /// The coordinate axis of the link's rotation ([`Data::plane_axis`], held here so that
    /// the steps index no further per-body array).
    plane_axis: Option<usize>,
}

/// Per sub-system: its [`LinkRotors`] if it has one coordinate, exactly one member that is not
/// a spin-invariant rotor, that member is a revolute or prismatic link on the parent, and it
/// has at most [`MAX_LINK_ROTORS`] rotors.
pub(crate) fn link_rotor_subsystems(
    model: &Model,
    axial_member: &[Option<super::axial::AxialMember>],
) -> Vec<Option<LinkRotors>> {
    let one = |s: &super::Subsystem| {
        let mut links = s.members.iter().filter(|&&j| axial_member[j].is_none());
        let (Some(&link), None) = (links.next(), links.next()) else {
            return None;
        };
        let body = &model.bodies[link];
        let (Joint::Revolute(axis) | Joint::Prismatic(axis)) = body.joint else {
            return None;
        };
        let rotors = s.members.iter().filter_map(|&j| axial_member[j].as_ref());
        let geared = (rotors.clone()).all(|rc| rc.kind == AxialKind::Geared && rc.lumped());
        if s.v_set.len() != 1
            || body.parent != s.parent
            || rotors.count() > MAX_LINK_ROTORS
            || !geared
        {
            return None;
        }
        let rigid = s
            .members
            .iter()
            .zip(&s.rigid_member)
            .any(|(&j, &r)| j == link && r);
        let mut out = LinkRotors {
            link,
            axis,
            v_index: s.v_set[0],
            parent: s.parent,
            rotors: [0; MAX_LINK_ROTORS],
            nrotors: 0,
            rigid: rigid.then_some(body.inertia),
            plane_axis: crate::data::plane_axis(body),
            ks: Force::zero(),
            sks: 0.0,
        };
        for &j in &s.members {
            let Some(rc) = &axial_member[j] else {
                continue;
            };
            out.rotors[out.nrotors] = j;
            out.nrotors += 1;
            out.ks += rc.ks;
            out.sks += rc.sks;
        }
        Some(out)
    };
    model.subsystems.iter().map(one).collect()
}

/// Backward step (Algorithm 2.3) of link-with-rotors sub-system `s` (`data.link_rotors[s]` is
/// set); stores `B_S`, `D^-1` and `p_S` in `one_dof[link]`.
pub(crate) fn backward(data: &mut Data, s: usize, tau: &DVector<f64>) -> Result<(), DynamicsError> {
    let Some(lr) = &data.link_rotors[s] else {
        return Err(DynamicsError::Unsupported(
            "not a link-with-rotors sub-system",
        ));
    };
    let (link, ax, vi) = (lr.link, &lr.axis, lr.v_index);
    // The rotors' loads s . h; their forces are in the parent's f-bar (`Data::force_inertia`).
    // Slice indexing: one bounds comparison, where DVector's (row, column) index checks both.
    let mut rhs = tau.as_slice()[vi];
    for j in lr.rotors.iter().take(lr.nrotors) {
        rhs -= data.axial_load[*j];
    }
    let m = &data.mbar[link];
    let u = ax.apply_inertia(m);
    let hat_f = m.apply(&data.bias_acc[link]) - data.fbar[link];
    let d = ax.dot_force(&u) + lr.sks;
    crate::check::positive_pivot(vi, d)?;
    let (x, axis) = (&data.x[link], lr.plane_axis);
    let b = plane::tr_apply_force(x, axis, &u) + lr.ks;
    let dinv = 1.0 / d;
    let p = (rhs - ax.dot_force(&hat_f)) * dinv;
    data.one_dof[link] = OneDofStep { u: b, dinv, p };
    let Some(parent) = lr.parent else {
        return Ok(());
    };
    let k = plane::tr_apply_force(x, axis, &hat_f) + b * p;
    let (head, tail) = data.mbar.split_at_mut(link);
    let (m, out) = (&tail[0], &mut head[parent]);
    // The rotors' sum K is in the parent's `mbar_init`.
    match &lr.rigid {
        Some(inertia) => {
            add_rigid_congruence(inertia, x, out);
            out.sub_outer(&b, dinv);
        }
        None => m.add_tr_transform_sub_outer_to(axis, x, (&b, dinv), out),
    }
    data.fbar[parent] -= k;
    Ok(())
}

/// Second forward step (Algorithm 2.4) of link-with-rotors sub-system `s`:
/// `qddot = p_S - D^-1 B_S^T a_p` and the link's acceleration `C a_p + J qddot + b`, formed
/// only if the link has children outside the sub-system (like the loop sub-systems' members,
/// see [`Data`]: nothing reads a leaf's).
pub(crate) fn forward(data: &mut Data, s: usize) {
    let Some(lr) = &data.link_rotors[s] else {
        return;
    };
    let link = lr.link;
    let ap = lr.parent.map_or(Motion::zero(), |p| data.acc[p]);
    let qdd = data.one_dof[link].qdd(&ap);
    data.ddq.as_mut_slice()[lr.v_index] = qdd;
    if lr.rigid.is_some() {
        return;
    }
    let cap = plane::apply_motion(&data.x[link], lr.plane_axis, &ap);
    data.acc[link] = cap + lr.axis.motion(qdd) + data.bias_acc[link];
}
