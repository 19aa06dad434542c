//! One body step of the first forward recursion (Algorithm 2.2): world pose, `g_i`, `v_i`
//! (2.33) and `b_i` (2.37) from the parent's, and the body force `f_i` (2.56).

use super::joint::joint_kinematics;
use super::plane::{plane_revolute_step, translation_step};
use crate::model::joint::Joint;
use crate::model::Body;
use crate::spatial::plane::{General, Plane, RotationOps};
use crate::spatial::{Force, Motion, RigidInertia, SpatialTransform, SubspaceKind, Wrench};
use crate::subsystem::axial::AxialKind;
use crate::{Data, Model};
use nalgebra::{DVector, Matrix3, Vector3};

/// One step of the first forward recursion for body `i`: `C_i`, world pose, `g_i`, `v_i`
/// (2.33) and `b_i` (2.37); without `v` velocities and `b_i` are zero.
#[inline]
pub(crate) fn body_kinematics(
    model: &Model,
    data: &mut Data,
    i: usize,
    q: &DVector<f64>,
    v: Option<&DVector<f64>>,
) {
    let body = (i, &model.bodies[i]);
    let kind = data.step_kind[i];
    body_step(
        model,
        data,
        body,
        kind,
        q.as_slice(),
        v.map(|v| v.as_slice()),
    );
}

/// How the first forward recursion steps one body, decided once per model in
/// [`Data::new`] from the joint, placement and parent ([`step_kind`], [`fd_step_kind`]; the
/// fast paths are tested against the general step, `general_forward_kinematics`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum StepKind {
    /// Revolute (or geared-rotor) joint about `e_x` of an unrotated placement:
    /// [`plane_revolute_step`] with `K = 0`.
    PlaneX(PlaneJoint),
    /// As [`StepKind::PlaneX`] about `e_y` (`K = 1`).
    PlaneY(PlaneJoint),
    /// As [`StepKind::PlaneX`] about `e_z` (`K = 2`).
    PlaneZ(PlaneJoint),
    /// Fixed joint with a translation-only placement and parent `p`: [`translation_step`].
    Translation(usize),
    /// Any other body: the general joint kinematics and child step.
    General,
    /// Forward-dynamics pass only: a spin-invariant Harmonic Drive rotor, skipped
    /// ([`crate::subsystem::axial`]).
    SkipRotor,
    /// Forward-dynamics pass only: a roller-screw rotor or nut, of which only its spin or
    /// travel is recorded ([`super::coupled::axial_motion`]).
    AxialMotion,
}

/// Parent `p` and axis scale of a [`StepKind::PlaneX`]-type body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PlaneJoint {
    /// Parent body (`p < i`).
    pub(crate) parent: usize,
    /// Axis scale (1, or the gear ratio `N` of a geared rotor (3.1)).
    pub(crate) scale: f64,
}

/// [`StepKind`] of body `(i, body)` given its [`Data::plane_axis`] `axis`: the plane and
/// translation paths need a parent before `i` (true for every model; it lets the compiler
/// drop bounds checks), the plane path an angular axis (always so for revolute and rotor
/// joints after `Joint::compile`).
pub(crate) fn step_kind((i, body): (usize, &Body), axis: Option<usize>) -> StepKind {
    let parent = body.parent.filter(|&p| p < i);
    match (&body.joint, axis, parent) {
        (Joint::Revolute(ax) | Joint::Rotor(ax), Some(k), Some(parent))
            if ax.kind == SubspaceKind::Angular =>
        {
            let j = PlaneJoint {
                parent,
                scale: ax.scale,
            };
            [
                StepKind::PlaneX(j),
                StepKind::PlaneY(j),
                StepKind::PlaneZ(j),
            ][k]
        }
        (Joint::Fixed, _, Some(p)) if body.placement_x.rot == Matrix3::identity() => {
            StepKind::Translation(p)
        }
        _ => StepKind::General,
    }
}

/// [`StepKind`] of a body in the forward-dynamics kinematics pass: its [`step_kind`] `kind`
/// unless it is an axial member (`Data::axial_member`), whose pose that pass skips.
pub(crate) fn fd_step_kind(kind: StepKind, member: Option<AxialKind>) -> StepKind {
    match member {
        None => kind,
        Some(AxialKind::Geared) => StepKind::SkipRotor,
        Some(_) => StepKind::AxialMotion,
    }
}

/// [`body_kinematics`] of body `(i, model.bodies[i])` by its precomputed `kind` on coordinate
/// slices (both taken once per pass by the callers, which iterate over the bodies without
/// bounds checks). The written-out paths of [`super::plane`] need velocities; without them,
/// and for the forward-dynamics-only kinds, the general step runs (inlined into the passes;
/// the `p < i` guards, true by construction, let the compiler drop bounds checks on the
/// parent's entries).
#[inline(always)]
pub(crate) fn body_step(
    model: &Model,
    data: &mut Data,
    (i, body): (usize, &Body),
    kind: StepKind,
    q: &[f64],
    v: Option<&[f64]>,
) {
    let r = &body.placement_x.trans;
    let at = |v: &[f64]| (q[body.q_index], v[body.v_index]);
    match (kind, v) {
        (StepKind::PlaneX(j), Some(v)) if j.parent < i => {
            plane_revolute_step::<0>(data, i, j.parent, r, j.scale, at(v))
        }
        (StepKind::PlaneY(j), Some(v)) if j.parent < i => {
            plane_revolute_step::<1>(data, i, j.parent, r, j.scale, at(v))
        }
        (StepKind::PlaneZ(j), Some(v)) if j.parent < i => {
            plane_revolute_step::<2>(data, i, j.parent, r, j.scale, at(v))
        }
        (StepKind::Translation(p), Some(_)) if p < i => {
            translation_step(data, i, p, &body.placement_x)
        }
        _ => general_body_kinematics(model, data, i, q, v),
    }
}

/// [`body_step`] by the general joint kinematics and child step (every joint type).
#[inline]
pub(crate) fn general_body_kinematics(
    model: &Model,
    data: &mut Data,
    i: usize,
    q: &[f64],
    v: Option<&[f64]>,
) {
    let (x, rel, cj) = joint_kinematics(model, data, i, q, v);
    match model.bodies[i].parent {
        None => {
            data.world_rot[i] = x.rot.transpose();
            data.world_pos[i] = x.trans;
            data.gravity_body[i] = x.rot * model.gravity;
            data.vel[i] = rel;
            data.bias_acc[i] = cj;
        }
        Some(p) => {
            let v = v.is_some();
            match data.plane_axis[i] {
                Some(0) => child_step(data, i, p, &x, &Plane::<0>(&x.rot), rel, cj, v),
                Some(1) => child_step(data, i, p, &x, &Plane::<1>(&x.rot), rel, cj, v),
                Some(_) => child_step(data, i, p, &x, &Plane::<2>(&x.rot), rel, cj, v),
                None => child_step(data, i, p, &x, &General(&x.rot), rel, cj, v),
            }
        }
    }
    data.x[i] = x;
}

/// World pose, `g_i`, `v_i` (2.33) and `b_i` (2.37) of body `i` from its parent `p`, with the
/// products by `A = x.rot` done by `r` (general or about a coordinate axis).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn child_step<R: RotationOps>(
    data: &mut Data,
    i: usize,
    p: usize,
    x: &SpatialTransform,
    r: &R,
    rel: Motion,
    cj: Motion,
    with_velocity: bool,
) {
    data.world_rot[i] = r.compose_tr(&data.world_rot[p]);
    data.world_pos[i] = data.world_pos[p] + data.world_rot[p] * x.trans;
    data.gravity_body[i] = r.mul(&data.gravity_body[p]);
    if with_velocity {
        // C v_p = [A w_p; A v_p + (A w_p) x (A r)] shares `A r` with the bias (2.37).
        let w = r.mul(&data.vel[p].ang);
        let rk = r.mul(&x.trans);
        let vp = Motion::new(w, r.mul(&data.vel[p].lin) + w.cross(&rk));
        data.vel[i] = vp + rel;
        data.bias_acc[i] = Motion::new(
            w.cross(&rel.ang) + cj.ang,
            w.cross(&(w.cross(&rk) + rel.lin * 2.0)) + cj.lin,
        );
    } else {
        data.vel[i] = Motion::zero();
        data.bias_acc[i] = Motion::zero();
    }
}

/// Body force `f_i = f_ext,i + f_g,i - h_i` of (2.56) (Algorithm 2.1, step 2).
#[inline]
pub(crate) fn body_force(model: &Model, data: &mut Data, i: usize, fext: Option<&[Wrench]>) {
    let w = data.vel[i].ang;
    data.force[i] = force_of(&model.bodies[i].inertia, &data.gravity_body[i], &w, fext, i);
}

/// `f_ext,i + f_g,i - h_i` of (2.56) from gravity `g` and angular velocity `w` (body axes).
#[inline(always)]
pub(crate) fn force_of(
    inertia: &RigidInertia,
    g: &Vector3<f64>,
    w: &Vector3<f64>,
    fext: Option<&[Wrench]>,
    i: usize,
) -> Force {
    let mut f = inertia.gravity_force(g) - inertia.bias_force(w);
    if let Some(fext) = fext {
        f += fext[i];
    }
    f
}
