//! Spatial transformation `C_i = C_kp` of (2.36), applied without forming 6x6 matrices.

use super::{skew, Force, Motion};
use nalgebra::{Isometry3, Matrix3, Matrix6, Rotation3, Translation3, UnitQuaternion, Vector3};

/// Spatial transform `C_kp = [A_kp, 0; -A_kp r~_PO, A_kp]` (2.36) from parent `p` to child `k`.
///
/// `rot` is `A_kp` (parent coordinates to child coordinates) and `trans` is `r_PO`, the child
/// origin relative to the parent origin in parent coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpatialTransform {
    /// Rotation `A_kp` mapping parent coordinates to child coordinates.
    pub rot: Matrix3<f64>,
    /// Vector `r_PO` from the parent origin to the child origin, in parent coordinates.
    pub trans: Vector3<f64>,
}

impl Default for SpatialTransform {
    fn default() -> Self {
        Self::identity()
    }
}

impl SpatialTransform {
    /// Transform from `A_kp` and `r_PO` (parent coordinates).
    #[inline]
    pub fn new(rot: Matrix3<f64>, trans: Vector3<f64>) -> Self {
        Self { rot, trans }
    }

    /// The identity transform (2.88).
    #[inline]
    pub fn identity() -> Self {
        Self::new(Matrix3::identity(), Vector3::zeros())
    }

    /// Transform for a child frame whose pose in the parent frame is `pose` (`A_kp = R^T`).
    pub fn from_pose(pose: &Isometry3<f64>) -> Self {
        Self::new(
            pose.rotation.to_rotation_matrix().matrix().transpose(),
            pose.translation.vector,
        )
    }

    /// Pose of the child frame in the parent frame (inverse of [`Self::from_pose`]).
    pub fn to_pose(&self) -> Isometry3<f64> {
        let r = Rotation3::from_matrix_unchecked(self.rot.transpose());
        Isometry3::from_parts(
            Translation3::from(self.trans),
            UnitQuaternion::from_rotation_matrix(&r),
        )
    }

    /// `C m`: parent-frame motion to child frame, `[A w; A (v + w x r)]`.
    #[inline]
    pub fn apply_motion(&self, m: &Motion) -> Motion {
        Motion::new(
            self.rot * m.ang,
            self.rot * (m.lin + m.ang.cross(&self.trans)),
        )
    }

    /// `C^-1 m`: child-frame motion to parent frame.
    #[inline]
    pub fn inv_apply_motion(&self, m: &Motion) -> Motion {
        let ang = self.rot.tr_mul(&m.ang);
        Motion::new(ang, self.rot.tr_mul(&m.lin) + self.trans.cross(&ang))
    }

    /// `C^T f`: child-frame force to parent frame, `[A^T n + r x A^T f; A^T f]`.
    #[inline]
    pub fn tr_apply_force(&self, f: &Force) -> Force {
        let lin = self.rot.tr_mul(&f.lin);
        Force::new(self.rot.tr_mul(&f.ang) + self.trans.cross(&lin), lin)
    }

    /// `C^-T f`: parent-frame force to child frame.
    #[inline]
    pub fn inv_tr_apply_force(&self, f: &Force) -> Force {
        Force::new(
            self.rot * (f.ang - self.trans.cross(&f.lin)),
            self.rot * f.lin,
        )
    }

    /// Composition `C_kq = C_kp C_pq` where `self = C_kp` and `inner = C_pq`.
    #[inline]
    pub fn compose(&self, inner: &SpatialTransform) -> SpatialTransform {
        SpatialTransform::new(
            self.rot * inner.rot,
            inner.trans + inner.rot.tr_mul(&self.trans),
        )
    }

    /// Dense 6x6 matrix of (2.36), for tests and debugging only.
    pub fn to_matrix(&self) -> Matrix6<f64> {
        let mut c = Matrix6::zeros();
        c.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.rot);
        c.fixed_view_mut::<3, 3>(3, 3).copy_from(&self.rot);
        c.fixed_view_mut::<3, 3>(3, 0)
            .copy_from(&(-self.rot * skew(&self.trans)));
        c
    }
}
