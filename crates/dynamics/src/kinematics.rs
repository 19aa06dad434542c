//! Recursive kinematics (2.33)-(2.37): the first forward recursion (Algorithm 2.2) shared by
//! every algorithm of the crate, and the public forward-kinematics entry points.

use crate::check;
use crate::mechanism::harmonic_drive::HarmonicDriveRotor;
use crate::mechanism::{Coupling, MechanismError, RelativeMotion, MAX_COUPLED};
use crate::model::coupling::Mechanism;
use crate::model::joint::{
    euler_zxz_jacobian, euler_zxz_jr_dot_qd, euler_zxz_rotation, quaternion_rotation,
    six_dof_motion, Joint,
};
use crate::model::{Body, JointModel};
use crate::spatial::plane::{General, Plane, RotationOps};
use crate::spatial::{sin_cos, Axis, Force, Motion, RigidInertia, SpatialTransform, Wrench};
use crate::{Data, DynamicsError, Model};
use nalgebra::{DVector, Isometry3, Matrix3, Translation3, Vector3, Vector6};

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
    check::data(model, data)?;
    check::configuration(model, q)?;
    check::vector("v", v, model.nv())?;
    check::vector("a", a, model.nv())?;
    for i in 0..model.nbodies() {
        body_kinematics(model, data, i, q, Some(v));
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
    for i in 0..model.nbodies() {
        body_kinematics(model, data, i, q, None);
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
fn joint_kinematics(
    model: &Model,
    data: &mut Data,
    i: usize,
    q: &DVector<f64>,
    v: Option<&DVector<f64>>,
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
            let qd = six(v, vi);
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

/// Relative kinematics of a coupled part from its mechanism (see [`crate::mechanism`]): the
/// Jacobian columns go to `jacobian6[i]`; the joint bias adds `omega_rel x v_rel` to the
/// mechanism's component-wise `Jdot qd` (the frame rotates while `v_rel` is expressed in it).
/// A mechanism error leaves the placement and records the body in `mechanism_fault`.
fn coupled_kinematics(
    body: &Body,
    data: &mut Data,
    i: usize,
    q: &DVector<f64>,
    v: Option<&DVector<f64>>,
) -> (SpatialTransform, Motion, Motion) {
    let JointModel::Coupled { mechanism, .. } = &body.joint_model else {
        return (body.placement_x, Motion::zero(), Motion::zero());
    };
    if let Mechanism::HarmonicDrive(rotor) = mechanism {
        return rotor_kinematics(rotor, body, data, i, q, v);
    }
    let n = body.v_set.len();
    let (mut qin, mut qdin) = ([0.0; MAX_COUPLED], [0.0; MAX_COUPLED]);
    for k in 0..n {
        qin[k] = q[body.q_set.as_slice()[k]];
        qdin[k] = v.map_or(0.0, |v| v[body.v_set.as_slice()[k]]);
    }
    let motion = match mechanism {
        Mechanism::Ankle(part) => part.relative_cached(&qin[..n], &qdin[..n], &mut data.ankle_loop),
        Mechanism::Knee(part) => part.relative_cached(&qin[..n], &qdin[..n], &mut data.knee_loop),
        _ => mechanism
            .motion(&qin[..n], &qdin[..n])
            .map(|m| RelativeMotion::from_coupled(&m)),
    };
    let fault = match motion {
        Ok(m) if m.pos.iter().all(|x| x.is_finite()) => Ok(m),
        Ok(_) => Err(MechanismError::BadInput {
            mechanism: "coupled part",
            reason: "non-finite pose".into(),
        }),
        Err(e) => Err(e),
    };
    let m = match fault {
        Ok(m) => m,
        Err(e) => {
            data.mechanism_fault = Some((i, e));
            return (body.placement_x, Motion::zero(), Motion::zero());
        }
    };
    // Pose `placement * (A_pk, r)`: `A_kp = A_pk^T A_placement^T`, origin shifted by the placement.
    let pl = &body.placement_x;
    let x = SpatialTransform::new(m.rot.tr_mul(&pl.rot), pl.trans + pl.rot.tr_mul(&m.pos));
    let mut rel = Motion::zero();
    for (c, (col, qd)) in m.jacobian.iter().zip(&qdin).take(n).enumerate() {
        data.jacobian6[i].set_column(c, col);
        rel += Motion::from_vector(col) * *qd;
    }
    let mut cj = Motion::from_vector(&m.bias);
    cj.lin += rel.ang.cross(&rel.lin);
    (x, rel, cj)
}

/// Harmonic Drive rotor (3.1)-(3.2) without evaluating the mechanism: the rotor turns by
/// `N q + offset` about the z axis of the constant frame `data.rotor_frame[i]` (placement times
/// the rotor's initial pose, precomputed by [`rotor_frames`]); its Jacobian column
/// `[0, 0, N, 0, 0, 0]` is constant (set in [`crate::Data::new`]) and its bias is zero.
#[inline]
fn rotor_kinematics(
    rotor: &HarmonicDriveRotor,
    body: &Body,
    data: &mut Data,
    i: usize,
    q: &DVector<f64>,
    v: Option<&DVector<f64>>,
) -> (SpatialTransform, Motion, Motion) {
    let Some(x) = rotor_transform(rotor, &data.rotor_frame[i], q[body.q_set.as_slice()[0]]) else {
        data.mechanism_fault = Some((
            i,
            MechanismError::BadInput {
                mechanism: "harmonic drive rotor",
                reason: "non-finite input".into(),
            },
        ));
        return (body.placement_x, Motion::zero(), Motion::zero());
    };
    let qd = v.map_or(0.0, |v| v[body.v_set.as_slice()[0]]);
    let rel = Motion::new(
        Vector3::new(0.0, 0.0, rotor.params().ratio * qd),
        Vector3::zeros(),
    );
    (x, rel, Motion::zero())
}

/// Per body: the constant frame of a Harmonic Drive rotor (placement times the rotor's initial
/// pose `A_pk'`, `r_0` of (3.2)) as a transform from the parent, identity for other bodies.
pub(crate) fn rotor_frames(model: &Model) -> Vec<SpatialTransform> {
    let frame = |b: &Body| match &b.joint_model {
        JointModel::Coupled {
            mechanism: Mechanism::HarmonicDrive(rotor),
            ..
        } => {
            let p = rotor.params();
            let initial = Isometry3::from_parts(Translation3::from(p.position), p.orientation);
            SpatialTransform::from_pose(&(b.placement * initial))
        }
        _ => SpatialTransform::identity(),
    };
    model.bodies.iter().map(frame).collect()
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

/// Full first forward recursion: kinematics and body forces for all bodies (Algorithm 2.2).
pub(crate) fn first_forward(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    fext: Option<&[Wrench]>,
) {
    for i in 0..model.nbodies() {
        body_kinematics(model, data, i, q, Some(v));
        body_force(model, data, i, fext);
    }
}

/// Kinematic half of the first forward recursion (Algorithm 2.2 without body forces): `C_i`,
/// world poses, `g_i`, `v_i`, `b_i` and the mechanism loop caches of all bodies except the
/// spin-invariant Harmonic Drive rotors (see [`crate::subsystem::rotor`]), whose kinematics
/// the O(n) solve does not need; [`complete_rotor_kinematics`] adds them from the stored `q, v`.
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
    for i in 0..model.nbodies() {
        if data.rotor_constant[i].is_none() {
            body_kinematics(model, data, i, q, Some(v));
        }
    }
}

/// Kinematics of the rotors skipped by [`first_forward_kinematics`], from its stored `q, v`.
pub(crate) fn complete_rotor_kinematics(model: &Model, data: &mut Data) {
    let (q, v) = (
        std::mem::take(&mut data.fd_q),
        std::mem::take(&mut data.fd_v),
    );
    for i in 0..model.nbodies() {
        if data.rotor_constant[i].is_some() {
            body_kinematics(model, data, i, &q, Some(&v));
        }
    }
    (data.fd_q, data.fd_v) = (q, v);
}

/// Transform `C` of a Harmonic Drive rotor at angle `N q + offset` about the z axis of its
/// constant frame `frame` (3.1)-(3.2); `None` for a non-finite angle.
#[inline]
pub(crate) fn rotor_transform(
    rotor: &HarmonicDriveRotor,
    frame: &SpatialTransform,
    q: f64,
) -> Option<SpatialTransform> {
    let angle = rotor.rotor_angle(q);
    if !angle.is_finite() {
        return None;
    }
    let (s, c) = sin_cos(angle);
    Some(SpatialTransform::new(
        Axis::Z.rot_tr_mul(s, c, &frame.rot),
        frame.trans,
    ))
}

/// Body forces `f_i` (2.56) of all bodies from the kinematics already in `data`.
pub(crate) fn body_forces(model: &Model, data: &mut Data, fext: Option<&[Wrench]>) {
    for i in 0..model.nbodies() {
        body_force(model, data, i, fext);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanism::harmonic_drive::HarmonicDriveParams;
    use crate::model::{BodySpec, ModelBuilder};
    use crate::spatial::RigidInertia;
    use nalgebra::UnitQuaternion;

    /// Base on a revolute joint carrying a link and its Harmonic Drive rotor.
    fn rotor_model() -> (Model, HarmonicDriveRotor) {
        let inertia = RigidInertia::new(1.0, Vector3::new(0.1, 0.0, 0.0), Matrix3::identity())
            .expect("valid inertia");
        let rotor = HarmonicDriveRotor::new(HarmonicDriveParams {
            ratio: -80.0,
            orientation: UnitQuaternion::from_euler_angles(0.3, -0.2, 1.1),
            position: Vector3::new(0.01, -0.02, 0.3),
            offset: 0.4,
        })
        .expect("valid rotor");
        let mut b = ModelBuilder::new();
        let spec = |name: &str, parent, joint, placement| BodySpec {
            name: name.into(),
            joint_name: name.into(),
            parent,
            joint,
            placement,
            inertia,
        };
        let place = Isometry3::new(Vector3::new(0.2, 0.1, -0.3), Vector3::new(0.4, 0.5, -0.6));
        let axis = Vector3::y_axis();
        let base = b
            .add_body(spec("base", None, JointModel::Revolute { axis }, place))
            .expect("base");
        let link = b
            .add_body(spec(
                "link",
                Some(base),
                JointModel::Revolute { axis },
                place,
            ))
            .expect("link");
        let joint = JointModel::Coupled {
            mechanism: Mechanism::HarmonicDrive(rotor),
            inputs: vec![link],
        };
        b.add_body(spec("rotor", Some(base), joint, place))
            .expect("rotor");
        (b.build().expect("model"), rotor)
    }

    /// The rotor fast path against the generic mechanism evaluation: pose `placement * pose`,
    /// velocity `C v_p + J qd`, bias `b = w x (J qd)`-type terms through a zero-bias mechanism.
    #[test]
    fn rotor_fast_path_matches_the_mechanism() {
        let (model, rotor) = rotor_model();
        let mut data = Data::new(&model);
        let q = DVector::from_vec(vec![0.7, -1.3]);
        let v = DVector::from_vec(vec![2.0, -0.5]);
        let a = DVector::zeros(2);
        forward_kinematics(&model, &mut data, &q, &v, &a).expect("kinematics");
        let body = &model.bodies[2];
        let m = rotor.motion(&[q[1]], &[v[1]]).expect("motion");
        let x = SpatialTransform::from_pose(&(body.placement * m.pose));
        assert!((data.x[2].rot - x.rot).amax() < 1e-12);
        assert!((data.x[2].trans - x.trans).amax() < 1e-12);
        let rel = Motion::from_vector(&(m.jacobian[0] * v[1]));
        let vel = x.apply_motion(&data.vel[0]) + rel;
        assert!((data.vel[2].ang - vel.ang).amax() < 1e-12);
        assert!((data.vel[2].lin - vel.lin).amax() < 1e-12);
        let col = joint_column(&data, 2, &body.joint, 0);
        assert_eq!(col.ang, Vector3::new(0.0, 0.0, rotor.params().ratio));
        let mut qn = q.clone();
        qn[1] = f64::NAN;
        assert!(update_placements(&model, &mut data, &qn).is_err());
    }
}
