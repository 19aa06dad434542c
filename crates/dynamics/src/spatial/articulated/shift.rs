//! Shift of rotated inertia blocks by the joint offset `r`: the `[E 0; -r~ E]` factor of
//! `C_i` (2.36) in the congruence `C^T I C` of (2.69).

use super::{outer, ArticulatedInertia};
use crate::spatial::Force;
use nalgebra::{Matrix3, Vector3};

/// What [`store`] subtracts from the shifted blocks: nothing (`()`) or a rank-one term
/// `w b b^T` given as `(b, w)` (the `- B_S D^-1 B_S^T` of a one-DoF step (2.72) folded into
/// the accumulation); a type parameter, so the plain congruence carries no extra branch.
pub(super) trait Minus: Copy {
    /// The blocks `[ang, cross, lin]` less the term.
    fn from(self, blocks: [Matrix3<f64>; 3]) -> [Matrix3<f64>; 3];
}

impl Minus for () {
    #[inline(always)]
    fn from(self, blocks: [Matrix3<f64>; 3]) -> [Matrix3<f64>; 3] {
        blocks
    }
}

impl Minus for (&Force, f64) {
    #[inline(always)]
    fn from(self, [ang, cross, lin]: [Matrix3<f64>; 3]) -> [Matrix3<f64>; 3] {
        let [oa, oc, ol] = outer(self.0, self.1);
        [ang - oa, cross - oc, lin - ol]
    }
}

/// Shift of rotated blocks by `r` (parent coordinates), the `[E 0; -r~ E]` factor of `C`:
/// `cross' = B - (D r~)^T`, `ang' = A - B r~ - (B r~)^T - r~ D r~`, less `minus`, written to
/// `out` (`ADD = false`) or added to it (`ADD = true`, no temporary inertia). Joint offsets are
/// often zero or along one coordinate axis (constant for revolute joints): those skip the
/// products with the zero entries of `r~` ([`shift_axis`]).
#[inline]
pub(super) fn shift_into<const ADD: bool>(
    ang: &Matrix3<f64>,
    cross: &Matrix3<f64>,
    lin: Matrix3<f64>,
    r: &Vector3<f64>,
    minus: impl Minus,
    out: &mut ArticulatedInertia,
) {
    match (r.x != 0.0, r.y != 0.0, r.z != 0.0) {
        (false, false, false) => store::<ADD>(*ang, *cross, lin, minus, out),
        (true, false, false) => shift_axis::<0, ADD>(ang, cross, lin, r.x, minus, out),
        (false, true, false) => shift_axis::<1, ADD>(ang, cross, lin, r.y, minus, out),
        (false, false, true) => shift_axis::<2, ADD>(ang, cross, lin, r.z, minus, out),
        _ => shift_general::<ADD>(ang, cross, lin, r, minus, out),
    }
}

/// The blocks less `minus` written to (`ADD = false`) or added to (`ADD = true`) `out`.
#[inline]
fn store<const ADD: bool>(
    ang: Matrix3<f64>,
    cross: Matrix3<f64>,
    lin: Matrix3<f64>,
    minus: impl Minus,
    out: &mut ArticulatedInertia,
) {
    let [ang, cross, lin] = minus.from([ang, cross, lin]);
    if ADD {
        out.ang += ang;
        out.cross += cross;
        out.lin += lin;
    } else {
        *out = ArticulatedInertia { ang, cross, lin };
    }
}

/// [`shift_general`] for `r = rho e_J`: with `(p, q)` the plane normal to axis `J`, `M r~` has
/// the columns `p: rho M e_q`, `q: -rho M e_p` and a zero column `J`; `r~ M` the rows
/// `p: -rho M^T e_q`, `q: rho M^T e_p` and a zero row `J` (6 instead of 18 products each).
#[inline]
pub(super) fn shift_axis<const J: usize, const ADD: bool>(
    ang: &Matrix3<f64>,
    cross: &Matrix3<f64>,
    lin: Matrix3<f64>,
    rho: f64,
    minus: impl Minus,
    out: &mut ArticulatedInertia,
) {
    let (p, q) = ((J + 1) % 3, (J + 2) % 3);
    let mul_skew = |m: &Matrix3<f64>| {
        let mut t = Matrix3::zeros();
        for i in 0..3 {
            t[(i, p)] = rho * m[(i, q)];
            t[(i, q)] = -(rho * m[(i, p)]);
        }
        t
    };
    let (dr, br) = (mul_skew(&lin), mul_skew(cross));
    // (r~ D r~)_ij: row p is -rho (D r~)_qj, row q is rho (D r~)_pj, row J is zero.
    let rdr = |i: usize, j: usize| {
        if i == p {
            -(rho * dr[(q, j)])
        } else if i == q {
            rho * dr[(p, j)]
        } else {
            0.0
        }
    };
    let e = |i: usize, j: usize| ang[(i, j)] - br[(i, j)] - br[(j, i)] - rdr(i, j);
    let (m01, m02, m12) = (e(0, 1), e(0, 2), e(1, 2));
    let ang = Matrix3::new(e(0, 0), m01, m02, m01, e(1, 1), m12, m02, m12, e(2, 2));
    store::<ADD>(ang, cross - dr.transpose(), lin, minus, out);
}

/// The shift for a general `r`, the symmetric `ang'` evaluated on its upper triangle only
/// (exactly symmetric result).
#[inline]
pub(super) fn shift_general<const ADD: bool>(
    ang: &Matrix3<f64>,
    cross: &Matrix3<f64>,
    lin: Matrix3<f64>,
    r: &Vector3<f64>,
    minus: impl Minus,
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
    store::<ADD>(ang, cross - dr.transpose(), lin, minus, out);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spatial::SpatialTransform;
    use nalgebra::{Matrix6, Rotation3};
    use proptest::prelude::*;

    /// A symmetric positive definite 6x6 inertia `L L^T` from 21 entries of `L`.
    fn inertia(l: &[f64]) -> ArticulatedInertia {
        let mut k = 0;
        let l = Matrix6::from_fn(|i, j| {
            if j <= i {
                k += 1;
                l[k - 1] + if i == j { 2.0 } else { 0.0 }
            } else {
                0.0
            }
        });
        ArticulatedInertia::from_matrix(&(l * l.transpose()))
    }

    proptest! {
        /// Offsets zero or along one axis: the dispatched shift equals the general one (set and
        /// accumulated), and the whole congruence equals the dense `C^T I C` of (2.69).
        #[test]
        fn axis_shift_equals_general_shift(
            l in prop::collection::vec(-1.0f64..1.0, 21),
            base in prop::collection::vec(-1.0f64..1.0, 21),
            rho in -2.0f64..2.0,
            axis in 0usize..4,
            angle in -4.0f64..4.0,
            (rx, ry, rz) in (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0),
        ) {
            let m = inertia(&l);
            let mut r = Vector3::zeros();
            if axis < 3 {
                r[axis] = rho;
            }
            let (mut fast, mut general) = (ArticulatedInertia::zero(), ArticulatedInertia::zero());
            shift_into::<false>(&m.ang, &m.cross, m.lin, &r, (), &mut fast);
            shift_general::<false>(&m.ang, &m.cross, m.lin, &r, (), &mut general);
            let tol = 1e-14 * general.to_matrix().amax();
            prop_assert!((fast.to_matrix() - general.to_matrix()).amax() <= tol);
            let start = inertia(&base);
            let (mut fast, mut general) = (start, start);
            shift_into::<true>(&m.ang, &m.cross, m.lin, &r, (), &mut fast);
            shift_general::<true>(&m.ang, &m.cross, m.lin, &r, (), &mut general);
            prop_assert!((fast.to_matrix() - general.to_matrix()).amax() <= 2.0 * tol);
            // Dense check of the full congruence with this offset and a general rotation
            // (and a general offset, which takes the general shift).
            let rot = Rotation3::from_euler_angles(angle, 0.5 * angle, -angle);
            for t in [r, Vector3::new(rx, ry, rz)] {
                let x = SpatialTransform::new(*rot.matrix(), t);
                let c = x.to_matrix();
                let dense = c.transpose() * m.to_matrix() * c;
                let got = m.tr_transform(&x).to_matrix();
                prop_assert!((got - dense).amax() <= 1e-12 * dense.amax());
            }
        }
    }
}
