//! Separating-axis test of two oriented boxes (3 + 3 face normals, 9 edge cross products).
//!
//! Work is done in the frame of box `a`: `r = A^T B` holds the axes of `b`, `t` the centre
//! offset. `|r| + EPS` guards the nine cross-product axes against near-parallel edges, where
//! the cross product degenerates and rounding alone could fake a separation.

use super::Obb;
use nalgebra::{Matrix3, Vector3};

/// Added to `|r_ij|` so that degenerate cross axes never report a false separation.
const EPS: f64 = 1e-9;
/// sqrt(3).
const SQRT_3: f64 = 1.732_050_807_568_877_2;

/// Whether `a` and `b`, each with half extents grown by `margin`, intersect.
#[inline]
pub(super) fn overlaps(a: &Obb, b: &Obb, margin: f64) -> bool {
    let ha = a.half_extents.add_scalar(margin);
    let hb = b.half_extents.add_scalar(margin);
    // Circumscribed spheres first: |h + m| <= |h| + sqrt(3) m bounds each enlarged box.
    let reach = a.circumradius() + b.circumradius() + 2.0 * SQRT_3 * margin + EPS;
    if (b.center - a.center).norm_squared() > reach * reach {
        return false;
    }
    let r = a.axes.tr_mul(&b.axes);
    let t = a.axes.tr_mul(&(b.center - a.center));
    let abs_r = r.abs().add_scalar(EPS);
    !(separated_by_a_faces(&ha, &hb, &t, &abs_r)
        || separated_by_b_faces(&ha, &hb, &t, &r, &abs_r)
        || separated_by_edges(&ha, &hb, &t, &r, &abs_r))
}

/// Axes a_i: projected radius of b is sum_j hb_j |r_ij|.
#[inline]
fn separated_by_a_faces(
    ha: &Vector3<f64>,
    hb: &Vector3<f64>,
    t: &Vector3<f64>,
    abs_r: &Matrix3<f64>,
) -> bool {
    (0..3).any(|i| {
        let rb = hb.x * abs_r[(i, 0)] + hb.y * abs_r[(i, 1)] + hb.z * abs_r[(i, 2)];
        t[i].abs() > ha[i] + rb
    })
}

/// Axes b_j: projected radius of a is sum_i ha_i |r_ij|, offset t . b_j.
#[inline]
fn separated_by_b_faces(
    ha: &Vector3<f64>,
    hb: &Vector3<f64>,
    t: &Vector3<f64>,
    r: &Matrix3<f64>,
    abs_r: &Matrix3<f64>,
) -> bool {
    (0..3).any(|j| {
        let ra = ha.x * abs_r[(0, j)] + ha.y * abs_r[(1, j)] + ha.z * abs_r[(2, j)];
        let offset = t.x * r[(0, j)] + t.y * r[(1, j)] + t.z * r[(2, j)];
        offset.abs() > ra + hb[j]
    })
}

/// Axes a_i x b_j (both frames right-handed).
#[inline]
fn separated_by_edges(
    ha: &Vector3<f64>,
    hb: &Vector3<f64>,
    t: &Vector3<f64>,
    r: &Matrix3<f64>,
    abs_r: &Matrix3<f64>,
) -> bool {
    for i in 0..3 {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        for j in 0..3 {
            let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
            let ra = ha[i1] * abs_r[(i2, j)] + ha[i2] * abs_r[(i1, j)];
            let rb = hb[j1] * abs_r[(i, j2)] + hb[j2] * abs_r[(i, j1)];
            let offset = t[i2] * r[(i1, j)] - t[i1] * r[(i2, j)];
            if offset.abs() > ra + rb {
                return true;
            }
        }
    }
    false
}
