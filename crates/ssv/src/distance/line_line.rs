//! LL: line-swept sphere to line-swept sphere (6.4.4, Appendix B.1).
//!
//! The unconstrained line parameter comes from the normal equations (6.31) where the
//! scale-invariant criterion (6.34) shows them well conditioned (sin^2 > 1e-2), and otherwise
//! from the components of u and w orthogonal to v (a QR-style solve of (6.28), backward stable
//! for nearly parallel lines). Both branches are exact where they meet, so the threshold is
//! not a fragile parallel epsilon. The two saturation steps of Tables 6.3/6.4 follow as
//! clamp-and-recompute; in the exactly parallel limit the first estimate is arbitrary and
//! these two 1-D projections return an optimal pair anyway, so Table 6.5 is not needed.

use super::assemble::{assemble, clamp01, inv_or_zero, Closest, Geom};
use crate::primitives::Lss;
use crate::result::{DistanceResult, PrimitiveParam};
use nalgebra::{Point3, Vector3};

/// Relative threshold of the scale-invariant criterion (6.34): above it the normal
/// equations (6.31) lose at most two digits and are used; below it the orthogonalised solve.
pub(crate) const WELL_CONDITIONED: f64 = 1e-2;

/// A segment `p + s u` with |u|^2 and 1/|u|^2 (0 for a zero-length segment).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Seg {
    /// Start point.
    pub p: Point3<f64>,
    /// Edge vector.
    pub u: Vector3<f64>,
    /// |u|^2.
    pub uu: f64,
    /// 1/|u|^2, or 0.
    pub inv_uu: f64,
}

impl Seg {
    /// A segment from its start point and edge vector.
    #[inline(always)]
    pub fn new(p: Point3<f64>, u: Vector3<f64>) -> Self {
        let uu = u.norm_squared();
        Self {
            p,
            u,
            uu,
            inv_uu: inv_or_zero(uu),
        }
    }
}

/// Parameters (s, t) in [0, 1]^2 of the closest points of segments `a.p + s a.u` and
/// `b.p + t b.u` (6.23); zero-length segments behave as points.
#[inline(always)]
pub(crate) fn segment_params(a: &Seg, b: &Seg) -> (f64, f64) {
    solve_params(a, b, near_parallel_s)
}

/// [`segment_params`] with the nearly parallel solve `near` (out of line or inlined).
#[inline(always)]
fn solve_params(
    a: &Seg,
    b: &Seg,
    near: impl Fn(&Vector3<f64>, &Vector3<f64>, &Vector3<f64>, f64, f64, f64) -> f64,
) -> (f64, f64) {
    let (u, v) = (&a.u, &b.u);
    let w = b.p - a.p;
    let (uv, uw, vw) = (u.dot(v), u.dot(&w), v.dot(&w));
    let n = a.uu * b.uu - uv * uv;
    let s = if n > WELL_CONDITIONED * a.uu * b.uu {
        (b.uu * uw - uv * vw) / n
    } else {
        near(u, v, &w, uv, vw, b.inv_uu)
    };
    let s = clamp01(s);
    // Step 1 (Table 6.3 analogue): best t for this s, saturated.
    let t = clamp01((s * uv - vw) * b.inv_uu);
    // Step 2 (Table 6.4 analogue): best s for that t, saturated.
    let s = clamp01((uw + t * uv) * a.inv_uu);
    (s, t)
}

/// Infinite-line parameter s of (6.28) for nearly parallel or degenerate segments, from the
/// components of u and w orthogonal to v (QR instead of the normal equations); 0 if u is
/// parallel to v to machine precision, where steps 1 and 2 alone give an optimal pair.
#[inline(never)]
pub(crate) fn near_parallel_s(
    u: &Vector3<f64>,
    v: &Vector3<f64>,
    w: &Vector3<f64>,
    uv: f64,
    vw: f64,
    inv_vv: f64,
) -> f64 {
    orthogonal_s(u, v, w, uv, vw, inv_vv)
}

/// The body of [`near_parallel_s`], for callers that inline it.
#[inline(always)]
fn orthogonal_s(
    u: &Vector3<f64>,
    v: &Vector3<f64>,
    w: &Vector3<f64>,
    uv: f64,
    vw: f64,
    inv_vv: f64,
) -> f64 {
    let u_perp = u - v * (uv * inv_vv);
    let w_perp = w - v * (vw * inv_vv);
    let den = u_perp.norm_squared();
    if den > 0.0 {
        u_perp.dot(&w_perp) / den
    } else {
        0.0
    }
}

/// Largest reciprocal 1/(|u|^2 |v|^2 N) the one-division path accepts: 2^1022, i.e. the
/// product itself is a normal number (a subnormal one would lose digits).
const MAX_RECIP: f64 = 1.0 / f64::MIN_POSITIVE;

/// LL: line segment to line segment (6.4.4).
///
/// Well-conditioned pairs (6.34) take the normal equations (6.31) with the three
/// reciprocals 1/|u|^2, 1/|v|^2 and 1/N from a single division; the rest (nearly parallel,
/// degenerate, or a product outside the normal range) take the general solve of
/// `segment_params`.
#[inline]
pub fn ll(a: &Lss, b: &Lss) -> DistanceResult {
    let [p0, p1] = a.vertices();
    let [q0, q1] = b.vertices();
    let (u, v, w) = (p1 - p0, q1 - q0, q0 - p0);
    let (uu, vv) = (u.norm_squared(), v.norm_squared());
    let (uv, uw, vw) = (u.dot(&v), u.dot(&w), v.dot(&w));
    let uuvv = uu * vv;
    let n = uuvv - uv * uv;
    // r is a positive normal number at most 2^1022 exactly when the product is a positive
    // normal number; the non-short-circuit `&` avoids a separate branch per test.
    let r = 1.0 / (uuvv * n);
    // Plain compares: `RangeInclusive::contains` adds work here.
    #[allow(clippy::manual_range_contains)]
    let fast = (n > WELL_CONDITIONED * uuvv) & (r >= f64::MIN_POSITIVE) & (r <= MAX_RECIP);
    let (s, t) = if fast {
        let nr = n * r;
        let s = clamp01((vv * uw - uv * vw) * (uuvv * r));
        let t = clamp01((s * uv - vw) * (uu * nr));
        (clamp01((uw + t * uv) * (vv * nr)), t)
    } else {
        // Nearly parallel or degenerate: inlined as a cold branch without calls, so the
        // common path spills nothing.
        std::hint::cold_path();
        solve_params(&Seg::new(*p0, u), &Seg::new(*q0, v), orthogonal_s)
    };
    let c = Closest {
        a: p0 + u * s,
        b: q0 + v * t,
        param_a: PrimitiveParam::Line(s),
        param_b: PrimitiveParam::Line(t),
    };
    assemble(c, a.radius(), b.radius(), Geom::Line(a), Geom::Line(b))
}

#[cfg(test)]
mod tests;
