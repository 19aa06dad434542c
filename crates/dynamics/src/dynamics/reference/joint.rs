//! Relative joint kinematics (2.27), (2.35)-(2.49), (3.1) and the closed-form mechanisms of
//! chapter 3: for body `i`, the pose of its frame `k` in the parent frame `p`, the relative
//! Jacobian `J_i` and the relative bias `Jdot_i qdot_i`, written out per joint type.
//!
//! Reading of (2.35): `J_i` maps `qdot_i` to the relative twist `[omega_rel; v_rel]` in the
//! body's own frame `k` (as (2.33) needs it), and `Jdot_i qdot_i` is the relative acceleration
//! at `qddot_i = 0` as seen from the parent-fixed frame `k'` (the thesis: "denoted with respect
//! to FoR k' which is fixed to the parent"), again in `k` coordinates. For a Jacobian whose
//! columns move with `k` (mechanisms, the quaternion joint) this is the component-wise
//! derivative in `k` plus `[0; omega_rel x v_rel]`: `d/dt (A_k'k v_rel) = A_k'k (vdot_rel +
//! omega_rel x v_rel)`.

use crate::mechanism::{Coupling, MAX_COUPLED};
use crate::model::{Body, JointModel};
use crate::DynamicsError;
use nalgebra::{Matrix3, Matrix6xX, Quaternion, Rotation3, Unit, UnitQuaternion, Vector3, Vector6};

/// Relative kinematics of one joint (frame `k` relative to the parent frame `p`).
#[derive(Clone, Debug)]
pub(super) struct Relative {
    /// `A_pk`: the axes of `k` in parent coordinates (the transpose of `A_kp` of (2.36)).
    pub(super) rot_pk: Matrix3<f64>,
    /// `r_PO`: the origin of `k` relative to the parent origin, parent coordinates (2.36).
    pub(super) r_po: Vector3<f64>,
    /// `J_i` (2.35), `k` coordinates, one column per entry of the body's index set (2.26).
    pub(super) jacobian: Matrix6xX<f64>,
    /// `Jdot_i qdot_i` (2.35), `k` coordinates (see the module doc).
    pub(super) jdot_qdot: Vector6<f64>,
}

/// The relative kinematics of `body` at `(q, v)`, the joint placement `A_pk'`, `r_PK'`
/// (Fig. 2.9) composed with the joint's own motion of `k` relative to `k'`.
pub(super) fn relative(
    body: &Body,
    index: usize,
    q: &[f64],
    v: &[f64],
) -> Result<Relative, DynamicsError> {
    let qs: Vec<f64> = body.q_set().as_slice().iter().map(|&k| q[k]).collect();
    let vs: Vec<f64> = body.v_set().as_slice().iter().map(|&k| v[k]).collect();
    let (rot, pos, jacobian, jdot_qdot) = match body.joint() {
        JointModel::Revolute { axis } => revolute(axis, 1.0, qs[0]),
        JointModel::GearedRotor { axis, ratio, .. } => revolute(axis, *ratio, qs[0]),
        JointModel::Prismatic { axis } => prismatic(axis, qs[0]),
        JointModel::Fixed => (
            Matrix3::identity(),
            Vector3::zeros(),
            Matrix6xX::zeros(0),
            Vector6::zeros(),
        ),
        JointModel::FreeEulerZxz => euler_zxz(&qs, &vs),
        JointModel::FreeQuaternion => quaternion(&qs, &vs),
        JointModel::Coupled { mechanism, .. } => coupled(mechanism, index, &qs, &vs)?,
    };
    let placement = body.placement();
    let rot_pkp = placement.rotation.to_rotation_matrix().into_inner();
    Ok(Relative {
        rot_pk: rot_pkp * rot,
        r_po: placement.translation.vector + rot_pkp * pos,
        jacobian,
        jdot_qdot,
    })
}

/// `(A_k'k, r_K'O in k', J, Jdot qdot)` of one joint.
type JointMotion = (Matrix3<f64>, Vector3<f64>, Matrix6xX<f64>, Vector6<f64>);

/// Revolute joint about `axis` (2.45)-(2.46), or a geared rotor turning `ratio` times its
/// driver's angle (3.1): `J = [ratio axis; 0]` constant, so `Jdot = 0`.
fn revolute(axis: &Unit<Vector3<f64>>, ratio: f64, q: f64) -> JointMotion {
    let rot = Rotation3::from_axis_angle(axis, ratio * q).into_inner();
    let mut j = Matrix6xX::zeros(1);
    j.fixed_view_mut::<3, 1>(0, 0)
        .copy_from(&(axis.into_inner() * ratio));
    (rot, Vector3::zeros(), j, Vector6::zeros())
}

/// Prismatic joint along `axis` (2.47)-(2.48): `J = [0; axis]`, `Jdot = 0`; its Coriolis term
/// `omega_p x 2 J_T qdot` is part of `b_i` (2.49).
fn prismatic(axis: &Unit<Vector3<f64>>, q: f64) -> JointMotion {
    let mut j = Matrix6xX::zeros(1);
    j.fixed_view_mut::<3, 1>(3, 0).copy_from(axis);
    (
        Matrix3::identity(),
        axis.into_inner() * q,
        j,
        Vector6::zeros(),
    )
}

/// Free joint `q = [x, y, z, phi, theta, psi]` with `A_k'k = Rz(phi) Rx(theta) Rz(psi)` and
/// `v = qdot` (2.38)-(2.43). The third row of `J_R` (2.39) is `[c2, 0, 1]` (the extracted text
/// reads `s2`; `c2` follows from `omega = Rz(psi)^T Rx(theta)^T e_z phidot + ...` and agrees
/// with (2.42)). The translation's Jacobian `A_kk' E` rotates with `k`, so its derivative seen
/// from `k'` vanishes: `Jdot qdot = [Jdot_R qdot_R; 0]` (2.42)-(2.43).
fn euler_zxz(q: &[f64], v: &[f64]) -> JointMotion {
    let (s1, c1) = q[3].sin_cos();
    let (s2, c2) = q[4].sin_cos();
    let (s3, c3) = q[5].sin_cos();
    let rz = |s: f64, c: f64| Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0);
    let rx = Matrix3::new(1.0, 0.0, 0.0, 0.0, c2, -s2, 0.0, s2, c2);
    let rot = rz(s1, c1) * rx * rz(s3, c3);
    let jr = Matrix3::new(s2 * s3, c3, 0.0, s2 * c3, -s3, 0.0, c2, 0.0, 1.0);
    let (d1, d2, d3) = (v[3], v[4], v[5]);
    let jdot_r = Matrix3::new(
        d2 * c2 * s3 + d3 * s2 * c3,
        -d3 * s3,
        0.0,
        d2 * c2 * c3 - d3 * s2 * s3,
        -d3 * c3,
        0.0,
        -d2 * s2,
        0.0,
        0.0,
    );
    let mut j = Matrix6xX::zeros(6);
    j.fixed_view_mut::<3, 3>(0, 3).copy_from(&jr);
    j.fixed_view_mut::<3, 3>(3, 0).copy_from(&rot.transpose());
    let mut b = Vector6::zeros();
    b.fixed_rows_mut::<3>(0)
        .copy_from(&(jdot_r * Vector3::new(d1, d2, d3)));
    (rot, Vector3::new(q[0], q[1], q[2]), j, b)
}

/// Free joint `q = [x, y, z, qx, qy, qz, qw]`, `v = [v_rel; omega_rel]` in `k` coordinates (the
/// project's redundant alternative to (2.38), footnote 7): `J` is the constant permutation to
/// `[omega; v]`, and `v_rel` turning with `k` gives `Jdot qdot = [0; omega_rel x v_rel]`. Here
/// `qddot` of the joint means `vdot`.
fn quaternion(q: &[f64], v: &[f64]) -> JointMotion {
    let quat = UnitQuaternion::new_normalize(Quaternion::new(q[6], q[3], q[4], q[5]));
    let mut j = Matrix6xX::zeros(6);
    j.fixed_view_mut::<3, 3>(0, 3).fill_with_identity();
    j.fixed_view_mut::<3, 3>(3, 0).fill_with_identity();
    let lin = Vector3::new(v[0], v[1], v[2]);
    let ang = Vector3::new(v[3], v[4], v[5]);
    let mut b = Vector6::zeros();
    b.fixed_rows_mut::<3>(3).copy_from(&ang.cross(&lin));
    let rot = quat.to_rotation_matrix().into_inner();
    (rot, Vector3::new(q[0], q[1], q[2]), j, b)
}

/// Coupled part of a closed-form mechanism (ch. 3): pose, `J` and the component-wise `Jdot
/// qdot` from [`Coupling::motion`], plus `[0; omega_rel x v_rel]` (module doc).
fn coupled(
    mechanism: &impl Coupling,
    body: usize,
    q: &[f64],
    v: &[f64],
) -> Result<JointMotion, DynamicsError> {
    let m = mechanism
        .motion(q, v)
        .map_err(|source| DynamicsError::Mechanism { body, source })?;
    let n = q.len().min(MAX_COUPLED);
    let mut j = Matrix6xX::zeros(n);
    for c in 0..n {
        j.set_column(c, &m.jacobian[c]);
    }
    let twist: Vector6<f64> = &j * nalgebra::DVector::from_column_slice(&v[..n]);
    let w = Vector3::new(twist[0], twist[1], twist[2]);
    let u = Vector3::new(twist[3], twist[4], twist[5]);
    let mut b = m.bias;
    let turning = w.cross(&u);
    for r in 0..3 {
        b[3 + r] += turning[r];
    }
    let rot = m.pose.rotation.to_rotation_matrix().into_inner();
    Ok((rot, m.pose.translation.vector, j, b))
}
