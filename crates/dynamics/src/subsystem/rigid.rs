//! Congruence `C^T M C` of a rigid member (the `C-hat^T M-hat C-hat` term of (2.76) for a
//! member without children outside its sub-system, whose `M-hat_j` is still the rigid-body
//! `M_j` of (2.22)), shared by the generic, link-with-rotors and rotor-constant steps, and
//! the compact sum of such inertias the loop sub-systems accumulate `K_S` in.

use crate::spatial::{
    sym_congruence, ArticulatedInertia, Force, Motion, RigidInertia, SpatialTransform,
};
use nalgebra::{Matrix3, Vector3};

/// `out += C^T M C` for a rigid-body inertia `M` (the `C-hat^T M-hat C-hat` term of (2.76) for
/// a member without children outside, whose `M-hat_j` is still `M_j`), see
/// [`RigidSum::congruence`].
#[inline]
pub(crate) fn add_rigid_congruence(
    inertia: &RigidInertia,
    x: &SpatialTransform,
    out: &mut ArticulatedInertia,
) {
    RigidSum::congruence(inertia, x).add_to(out);
}

/// A rigid-body inertia (2.22) or a sum of them in one frame, compact: mass `m`, first moment
/// `h` and inertia `I_O` about the origin (13 numbers to add per body instead of 27).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RigidSum {
    /// Mass `m`.
    m: f64,
    /// First moment `h = m c`.
    h: Vector3<f64>,
    /// `I_O = I_c + m (|c|^2 E - c c^T)`.
    io: Matrix3<f64>,
}

impl RigidSum {
    /// The empty sum.
    #[inline]
    pub(crate) fn zero() -> Self {
        Self {
            m: 0.0,
            h: Vector3::zeros(),
            io: Matrix3::zeros(),
        }
    }

    /// A body of mass `m` with CoM `c` and inertia `ic` about it, both in this frame.
    #[inline]
    pub(crate) fn at(m: f64, c: &Vector3<f64>, ic: &Matrix3<f64>) -> Self {
        let (mc, mut io) = (c * m, *ic);
        let diag = mc.dot(c);
        for i in 0..3 {
            io[(i, i)] += diag - mc[i] * c[i];
            for k in i + 1..3 {
                let o = mc[i] * c[k];
                io[(i, k)] -= o;
                io[(k, i)] -= o;
            }
        }
        Self { m, h: mc, io }
    }

    /// `C^T M C` of a rigid-body inertia `M`: in parent axes the CoM is `c = A^T c_j + r` and
    /// the inertia about it `I_c' = A^T I_c A`, formed by [`axisymmetric_inertia`] when it
    /// applies.
    #[inline]
    pub(crate) fn congruence(inertia: &RigidInertia, x: &SpatialTransform) -> Self {
        let (c, ic) = (inertia.com(), inertia.inertia_about_com());
        let (c, ang) = match axisymmetric_inertia(&c, &ic, &x.rot) {
            Some((z, ang)) => (z * c.z + x.trans, ang),
            None => (x.rot.tr_mul(&c) + x.trans, sym_congruence(&ic, &x.rot)),
        };
        Self::at(inertia.mass(), &c, &ang)
    }

    /// `out += [I_O, h~; -h~, m E]` (only the nonzero entries of `h~` and `m E`).
    #[inline]
    pub(crate) fn add_to(&self, out: &mut ArticulatedInertia) {
        out.ang += self.io;
        for (i, k, h) in [(1, 2, self.h.x), (2, 0, self.h.y), (0, 1, self.h.z)] {
            out.cross[(i, k)] -= h;
            out.cross[(k, i)] += h;
            out.lin[(i, i)] += self.m;
        }
    }
}

impl std::ops::AddAssign for RigidSum {
    #[inline]
    fn add_assign(&mut self, rhs: Self) {
        self.m += rhs.m;
        self.h += rhs.h;
        self.io += rhs.io;
    }
}

/// True if a body with CoM `c` and inertia `ic` about it (own frame) is axisymmetric about its
/// z axis: `c` on the axis and `I_c = diag(a, a, b)` exactly (e.g. a cylinder- or square-box-
/// shaped screw, nut, rod or rotor). Exact comparisons: a near-symmetric body takes the
/// general path.
#[inline]
pub(crate) fn is_axisymmetric(c: &Vector3<f64>, ic: &Matrix3<f64>) -> bool {
    let off = [c.x, c.y, ic[(0, 1)], ic[(0, 2)], ic[(1, 2)]];
    off.iter().all(|&v| v == 0.0) && ic[(0, 0)] == ic[(1, 1)]
}

/// For an axisymmetric body ([`is_axisymmetric`]): the axis `z = A^T e_z` in parent
/// coordinates and `A^T I_c A = a E + (b - a) z z^T` (12 instead of 75 flops). `None` for any
/// other inertia.
#[inline]
fn axisymmetric_inertia(
    c: &Vector3<f64>,
    ic: &Matrix3<f64>,
    rot: &Matrix3<f64>,
) -> Option<(Vector3<f64>, Matrix3<f64>)> {
    if !is_axisymmetric(c, ic) {
        return None;
    }
    let (a, z) = (ic[(0, 0)], rot.row(2).transpose());
    let bz = z * (ic[(2, 2)] - a);
    let e = |i: usize, j: usize| bz[i] * z[j];
    let (m01, m02, m12) = (e(0, 1), e(0, 2), e(1, 2));
    let ang = Matrix3::new(
        a + e(0, 0),
        m01,
        m02,
        m01,
        a + e(1, 1),
        m12,
        m02,
        m12,
        a + e(2, 2),
    );
    Some((z, ang))
}

/// Rigid-body inertia (2.22) of an axisymmetric body ([`is_axisymmetric`]), whose first moment
/// is `h = (0, 0, h_z)` and inertia about the origin `I_O = diag(p, p, q)`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Axisymmetric {
    /// Mass `m`.
    m: f64,
    /// `h_z`.
    hz: f64,
    /// `I_O` about the x and y axes.
    p: f64,
    /// `I_O` about the z axis.
    q: f64,
}

impl Axisymmetric {
    /// The compact form of an inertia known to satisfy [`is_axisymmetric`].
    #[inline]
    pub(crate) fn of(inertia: &RigidInertia) -> Self {
        let io = inertia.inertia_about_origin();
        Self {
            m: inertia.mass(),
            hz: inertia.first_moment().z,
            p: io[(0, 0)],
            q: io[(2, 2)],
        }
    }

    /// `M s = [p w_x - h_z v_y, p w_y + h_z v_x, q w_z; m v_x + h_z w_y, m v_y - h_z w_x, m v_z]`
    /// (12 instead of 42 flops).
    #[inline]
    pub(crate) fn apply(&self, s: &Motion) -> Force {
        let (Self { m, hz, p, q }, w, v) = (*self, &s.ang, &s.lin);
        Force::new(
            Vector3::new(p * w.x - hz * v.y, p * w.y + hz * v.x, q * w.z),
            Vector3::new(m * v.x + hz * w.y, m * v.y - hz * w.x, m * v.z),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Isometry3, Vector3};

    /// The rigid-member congruence against the general articulated one, `C^T M C`.
    #[test]
    fn rigid_congruence_matches_the_articulated_transform() {
        let ic = Matrix3::new(0.3, 0.01, -0.02, 0.01, 0.2, 0.03, -0.02, 0.03, 0.25);
        let inertia = RigidInertia::new(2.5, Vector3::new(0.1, -0.2, 0.05), ic).expect("valid");
        let pose = Isometry3::new(Vector3::new(0.3, -0.1, 0.7), Vector3::new(0.9, -0.4, 1.2));
        let x = SpatialTransform::from_pose(&pose);
        let mut fast = ArticulatedInertia::zero();
        add_rigid_congruence(&inertia, &x, &mut fast);
        let dense = x.to_matrix().transpose() * inertia.to_matrix() * x.to_matrix();
        assert!((fast.to_matrix() - dense).amax() < 1e-12);
        let general = inertia.to_articulated().tr_transform(&x);
        assert!((fast.to_matrix() - general.to_matrix()).amax() < 1e-12);
        // Axisymmetric bodies (the short path) and near-axisymmetric ones (the general path),
        // accumulated onto a nonzero inertia, against the dense congruence.
        let diag = |a: f64, b: f64, c: f64| Matrix3::from_diagonal(&Vector3::new(a, b, c));
        for (com, ic, short) in [
            (Vector3::new(0.0, 0.0, 0.1), diag(0.3, 0.3, 0.05), true),
            (Vector3::new(0.0, 0.0, -0.2), diag(0.2, 0.2, 0.2), true),
            (Vector3::new(1e-9, 0.0, 0.1), diag(0.3, 0.3, 0.05), false),
            (
                Vector3::new(0.0, 0.0, 0.1),
                diag(0.3, 0.3 + 1e-9, 0.05),
                false,
            ),
        ] {
            assert_eq!(axisymmetric_inertia(&com, &ic, &x.rot).is_some(), short);
            let body = RigidInertia::new(1.5, com, ic).expect("valid");
            let mut acc = general;
            add_rigid_congruence(&body, &x, &mut acc);
            let dense_body = x.to_matrix().transpose() * body.to_matrix() * x.to_matrix();
            let expect = general.to_matrix() + dense_body;
            assert!((acc.to_matrix() - expect).amax() < 1e-12 * expect.amax());
            assert_eq!(acc.ang, acc.ang.transpose());
        }
    }

    /// A compact sum of a body placed by `at` and a congruence against the dense inertias.
    #[test]
    fn rigid_sum_matches_dense() {
        let ic = Matrix3::new(0.3, 0.01, -0.02, 0.01, 0.2, 0.03, -0.02, 0.03, 0.25);
        let c = Vector3::new(0.1, -0.2, 0.05);
        let placed = RigidInertia::new(2.5, c, ic).expect("valid");
        let pose = Isometry3::new(Vector3::new(0.3, -0.1, 0.7), Vector3::new(0.9, -0.4, 1.2));
        let x = SpatialTransform::from_pose(&pose);
        let mut sum = RigidSum::at(2.5, &c, &ic);
        sum += RigidSum::congruence(&placed, &x);
        let mut out = ArticulatedInertia::zero();
        sum.add_to(&mut out);
        let dense = x.to_matrix().transpose() * placed.to_matrix() * x.to_matrix();
        let expect = placed.to_matrix() + dense;
        assert!((out.to_matrix() - expect).amax() < 1e-12 * expect.amax());
    }

    /// The axisymmetric `M s` against the general rigid-body product, and the predicate.
    #[test]
    fn axisymmetric_apply_matches_the_rigid_product() {
        let ic = Matrix3::from_diagonal(&Vector3::new(0.3, 0.3, 0.05));
        let body = RigidInertia::new(1.5, Vector3::new(0.0, 0.0, -0.12), ic).expect("valid");
        assert!(is_axisymmetric(&body.com(), &body.inertia_about_com()));
        for (w, v) in [
            (Vector3::new(0.3, -1.0, 2.0), Vector3::new(0.5, 0.1, -0.7)),
            (Vector3::new(-4.0, 0.2, 0.0), Vector3::new(0.0, 3.0, 1.5)),
        ] {
            let s = Motion::new(w, v);
            let (fast, general) = (Axisymmetric::of(&body).apply(&s), body.apply(&s));
            let err = (fast.to_vector() - general.to_vector()).amax();
            assert!(err < 1e-14 * general.to_vector().amax(), "{err}");
        }
        let tilted = Matrix3::new(0.3, 1e-6, 0.0, 1e-6, 0.3, 0.0, 0.0, 0.0, 0.05);
        assert!(!is_axisymmetric(&Vector3::new(0.0, 0.0, 0.1), &tilted));
        assert!(!is_axisymmetric(&Vector3::new(0.0, 1e-9, 0.1), &ic));
    }
}
