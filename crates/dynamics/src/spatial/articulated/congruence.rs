//! Rotation of inertia blocks `A^T M A` (general and about a coordinate axis) for the
//! congruence `C^T I C` of (2.69).

use nalgebra::Matrix3;

/// `A^T M A` for a rotation `A` about coordinate axis `K` (`A e_K = e_K`): only the plane
/// `(p, q)` normal to the axis mixes, `T = M A` then `A^T T`, 12 multiplications each.
#[inline]
pub(super) fn axis_congruence<const K: usize>(m: &Matrix3<f64>, a: &Matrix3<f64>) -> Matrix3<f64> {
    let (p, q) = ((K + 1) % 3, (K + 2) % 3);
    let (app, apq, aqp, aqq) = (a[(p, p)], a[(p, q)], a[(q, p)], a[(q, q)]);
    let mut t = *m;
    for r in 0..3 {
        let (mp, mq) = (m[(r, p)], m[(r, q)]);
        t[(r, p)] = mp * app + mq * aqp;
        t[(r, q)] = mp * apq + mq * aqq;
    }
    let mut out = t;
    for c in 0..3 {
        let (tp, tq) = (t[(p, c)], t[(q, c)]);
        out[(p, c)] = app * tp + aqp * tq;
        out[(q, c)] = apq * tp + aqq * tq;
    }
    out
}

/// `A^T S A` for symmetric `S` and a rotation `A` about coordinate axis `K`: the upper
/// triangle (18 multiplications), mirrored, so the result is exactly symmetric.
#[inline]
pub(super) fn sym_axis_congruence<const K: usize>(
    m: &Matrix3<f64>,
    a: &Matrix3<f64>,
) -> Matrix3<f64> {
    let (p, q) = ((K + 1) % 3, (K + 2) % 3);
    let (app, apq, aqp, aqq) = (a[(p, p)], a[(p, q)], a[(q, p)], a[(q, q)]);
    // Plane columns of T = S A (rows p, q and K).
    let (tpp, tqp) = (
        m[(p, p)] * app + m[(p, q)] * aqp,
        m[(q, p)] * app + m[(q, q)] * aqp,
    );
    let (tpq, tqq) = (
        m[(p, p)] * apq + m[(p, q)] * aqq,
        m[(q, p)] * apq + m[(q, q)] * aqq,
    );
    let (tkp, tkq) = (
        m[(K, p)] * app + m[(K, q)] * aqp,
        m[(K, p)] * apq + m[(K, q)] * aqq,
    );
    let opq = app * tpq + aqp * tqq;
    let mut out = Matrix3::zeros();
    out[(K, K)] = m[(K, K)];
    (out[(K, p)], out[(p, K)]) = (tkp, tkp);
    (out[(K, q)], out[(q, K)]) = (tkq, tkq);
    out[(p, p)] = app * tpp + aqp * tqp;
    (out[(p, q)], out[(q, p)]) = (opq, opq);
    out[(q, q)] = apq * tpq + aqq * tqq;
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
