//! Joint models and their relative kinematics `A_kp`, `r_PO`, `J_i`, `Jdot_i qdot` (2.33)-(2.49).
//!
//! Every joint maps the coordinates of its *index set* (2.26) to the pose of the child frame
//! relative to the joint frame (which the placement fixes in the parent body frame, the frame
//! `k'` of Fig. 2.9). The index set of a geared rotor is its driver's, i.e. shared.

use super::coupling::Mechanism;
use crate::spatial::{Axis, JointAxis, Motion, SubspaceKind};
use crate::BodyId;
use nalgebra::{Matrix3, Matrix6, Unit, UnitQuaternion, Vector3};

/// Joint connecting a body to its parent (public model description).
// Mechanisms are stored inline (no Box) so coupled-part kinematics read them without a
// pointer chase; models hold one joint per body, so the size difference is harmless.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum JointModel {
    /// Rotation about `axis` (joint frame) through the joint frame origin, (2.45)-(2.46).
    Revolute {
        /// Rotation axis in the joint frame.
        axis: Unit<Vector3<f64>>,
    },
    /// Translation along `axis` (joint frame), (2.47)-(2.49).
    Prismatic {
        /// Translation axis in the joint frame.
        axis: Unit<Vector3<f64>>,
    },
    /// Rigid attachment, `nq = nv = 0`.
    Fixed,
    /// Free joint `q = [x, y, z, phi, theta, psi]`, `R = Rz(phi) Rx(theta) Rz(psi)`, `v = qdot`
    /// (2.38)-(2.44); singular at `sin(theta) = 0`.
    FreeEulerZxz,
    /// Free joint `q = [x, y, z, qx, qy, qz, qw]`, `v = [linear; angular]` in body coordinates.
    FreeQuaternion,
    /// Harmonic-Drive rotor (3.1)-(3.2): rotates about `axis` by `ratio * q_driver`; no own
    /// coordinates, shares the driver joint's index.
    GearedRotor {
        /// Rotation axis in the joint frame.
        axis: Unit<Vector3<f64>>,
        /// Gear ratio `N`.
        ratio: f64,
        /// Body whose (one-DoF) joint coordinate drives the rotor.
        driver: BodyId,
    },
    /// Coupled part: relative motion `mechanism(q_in)` where `q_in` are the
    /// joint coordinates of the one-DoF bodies `inputs`; no own coordinates (its index set
    /// (2.26) is the inputs'), so it ends up in a sub-system (2.9). The geared rotor is the
    /// linear one-input case.
    Coupled {
        /// Closed-form mechanism giving pose, Jacobian and bias relative to the joint frame.
        mechanism: Mechanism,
        /// Input bodies (revolute or prismatic), in the mechanism's input order.
        inputs: Vec<BodyId>,
    },
}

impl JointModel {
    /// Number of position coordinates the joint owns.
    pub fn nq(&self) -> usize {
        match self {
            JointModel::Revolute { .. } | JointModel::Prismatic { .. } => 1,
            JointModel::Fixed | JointModel::GearedRotor { .. } | JointModel::Coupled { .. } => 0,
            JointModel::FreeEulerZxz => 6,
            JointModel::FreeQuaternion => 7,
        }
    }

    /// Number of velocity coordinates the joint owns.
    pub fn nv(&self) -> usize {
        match self {
            JointModel::Revolute { .. } | JointModel::Prismatic { .. } => 1,
            JointModel::Fixed | JointModel::GearedRotor { .. } | JointModel::Coupled { .. } => 0,
            JointModel::FreeEulerZxz | JointModel::FreeQuaternion => 6,
        }
    }
}

/// Compiled joint used in the recursions (axes classified for zero pruning).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Joint {
    /// Revolute joint: `S = [axis; 0]`.
    Revolute(JointAxis),
    /// Prismatic joint: `S = [0; axis]`.
    Prismatic(JointAxis),
    /// Rigid attachment.
    Fixed,
    /// Free joint with Euler ZXZ angles.
    EulerZxz,
    /// Free joint with a unit quaternion.
    Quaternion,
    /// Geared rotor: `S = [N axis; 0]` on the driver's coordinate.
    Rotor(JointAxis),
    /// Coupled part; the mechanism lives in the body's [`JointModel::Coupled`].
    Coupled,
}

impl Joint {
    /// Compiles a joint model whose axis has already been validated.
    pub(crate) fn compile(model: &JointModel) -> Self {
        let one = |axis: &Unit<Vector3<f64>>, kind, scale| JointAxis {
            axis: Axis::from_unit(axis),
            kind,
            scale,
        };
        match model {
            JointModel::Revolute { axis } => Joint::Revolute(one(axis, SubspaceKind::Angular, 1.0)),
            JointModel::Prismatic { axis } => {
                Joint::Prismatic(one(axis, SubspaceKind::Linear, 1.0))
            }
            JointModel::Fixed => Joint::Fixed,
            JointModel::FreeEulerZxz => Joint::EulerZxz,
            JointModel::FreeQuaternion => Joint::Quaternion,
            JointModel::GearedRotor { axis, ratio, .. } => {
                Joint::Rotor(one(axis, SubspaceKind::Angular, *ratio))
            }
            JointModel::Coupled { .. } => Joint::Coupled,
        }
    }
}

/// Relative rotation `Rz(phi) Rx(theta) Rz(psi)` of the Euler-ZXZ free joint (C.2).
pub(crate) fn euler_zxz_rotation(phi: f64, theta: f64, psi: f64) -> Matrix3<f64> {
    let (s1, c1) = phi.sin_cos();
    let (s2, c2) = theta.sin_cos();
    let (s3, c3) = psi.sin_cos();
    Axis::Z.rotation(s1, c1) * Axis::X.rotation(s2, c2) * Axis::Z.rotation(s3, c3)
}

/// Body-frame angular-velocity Jacobian `J_R` of the Euler-ZXZ joint (2.39, third row `c2`).
pub(crate) fn euler_zxz_jr(theta: f64, psi: f64) -> Matrix3<f64> {
    let (s2, c2) = theta.sin_cos();
    let (s3, c3) = psi.sin_cos();
    Matrix3::new(s2 * s3, c3, 0.0, s2 * c3, -s3, 0.0, c2, 0.0, 1.0)
}

/// `Jdot_R qdot_R` of the Euler-ZXZ joint (2.42).
pub(crate) fn euler_zxz_jr_dot_qd(theta: f64, psi: f64, qd: &Vector3<f64>) -> Vector3<f64> {
    let (s2, c2) = theta.sin_cos();
    let (s3, c3) = psi.sin_cos();
    let (d1, d2, d3) = (qd.x, qd.y, qd.z);
    Vector3::new(
        (d2 * c2 * s3 + d3 * s2 * c3) * d1 - d3 * s3 * d2,
        (d2 * c2 * c3 - d3 * s2 * s3) * d1 - d3 * c3 * d2,
        -d2 * s2 * d1,
    )
}

/// Full 6x6 relative Jacobian of the Euler-ZXZ joint in child coordinates, rows `[ang; lin]`,
/// columns `[x, y, z, phi, theta, psi]`: `[0, J_R; R_q^T, 0]` (2.38).
pub(crate) fn euler_zxz_jacobian(rot_q: &Matrix3<f64>, theta: f64, psi: f64) -> Matrix6<f64> {
    let mut s = Matrix6::zeros();
    s.fixed_view_mut::<3, 3>(0, 3)
        .copy_from(&euler_zxz_jr(theta, psi));
    s.fixed_view_mut::<3, 3>(3, 0).copy_from(&rot_q.transpose());
    s
}

/// Constant relative Jacobian of the quaternion free joint, `v = [lin; ang]` to `[ang; lin]`.
pub(crate) fn quaternion_jacobian() -> Matrix6<f64> {
    let mut s = Matrix6::zeros();
    s.fixed_view_mut::<3, 3>(0, 3).fill_with_identity();
    s.fixed_view_mut::<3, 3>(3, 0).fill_with_identity();
    s
}

/// Rotation of a (not necessarily normalised) quaternion `[qx, qy, qz, qw]`; `None` if ~zero.
pub(crate) fn quaternion_rotation(x: f64, y: f64, z: f64, w: f64) -> Option<Matrix3<f64>> {
    let n2 = x * x + y * y + z * z + w * w;
    if n2.is_nan() || n2 <= 1e-24 {
        return None;
    }
    let q = UnitQuaternion::new_normalize(nalgebra::Quaternion::new(w, x, y, z));
    Some(q.to_rotation_matrix().into_inner())
}

/// Relative joint motion `J qdot` for a 6-DoF joint from its Jacobian.
#[inline]
pub(crate) fn six_dof_motion(s: &Matrix6<f64>, qd: &nalgebra::Vector6<f64>) -> Motion {
    Motion::from_vector(&(s * qd))
}
