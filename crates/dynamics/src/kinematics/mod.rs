//! Recursive kinematics (2.33)-(2.37): the first forward recursion (Algorithm 2.2) shared by
//! every algorithm of the crate, and the public forward-kinematics entry points.
//!
//! Split by concept: `joint` relative joint kinematics `C_i`, `J_i qdot_i`, `Jdot_i qdot_i`
//! (2.35)-(2.36) and products with `J_i`; `coupled` coupled parts of closed-form mechanisms
//! (ch. 3); `rotor` Harmonic Drive rotor frames (3.1)-(3.2); `step` one body step of the
//! recursion (world pose, `g_i`, `v_i` (2.33), `b_i` (2.37)) and body forces (2.56); `plane`
//! its written-out forms for revolute joints about a coordinate axis of an unrotated placement
//! and for translation-only fixed joints (tested equal to the general step); this file the
//! passes over all bodies, which take `q`, `v` as slices once.

mod coupled;
mod joint;
mod plane;
mod rotor;
mod step;

pub(crate) use coupled::{coupled_transform, identity_placements};
pub(crate) use joint::{add_projected_force, joint_column, relative_motion, six};
pub(crate) use rotor::{rotor_frames, rotor_transform};
use step::body_step;
pub(crate) use step::{body_force, body_kinematics, fd_step_kind, force_of, step_kind, StepKind};

use crate::check;
use crate::spatial::Wrench;
use crate::{Data, DynamicsError, Model};
use nalgebra::DVector;

/// Positions, velocities and accelerations of all bodies for `(q, v, a)` (2.33)-(2.37).
///
/// Fills `x`, `world_rot`, `world_pos`, `vel`, `bias_acc` and `acc` of `data`; `acc` is the
/// kinematic acceleration (no gravity).
pub fn forward_kinematics(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    a: &DVector<f64>,
) -> Result<(), DynamicsError> {
    kinematics_pass(model, data, (q, v, a), false)
}

/// [`forward_kinematics`] with every body stepped by the general joint kinematics and child
/// step instead of its precomputed step kind: the independent reference the written-out fast
/// paths are tested against (test hook; same results up to rounding, slower).
#[doc(hidden)]
pub fn general_forward_kinematics(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    a: &DVector<f64>,
) -> Result<(), DynamicsError> {
    kinematics_pass(model, data, (q, v, a), true)
}

/// [`forward_kinematics`] of `(q, v, a)`, by the general step for every body if `general`.
fn kinematics_pass(
    model: &Model,
    data: &mut Data,
    (q, v, a): (&DVector<f64>, &DVector<f64>, &DVector<f64>),
    general: bool,
) -> Result<(), DynamicsError> {
    check::data(model, data)?;
    check::configuration(model, q)?;
    check::vector("v", v, model.nv())?;
    check::vector("a", a, model.nv())?;
    let (q, v) = (q.as_slice(), v.as_slice());
    for body in model.bodies.iter().enumerate() {
        let kind = if general {
            StepKind::General
        } else {
            data.step_kind[body.0]
        };
        body_step(model, data, body, kind, q, Some(v));
    }
    take_fault(data)?;
    propagate_accelerations(model, data, Some(a));
    Ok(())
}

/// World poses and transforms `C_i` of all bodies for configuration `q`.
pub fn update_placements(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
) -> Result<(), DynamicsError> {
    check::data(model, data)?;
    check::configuration(model, q)?;
    for body in model.bodies.iter().enumerate() {
        let kind = data.step_kind[body.0];
        body_step(model, data, body, kind, q.as_slice(), None);
    }
    take_fault(data)
}

/// `a_i = C_i a_p(i) + J_i qddot_i + b_i` (2.34) for all bodies; `qdd = None` means zero.
pub(crate) fn propagate_accelerations(model: &Model, data: &mut Data, qdd: Option<&DVector<f64>>) {
    for (i, body) in model.bodies.iter().enumerate() {
        let mut a = data.bias_acc[i];
        if let Some(p) = body.parent {
            a += data.x[i].apply_motion(&data.acc[p]);
        }
        if let Some(qdd) = qdd {
            a += relative_motion(data, i, body, qdd);
        }
        data.acc[i] = a;
    }
}

/// Error if a mechanism failed during the last kinematics pass (clears the record). Every
/// kinematics pass ends here, so this also marks the forward-dynamics kinematics as stale.
pub(crate) fn take_fault(data: &mut Data) -> Result<(), DynamicsError> {
    data.fd_kinematics = false;
    match data.mechanism_fault.take() {
        None => Ok(()),
        Some((body, source)) => Err(DynamicsError::Mechanism { body, source }),
    }
}

/// Full first forward recursion: kinematics and body forces for all bodies (Algorithm 2.2).
pub(crate) fn first_forward(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    fext: Option<&[Wrench]>,
) {
    let (q, v) = (q.as_slice(), v.as_slice());
    for (i, body) in model.bodies.iter().enumerate() {
        let kind = data.step_kind[i];
        body_step(model, data, (i, body), kind, q, Some(v));
        body_force(model, data, i, fext);
    }
}

/// Kinematic half of the first forward recursion (Algorithm 2.2 without body forces): `C_i`,
/// world poses, `g_i`, `v_i`, `b_i` and the mechanism loop caches of all bodies except the
/// spin-invariant motor rotors (see [`crate::subsystem::axial`]), whose kinematics the O(n)
/// solve does not need (of a roller-screw rotor only its spin rate is recorded);
/// [`complete_rotor_kinematics`] adds them from the stored `q, v`.
pub(crate) fn first_forward_kinematics(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
) {
    // Slice copies (a memcpy) instead of nalgebra's element-wise `copy_from`; the lengths
    // were checked by the caller (`check::data`, `check::configuration`, `check::vector`).
    data.fd_q.as_mut_slice().copy_from_slice(q.as_slice());
    data.fd_v.as_mut_slice().copy_from_slice(v.as_slice());
    let (q, v) = (q.as_slice(), v.as_slice());
    // Taken out of `data` for the loop (no step reads it) and put back: iterated beside the
    // bodies without bounds checks while the steps borrow `data`.
    let kinds = std::mem::take(&mut data.fd_step_kind);
    for (i, (body, &kind)) in model.bodies.iter().zip(&kinds).enumerate() {
        match kind {
            StepKind::SkipRotor => {}
            StepKind::AxialMotion => coupled::axial_motion(body, data, i, q, v),
            kind => body_step(model, data, (i, body), kind, q, Some(v)),
        }
    }
    data.fd_step_kind = kinds;
}

/// Kinematics of the rotors skipped by [`first_forward_kinematics`], from its stored `q, v`.
pub(crate) fn complete_rotor_kinematics(model: &Model, data: &mut Data) {
    let (q, v) = (
        std::mem::take(&mut data.fd_q),
        std::mem::take(&mut data.fd_v),
    );
    for (i, body) in model.bodies.iter().enumerate() {
        if data.axial_member[i].is_some() {
            let kind = data.step_kind[i];
            body_step(
                model,
                data,
                (i, body),
                kind,
                q.as_slice(),
                Some(v.as_slice()),
            );
        }
    }
    (data.fd_q, data.fd_v) = (q, v);
}

/// Body forces `f_i` (2.56) of all bodies from the kinematics already in `data`.
pub(crate) fn body_forces(model: &Model, data: &mut Data, fext: Option<&[Wrench]>) {
    for i in 0..model.nbodies() {
        body_force(model, data, i, fext);
    }
}
