//! Rigid (composite) inertia in world axes about the world origin, kept as mass, first moment
//! and rotational inertia: the form of (2.21)-(2.22) that sums of rigid bodies keep.

use super::{skew, sym_congruence, ArticulatedInertia, Force, Motion, RigidInertia};
use nalgebra::{Matrix3, Vector3};
use std::ops::AddAssign;

/// Inertia `[I_O, h~; h~^T, m E]` of (2.22) about a fixed origin, stored as `m`, `h = m c` and
/// the symmetric `I_O` (13 numbers instead of the 27 of an [`ArticulatedInertia`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CompositeInertia {
    /// Mass `m`.
    pub mass: f64,
    /// First moment `h = m r_OC`.
    pub h: Vector3<f64>,
    /// Rotational inertia `I_O` about the origin (symmetric).
    pub io: Matrix3<f64>,
}

impl CompositeInertia {
    /// A body's inertia in world axes about the world origin, for a body frame with rotation
    /// `rot` (body axes in world coordinates) and origin `pos` (Steiner: (2.21) at `c`).
    // Always inlined: returned through the stack, its scalar stores stalled the vector loads
    // that copied it into the CRBA's composite list (store forwarding).
    #[inline(always)]
    pub fn from_body(inertia: &RigidInertia, rot: &Matrix3<f64>, pos: &Vector3<f64>) -> Self {
        let m = inertia.mass();
        let c = rot * inertia.com() + pos;
        let h = c * m;
        // R I_C R^T = (R^T)^T I_C R^T: one triangle, contiguous column products.
        let ic = sym_congruence(&inertia.inertia_about_com(), &rot.transpose());
        let e = |i: usize, j: usize| ic[(i, j)];
        let hc = |i: usize, j: usize| h[i] * c[j];
        let d = h.dot(&c);
        let (a01, a02, a12) = (e(0, 1) - hc(0, 1), e(0, 2) - hc(0, 2), e(1, 2) - hc(1, 2));
        let io = Matrix3::new(
            e(0, 0) + d - hc(0, 0),
            a01,
            a02,
            a01,
            e(1, 1) + d - hc(1, 1),
            a12,
            a02,
            a12,
            e(2, 2) + d - hc(2, 2),
        );
        Self { mass: m, h, io }
    }

    /// `M s` for a motion `s = [w; v]`: `[I_O w + h x v; m v - h x w]` (2.22).
    #[inline]
    pub fn apply(&self, s: &Motion) -> Force {
        Force::new(
            self.io * s.ang + self.h.cross(&s.lin),
            s.lin * self.mass - self.h.cross(&s.ang),
        )
    }

    /// The same inertia as a general symmetric 6x6 block inertia.
    #[inline]
    pub fn to_articulated(&self) -> ArticulatedInertia {
        ArticulatedInertia {
            ang: self.io,
            cross: skew(&self.h),
            lin: Matrix3::from_diagonal_element(self.mass),
        }
    }
}

impl AddAssign for CompositeInertia {
    #[inline]
    fn add_assign(&mut self, o: CompositeInertia) {
        self.mass += o.mass;
        self.h += o.h;
        self.io += o.io;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spatial::SpatialTransform;
    use nalgebra::{Isometry3, Vector6};

    /// Against the dense congruence `C^T M C` (C world-to-body) and the dense product `M s`.
    #[test]
    fn from_body_matches_dense_congruence() {
        let ic = Matrix3::new(0.3, 0.01, -0.02, 0.01, 0.2, 0.03, -0.02, 0.03, 0.25);
        let body = RigidInertia::new(2.5, Vector3::new(0.1, -0.2, 0.05), ic).expect("valid");
        let pose = Isometry3::new(Vector3::new(0.3, -0.1, 0.7), Vector3::new(0.9, -0.4, 1.2));
        let c = SpatialTransform::from_pose(&pose).to_matrix();
        let dense = c.transpose() * body.to_matrix() * c;
        let rot = pose.rotation.to_rotation_matrix().into_inner();
        let k = CompositeInertia::from_body(&body, &rot, &pose.translation.vector);
        assert!((k.to_articulated().to_matrix() - dense).amax() < 1e-13);
        let s = Motion::from_vector(&Vector6::new(0.3, -1.0, 0.2, 0.5, 0.1, -0.7));
        let f = k.apply(&s).to_vector();
        assert!((f - dense * s.to_vector()).amax() < 1e-13);
    }
}
