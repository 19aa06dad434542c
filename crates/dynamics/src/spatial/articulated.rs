//! Symmetric 6x6 (articulated or composite) inertias `[A B; B^T D]` kept as 3x3 blocks.

use super::{skew, Force, Motion, SpatialTransform};
use nalgebra::{Matrix3, Matrix6};
use std::ops::{Add, AddAssign};

/// Symmetric 6x6 inertia `[ang, cross; cross^T, lin]` acting on motions, giving forces.
///
/// Used for the projected mass matrices `M-bar_i` of (2.69) and the composite inertias of CRBA.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArticulatedInertia {
    /// Upper-left block (symmetric): moment from angular motion.
    pub ang: Matrix3<f64>,
    /// Upper-right block: moment from linear motion.
    pub cross: Matrix3<f64>,
    /// Lower-right block (symmetric): force from linear motion.
    pub lin: Matrix3<f64>,
}

impl Default for ArticulatedInertia {
    fn default() -> Self {
        Self::zero()
    }
}

impl ArticulatedInertia {
    /// The zero inertia.
    #[inline]
    pub fn zero() -> Self {
        Self {
            ang: Matrix3::zeros(),
            cross: Matrix3::zeros(),
            lin: Matrix3::zeros(),
        }
    }

    /// `I m` for a motion vector.
    #[inline]
    pub fn apply(&self, m: &Motion) -> Force {
        Force::new(
            self.ang * m.ang + self.cross * m.lin,
            self.cross.tr_mul(&m.ang) + self.lin * m.lin,
        )
    }

    /// `self -= u u^T * w` (the rank-one update `M-bar - U D^-1 U^T` of the backward pass).
    #[inline]
    pub fn sub_outer(&mut self, u: &Force, w: f64) {
        let ua = u.ang * w;
        let ul = u.lin * w;
        self.ang -= ua * u.ang.transpose();
        self.cross -= ua * u.lin.transpose();
        self.lin -= ul * u.lin.transpose();
    }

    /// Congruence transform `C^T I C` into the parent frame (the `C_j^T K_j` term of (2.69)).
    pub fn tr_transform(&self, x: &SpatialTransform) -> ArticulatedInertia {
        let a = &x.rot;
        let ang = a.tr_mul(&(self.ang * a));
        let cross = a.tr_mul(&(self.cross * a));
        let lin = a.tr_mul(&(self.lin * a));
        let r = skew(&x.trans);
        let br = cross * r;
        let dr = lin * r;
        ArticulatedInertia {
            ang: ang - br - br.transpose() - r * dr,
            cross: cross + r * lin,
            lin,
        }
    }

    /// Dense 6x6 matrix (for tests, debugging and the 6-DoF joint path).
    pub fn to_matrix(&self) -> Matrix6<f64> {
        let mut m = Matrix6::zeros();
        m.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.ang);
        m.fixed_view_mut::<3, 3>(0, 3).copy_from(&self.cross);
        m.fixed_view_mut::<3, 3>(3, 0)
            .copy_from(&self.cross.transpose());
        m.fixed_view_mut::<3, 3>(3, 3).copy_from(&self.lin);
        m
    }

    /// Inertia from a dense symmetric 6x6 matrix (upper blocks are used).
    pub fn from_matrix(m: &Matrix6<f64>) -> Self {
        Self {
            ang: m.fixed_view::<3, 3>(0, 0).into(),
            cross: m.fixed_view::<3, 3>(0, 3).into(),
            lin: m.fixed_view::<3, 3>(3, 3).into(),
        }
    }
}

impl Add for ArticulatedInertia {
    type Output = ArticulatedInertia;
    #[inline]
    fn add(self, o: ArticulatedInertia) -> ArticulatedInertia {
        ArticulatedInertia {
            ang: self.ang + o.ang,
            cross: self.cross + o.cross,
            lin: self.lin + o.lin,
        }
    }
}

impl AddAssign for ArticulatedInertia {
    #[inline]
    fn add_assign(&mut self, o: ArticulatedInertia) {
        self.ang += o.ang;
        self.cross += o.cross;
        self.lin += o.lin;
    }
}
