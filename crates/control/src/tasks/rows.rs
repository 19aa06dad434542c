//! Row helpers shared by the task sets: `J_C` from `A_G` and rotated differences of
//! Jacobian row blocks.

use nalgebra::{DMatrix, Matrix3, Vector3};

/// `J_C` (3 x nv) from the centroidal momentum matrix `A_G = [J_L; m J_C]`.
pub(crate) fn com_jacobian_from_ag(ag: &DMatrix<f64>, mass: f64, jc: &mut DMatrix<f64>) {
    let inv = 1.0 / mass;
    for (dst, col) in jc
        .as_mut_slice()
        .chunks_exact_mut(3)
        .zip(ag.as_slice().chunks_exact(6))
    {
        for r in 0..3 {
            dst[r] = col[3 + r] * inv;
        }
    }
}

/// `out[r..r+3, :] = rot * (a[ra..ra+3, :] - b[rb..rb+3, :])` (b optional).
pub(crate) fn put_rows(
    out: &mut DMatrix<f64>,
    r: usize,
    rot: &Matrix3<f64>,
    a: &DMatrix<f64>,
    ra: usize,
    b: Option<&DMatrix<f64>>,
    rb: usize,
) {
    for c in 0..a.ncols() {
        let mut v = Vector3::new(a[(ra, c)], a[(ra + 1, c)], a[(ra + 2, c)]);
        if let Some(b) = b {
            v -= Vector3::new(b[(rb, c)], b[(rb + 1, c)], b[(rb + 2, c)]);
        }
        let w = rot * v;
        for i in 0..3 {
            out[(r + i, c)] = w[i];
        }
    }
}
