//! Shared pieces of the six distance functions: clamping, candidate bookkeeping, the result
//! assembly of eq. (6.11) and the documented normal rule for c* = 0 (see the module doc of
//! [`crate::distance`]).

use super::triangle_frame::TriFrame;
use crate::primitives::{Lss, Tss};
use crate::result::{DistanceResult, PrimitiveParam};
use nalgebra::{Point3, Vector3};

/// Squared sine below which an angle counts as zero (flat triangle, parallel lines); relative,
/// so every degeneracy test is scale invariant.
pub(crate) const SIN2_EPS: f64 = 1e-20;

/// 1/x for x > 0, else 0 (a zero-length edge then behaves as a point).
#[inline(always)]
pub(crate) fn inv_or_zero(x: f64) -> f64 {
    if x > 0.0 {
        1.0 / x
    } else {
        0.0
    }
}

/// Branch-free arg-min key of a candidate: the bits of a squared distance d2 >= 0 order like
/// the values, so the lowest four mantissa bits (a relative 2^-48, only able to swap nearly
/// equal candidates, whose distance is then evaluated exactly) carry the candidate index.
#[inline(always)]
pub(crate) fn min_key(d2: f64, k: usize) -> u64 {
    (d2.to_bits() & !15) | k as u64
}

/// Candidate index of a key made by [`min_key`].
#[inline(always)]
pub(crate) fn key_index(key: u64) -> usize {
    (key & 15) as usize
}

/// Saturation sat(x, 0, 1) of Tables 6.3/6.4; a NaN input maps to 0 (every comparison with
/// NaN is false), and the two selects map to single min/max instructions.
#[inline(always)]
pub(crate) fn clamp01(x: f64) -> f64 {
    let x = if x > 0.0 { x } else { 0.0 };
    if x < 1.0 {
        x
    } else {
        1.0
    }
}

/// Closest points p*_0, p*_1 (6.9) on the two underlying primitives and their parameters.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Closest {
    /// p*_0 on primitive a.
    pub a: Point3<f64>,
    /// p*_1 on primitive b.
    pub b: Point3<f64>,
    /// Parameters of `a`.
    pub param_a: PrimitiveParam,
    /// Parameters of `b`.
    pub param_b: PrimitiveParam,
}

/// The underlying primitive of an SSV, as seen by the c* = 0 normal rule.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Geom<'a> {
    /// A point.
    Point,
    /// A line segment.
    Line(&'a Lss),
    /// A triangle (its frame is rebuilt if the rule needs it).
    Triangle(&'a Tss),
    /// A triangle with the frame its distance function already prepared.
    Frame(&'a TriFrame),
}

/// Result assembly of eq. (6.11): offsets the primitive points along the unit normal.
///
/// The hot path is one sqrt and one division. The rare |c*|^2 < `f64::MIN_POSITIVE` (or
/// NaN) case is inlined as a cold branch without any call, so no value of the caller has
/// to be spilled around a call that clobbers every vector register.
#[inline(always)]
pub(crate) fn assemble(c: Closest, ra: f64, rb: f64, ga: Geom, gb: Geom) -> DistanceResult {
    let cv = c.b - c.a;
    let d2 = cv.norm_squared();
    let (len, n) = if d2 >= f64::MIN_POSITIVE {
        let len = d2.sqrt();
        (len, cv * (1.0 / len))
    } else {
        std::hint::cold_path();
        if let (Geom::Frame(_), Geom::Frame(_)) = (ga, gb) {
            // TT keeps too many values live for the inlined version to pay off.
            tiny_normal_call(&cv, ga, gb)
        } else {
            tiny_normal(&cv, ga, gb)
        }
    };
    DistanceResult {
        distance: len - ra - rb,
        point_a: c.a + n * ra,
        point_b: c.b - n * rb,
        normal: n,
        closest_a: c.a,
        closest_b: c.b,
        param_a: c.param_a,
        param_b: c.param_b,
    }
}

/// [`tiny_normal`] out of line.
#[cold]
#[inline(never)]
fn tiny_normal_call(cv: &Vector3<f64>, ga: Geom, gb: Geom) -> (f64, Vector3<f64>) {
    tiny_normal(cv, ga, gb)
}

/// |c*| and the normal when |c*|^2 underflows: c*/|c*| if c* != 0, else the geometric rule.
#[inline(always)]
fn tiny_normal(cv: &Vector3<f64>, ga: Geom, gb: Geom) -> (f64, Vector3<f64>) {
    match scaled_unit(cv) {
        Some((len, n)) => (len, n),
        None => (0.0, geometric_normal(ga, gb)),
    }
}

/// Length and direction of a non-zero vector, computed without under- or overflow.
#[inline(always)]
pub(crate) fn scaled_unit(v: &Vector3<f64>) -> Option<(f64, Vector3<f64>)> {
    let m = v.amax();
    if m > 0.0 && m.is_finite() {
        let w = v / m;
        let l = w.norm();
        Some((l * m, w / l))
    } else {
        None
    }
}

/// Index of the largest of three squared edge lengths (first one on ties).
#[inline(always)]
pub(crate) fn longest(l: &[f64; 3]) -> usize {
    if l[0] >= l[1] && l[0] >= l[2] {
        0
    } else if l[1] >= l[2] {
        1
    } else {
        2
    }
}

/// Boundary edges v_{i+1} - v_i of a triangle.
#[inline(always)]
pub(crate) fn boundary_edges(v: &[Point3<f64>; 3]) -> [Vector3<f64>; 3] {
    [v[1] - v[0], v[2] - v[1], v[0] - v[2]]
}

/// Triangle parameters (s0, s1) of eq. (6.5) of the point at parameter s on boundary edge i.
#[inline(always)]
pub(crate) fn edge_to_tri(i: usize, s: f64) -> (f64, f64) {
    match i {
        0 => (s, 0.0),
        1 => (1.0 - s, s),
        _ => (0.0, 1.0 - s),
    }
}

/// Unit normal of a non-flat triangle, e0 x e1 normalised (computed as e0 x F', see
/// [`TriFrame`]); `None` when flat.
#[inline(always)]
fn triangle_normal(f: &TriFrame) -> Option<Vector3<f64>> {
    if f.flat {
        None
    } else {
        scaled_unit(&f.n).map(|(_, u)| u)
    }
}

/// Unit direction of the line a primitive reduces to (a flat triangle: its longest edge).
#[inline(always)]
fn line_direction(g: Geom) -> Option<Vector3<f64>> {
    let e = match g {
        Geom::Point => return None,
        Geom::Line(l) => l.vertices()[1] - l.vertices()[0],
        Geom::Triangle(t) => {
            let e = boundary_edges(t.vertices());
            e[longest(&e.map(|x| x.norm_squared()))]
        }
        Geom::Frame(f) => f.e[longest(&f.ee)],
    };
    scaled_unit(&e).map(|(_, u)| u)
}

/// unit(e x axis_k) with axis_k the coordinate axis of the smallest |e_k|.
#[inline(always)]
fn perpendicular(e: &Vector3<f64>) -> Vector3<f64> {
    let k = e.iamin();
    let axis = Vector3::ith(k, 1.0);
    scaled_unit(&e.cross(&axis)).map_or(Vector3::z(), |(_, u)| u)
}

/// The normal rule for c* = 0 (module doc of [`crate::distance`]).
#[inline(always)]
pub(crate) fn geometric_normal(ga: Geom, gb: Geom) -> Vector3<f64> {
    for g in [gb, ga] {
        let n = match g {
            Geom::Triangle(t) => triangle_normal(&TriFrame::new(t)),
            Geom::Frame(f) => triangle_normal(f),
            _ => None,
        };
        if let Some(n) = n {
            return n;
        }
    }
    let (la, lb) = (line_direction(ga), line_direction(gb));
    if let (Some(ea), Some(eb)) = (la, lb) {
        let x = ea.cross(&eb);
        if x.norm_squared() > SIN2_EPS {
            if let Some((_, n)) = scaled_unit(&x) {
                return n;
            }
        }
    }
    match la.or(lb) {
        Some(e) => perpendicular(&e),
        None => Vector3::z(),
    }
}
