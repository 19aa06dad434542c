//! Shift of rotated inertia blocks by the joint offset `r`: the `[E 0; -r~ E]` factor of
//! `C_i` (2.36) in the congruence `C^T I C` of (2.69).

use super::ArticulatedInertia;
use nalgebra::{Matrix3, Vector3};

/// Shift of rotated blocks by `r` (parent coordinates), the `[E 0; -r~ E]` factor of `C`:
/// `cross' = B - (D r~)^T`, `ang' = A - B r~ - (B r~)^T - r~ D r~`, the symmetric `ang'`
/// evaluated on its upper triangle only (exactly symmetric result); written to `out`
/// (`ADD = false`) or added to it (`ADD = true`, no temporary inertia).
#[inline]
pub(super) fn shift_into<const ADD: bool>(
    ang: &Matrix3<f64>,
    cross: &Matrix3<f64>,
    lin: Matrix3<f64>,
    r: &Vector3<f64>,
    out: &mut ArticulatedInertia,
) {
    let dr = mul_skew(&lin, r);
    let br = mul_skew(cross, r);
    // (r~ M)_ij = (r x M e_j)_i.
    let rdr = |i: usize, j: usize| {
        let (a, b) = ((i + 1) % 3, (i + 2) % 3);
        r[a] * dr[(b, j)] - r[b] * dr[(a, j)]
    };
    let e = |i: usize, j: usize| ang[(i, j)] - br[(i, j)] - br[(j, i)] - rdr(i, j);
    let (m01, m02, m12) = (e(0, 1), e(0, 2), e(1, 2));
    let ang = Matrix3::new(e(0, 0), m01, m02, m01, e(1, 1), m12, m02, m12, e(2, 2));
    let cross = cross - dr.transpose();
    if ADD {
        out.ang += ang;
        out.cross += cross;
        out.lin += lin;
    } else {
        *out = ArticulatedInertia { ang, cross, lin };
    }
}

/// `M r~`: row `i` is `m_i x r`.
#[inline]
fn mul_skew(m: &Matrix3<f64>, r: &Vector3<f64>) -> Matrix3<f64> {
    let row = |i: usize| {
        let (x, y, z) = (m[(i, 0)], m[(i, 1)], m[(i, 2)]);
        [y * r.z - z * r.y, z * r.x - x * r.z, x * r.y - y * r.x]
    };
    let (r0, r1, r2) = (row(0), row(1), row(2));
    Matrix3::new(
        r0[0], r0[1], r0[2], r1[0], r1[1], r1[2], r2[0], r2[1], r2[2],
    )
}
