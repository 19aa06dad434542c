//! Symmetric 6x6 (articulated or composite) inertias `[A B; B^T D]` kept as 3x3 blocks.
//!
//! The congruence `C^T I C` of (2.69) is split into the rotation of the blocks
//! (`congruence`) and the shift by the joint offset (`shift`).

mod congruence;
mod shift;

pub use congruence::sym_congruence;

use super::{Force, Motion, SpatialTransform};
use congruence::{axis_congruence, sym_axis_congruence, PlaneRotation};
use nalgebra::{Matrix3, Matrix6};
use shift::{shift_into, Minus};
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

    /// `self = o` block by block: the whole-struct copy (216 bytes) compiled to a `memcpy`
    /// call per body in the O(n) first pass; three 72-byte copies stay inline.
    #[inline(always)]
    pub(crate) fn set_from(&mut self, o: &Self) {
        self.ang = o.ang;
        self.cross = o.cross;
        self.lin = o.lin;
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
    /// Kept out of line: inlined into the O(n) backward loop it cost more (spills; measured).
    #[inline(never)]
    pub fn sub_outer(&mut self, u: &Force, w: f64) {
        let [ang, cross, lin] = outer(u, w);
        self.ang -= ang;
        self.cross -= cross;
        self.lin -= lin;
    }

    /// Congruence transform `C^T I C` into the parent frame (the `C_j^T K_j` term of (2.69)).
    ///
    /// With `C = [A 0; 0 A] [E 0; -r~ E]`: rotate the three blocks (`A^T S A`, symmetric
    /// blocks computed on one triangle), then shift by `r` with skew products (18 mults each).
    pub fn tr_transform(&self, x: &SpatialTransform) -> ArticulatedInertia {
        let mut out = ArticulatedInertia::zero();
        self.tr_transform_into::<false>(x, (), &mut out);
        out
    }

    /// [`Self::tr_transform`] less `minus` written to (`ADD = false`) or added to
    /// (`ADD = true`) `out`.
    #[inline]
    fn tr_transform_into<const ADD: bool>(
        &self,
        x: &SpatialTransform,
        minus: impl Minus,
        out: &mut Self,
    ) {
        let a = &x.rot;
        let ang = sym_congruence(&self.ang, a);
        let lin = sym_congruence(&self.lin, a);
        let cross = a.tr_mul(&(self.cross * a));
        shift_into::<ADD>(&ang, &cross, lin, &x.trans, minus, out);
    }

    /// `out += C^T I C` ([`Self::tr_transform`] accumulated in place, the backward-pass sum
    /// (2.69) without a temporary inertia) when `x.rot` is a rotation about coordinate axis
    /// `k` (0, 1, 2): a revolute joint about a body axis whose placement is a pure
    /// translation. Each block rotates in the plane normal to the axis, its plane part by the
    /// double angle (40 multiplications for the three blocks, halvings included, instead of
    /// 144 for a general rotation).
    pub(crate) fn add_tr_transform_axis_to(&self, k: usize, x: &SpatialTransform, out: &mut Self) {
        self.tr_transform_axis_into::<true>(k, x, (), out);
    }

    /// `out += C^T I C - w b b^T`: the congruence of (2.69) for a rotation about coordinate
    /// axis `axis` ([`Self::add_tr_transform_axis_to`]) or a general one (`None`), with the
    /// rank-one `- B_S D^-1 B_S^T` of a one-DoF step (2.72) subtracted on the way, so that
    /// `out` is read and written once (instead of again by [`Self::sub_outer`]).
    pub(crate) fn add_tr_transform_sub_outer_to(
        &self,
        axis: Option<usize>,
        x: &SpatialTransform,
        (b, w): (&Force, f64),
        out: &mut Self,
    ) {
        match axis {
            Some(k) => self.tr_transform_axis_into::<true>(k, x, (b, w), out),
            None => self.tr_transform_into::<true>(x, (b, w), out),
        }
    }

    /// The axis congruence of [`Self::add_tr_transform_axis_to`] less `minus` written to
    /// (`ADD = false`) or added to (`ADD = true`) `out`.
    #[inline]
    fn tr_transform_axis_into<const ADD: bool>(
        &self,
        k: usize,
        x: &SpatialTransform,
        minus: impl Minus,
        out: &mut Self,
    ) {
        match k {
            0 => self.tr_transform_plane::<0, ADD>(x, minus, out),
            1 => self.tr_transform_plane::<1, ADD>(x, minus, out),
            _ => self.tr_transform_plane::<2, ADD>(x, minus, out),
        }
    }

    /// [`Self::tr_transform_axis_into`] for the axis `K` known at compile time (constant indices).
    #[inline]
    fn tr_transform_plane<const K: usize, const ADD: bool>(
        &self,
        x: &SpatialTransform,
        minus: impl Minus,
        out: &mut Self,
    ) {
        let r = PlaneRotation::new::<K>(&x.rot);
        let ang = sym_axis_congruence::<K>(&self.ang, &r);
        let lin = sym_axis_congruence::<K>(&self.lin, &r);
        let cross = axis_congruence::<K>(&self.cross, &r);
        shift_into::<ADD>(&ang, &cross, lin, &x.trans, minus, out);
    }

    /// `out += C^T I C` without a temporary inertia (the backward-pass accumulation (2.69)).
    #[inline]
    pub fn add_tr_transform_to(&self, x: &SpatialTransform, out: &mut ArticulatedInertia) {
        self.tr_transform_into::<true>(x, (), out);
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

/// The blocks `[ang, cross, lin]` of `w u u^T` (`u` a force, so `ang = w u_ang u_ang^T`).
#[inline(always)]
fn outer(u: &Force, w: f64) -> [Matrix3<f64>; 3] {
    let (ua, ul) = (u.ang * w, u.lin * w);
    [
        ua * u.ang.transpose(),
        ua * u.lin.transpose(),
        ul * u.lin.transpose(),
    ]
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

#[cfg(test)]
mod tests;
