//! Rotation of inertia blocks `A^T M A` (general and about a coordinate axis) for the
//! congruence `C^T I C` of (2.69).

use nalgebra::Matrix3;

/// The in-plane entries of a rotation `A` about coordinate axis `K` (plane `(p, q)` normal to
/// it), `A_pp = A_qq = c`, `A_pq = -A_qp = s`, and their double angle `(c^2 - s^2, 2 c s)`:
/// in the plane, the trace and the antisymmetric part of a 2x2 block are invariant under
/// `A^T M A` and its traceless symmetric part turns by the double angle, shared by the blocks.
#[derive(Clone, Copy, Debug)]
pub(super) struct PlaneRotation {
    /// `cos` of the angle.
    c: f64,
    /// `sin` of the angle (entry `(p, q)`).
    s: f64,
    /// `cos` of the double angle.
    c2: f64,
    /// `sin` of the double angle.
    s2: f64,
}

impl PlaneRotation {
    /// From the rotation matrix `a` about axis `K` (`A e_K = e_K`).
    #[inline(always)]
    pub(super) fn new<const K: usize>(a: &Matrix3<f64>) -> Self {
        let (p, q) = ((K + 1) % 3, (K + 2) % 3);
        let (c, s) = (a[(p, p)], a[(p, q)]);
        Self {
            c,
            s,
            c2: c * c - s * s,
            s2: 2.0 * c * s,
        }
    }

    /// The traceless symmetric part `[e f; f -e]` of a plane block turned: `(e', f')`.
    #[inline(always)]
    fn turn(&self, e: f64, f: f64) -> (f64, f64) {
        (e * self.c2 - f * self.s2, e * self.s2 + f * self.c2)
    }

    /// `(x_p c - x_q s, x_p s + x_q c)`: a row `x^T A` or column `A^T x` restricted to the plane.
    #[inline(always)]
    fn mul(&self, xp: f64, xq: f64) -> (f64, f64) {
        (xp * self.c - xq * self.s, xp * self.s + xq * self.c)
    }
}

/// `A^T M A` for a rotation about coordinate axis `K` ([`PlaneRotation`]): row and column `K`
/// rotate in the plane (8 multiplications), the plane block by its double angle (4).
#[inline]
pub(super) fn axis_congruence<const K: usize>(m: &Matrix3<f64>, r: &PlaneRotation) -> Matrix3<f64> {
    let (p, q) = ((K + 1) % 3, (K + 2) % 3);
    let (a, b, c, d) = (m[(p, p)], m[(p, q)], m[(q, p)], m[(q, q)]);
    let (h, k) = (0.5 * (a + d), 0.5 * (b - c));
    let (e, f) = r.turn(0.5 * (a - d), 0.5 * (b + c));
    let mut out = *m;
    (out[(p, p)], out[(q, q)]) = (h + e, h - e);
    (out[(p, q)], out[(q, p)]) = (k + f, f - k);
    (out[(K, p)], out[(K, q)]) = r.mul(m[(K, p)], m[(K, q)]);
    (out[(p, K)], out[(q, K)]) = r.mul(m[(p, K)], m[(q, K)]);
    out
}

/// `A^T S A` for symmetric `S` and a rotation about coordinate axis `K` ([`PlaneRotation`]):
/// the upper triangle (6 multiplications), mirrored, so the result is exactly symmetric.
#[inline]
pub(super) fn sym_axis_congruence<const K: usize>(
    m: &Matrix3<f64>,
    r: &PlaneRotation,
) -> Matrix3<f64> {
    let (p, q) = ((K + 1) % 3, (K + 2) % 3);
    let (a, d) = (m[(p, p)], m[(q, q)]);
    let h = 0.5 * (a + d);
    let (e, f) = r.turn(0.5 * (a - d), m[(p, q)]);
    let (kp, kq) = r.mul(m[(K, p)], m[(K, q)]);
    let mut out = Matrix3::zeros();
    out[(K, K)] = m[(K, K)];
    (out[(K, p)], out[(p, K)]) = (kp, kp);
    (out[(K, q)], out[(q, K)]) = (kq, kq);
    (out[(p, p)], out[(q, q)]) = (h + e, h - e);
    (out[(p, q)], out[(q, p)]) = (f, f);
    out
}

/// `A^T S A` for symmetric `S`, computing one triangle (exactly symmetric result).
#[inline]
pub fn sym_congruence(s: &Matrix3<f64>, a: &Matrix3<f64>) -> Matrix3<f64> {
    let t = s * a;
    let e = |i: usize, j: usize| a.column(i).dot(&t.column(j));
    let (m00, m01, m02, m11, m12, m22) = (e(0, 0), e(0, 1), e(0, 2), e(1, 1), e(1, 2), e(2, 2));
    Matrix3::new(m00, m01, m02, m01, m11, m12, m02, m12, m22)
}
