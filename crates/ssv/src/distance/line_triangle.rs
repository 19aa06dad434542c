//! LT: line-swept sphere to triangle-swept sphere (6.4.5).
//!
//! Exact feature enumeration in place of the region tables 6.6/6.7 (the "unified approach" of
//! 6.4.5): the closest pair of a segment and a triangle that do not intersect is either an
//! edge-edge pair (three LL calls) or a segment end point over the face (two plane
//! projections (6.21)); if the segment pierces the triangle the piercing point (6.46) gives
//! c* = 0. Every candidate is a feasible pair whose distance is evaluated exactly (edge pairs
//! from their points, end points over the face from their height), so near-degenerate input
//! can only make a candidate lose, never report a wrong distance. A flat
//! triangle has no face candidates: it is the union of its edges (its longest edge).
//! The piercing test and a segment on one side of the plane with its nearer end point over
//! the face are decided from the two end-point projections before any edge pair is solved;
//! then the edge opposite the nearer end point's most negative barycentric coordinate is
//! tried with a separating-plane certificate (PQP-style), and only if that fails are all
//! candidates compared.

use super::assemble::{assemble, clamp01, edge_to_tri, key_index, min_key, Closest, Geom};
use super::line_line::{segment_params, Seg};
use super::triangle_frame::{Proj, TriFrame};
use crate::primitives::{Lss, Tss};
use crate::result::{DistanceResult, PrimitiveParam};
use nalgebra::{Point3, Vector3};

/// Closest pair of a segment and a triangle: segment parameter, triangle parameters, points.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SegTri {
    /// Squared distance |c*|^2.
    pub d2: f64,
    /// Segment parameter t of (6.35).
    pub t: f64,
    /// Triangle parameters (s0, s1) of (6.35).
    pub s: (f64, f64),
    /// Closest point on the segment.
    pub pl: Point3<f64>,
    /// Closest point on the triangle.
    pub pt: Point3<f64>,
}

/// Closest pair of segment `p + t u` and the triangle of `f`: piercing first, then an end
/// point over the face when the segment lies on one side of the plane (it is then the
/// closest pair: every point of the segment is at least that far from the plane), else the
/// three edge pairs against the end points over the face.
#[inline(always)]
pub(crate) fn segment_triangle(p: &Point3<f64>, u: &Vector3<f64>, f: &TriFrame) -> SegTri {
    if f.flat {
        return nearest_edge(p, u, f);
    }
    let q = p + u;
    let (w0, w1) = (f.project(p), f.project(&q));
    let (h0, h1) = (w0.h, w1.h);
    let straddle = ((h0 < 0.0) & (h1 > 0.0)) | ((h0 > 0.0) & (h1 < 0.0));
    if straddle {
        // Piercing (6.46): the end points on strictly opposite sides and the crossing inside.
        let tx = clamp01(h0 / (h0 - h1));
        let x = p + u * tx;
        let wx = f.project(&x);
        if wx.inside() {
            return SegTri {
                d2: 0.0,
                t: tx,
                s: wx.params(),
                pl: x,
                pt: x,
            };
        }
    } else {
        let (tv, w, pv) = if h1.abs() < h0.abs() {
            (1.0, w1, q)
        } else {
            (0.0, w0, *p)
        };
        if w.inside() {
            return face_point(f, tv, &w, pv);
        }
    }
    let near = if h1.abs() < h0.abs() { &w1 } else { &w0 };
    if let Some(x) = edge_walk(p, u, f, likely_edge(near)) {
        return x;
    }
    let best = nearest_edge(p, u, f);
    // End points over the face: squared height h^2/|n|^2.
    let face = |w: &Proj| {
        if w.inside() {
            w.h * w.h * f.inv_nn
        } else {
            f64::INFINITY
        }
    };
    let (d0, d1) = (face(&w0), face(&w1));
    let (dv, tv, w, pv) = if d1 < d0 {
        (d1, 1.0, w1, q)
    } else {
        (d0, 0.0, w0, *p)
    };
    if dv < best.d2 {
        return face_point(f, tv, &w, pv);
    }
    best
}

/// Relative slack of the separation certificate (see the TT module): a vertex may lie this
/// fraction of the primitives' size beyond the plane.
const SEPARATION_SLACK: f64 = 1e-12;

/// Steps of [`edge_walk`] before the full enumeration takes over.
const WALK_STEPS: usize = 2;

/// The boundary edge most likely closest to a point with plane projection `w`: the one
/// opposite the most negative barycentric coordinate.
#[inline(always)]
fn likely_edge(w: &Proj) -> usize {
    // Opposite v2 (weight s1): edge 0; opposite v0: edge 1; opposite v1 (weight s0): edge 2.
    let b = [w.s1, 1.0 - w.s0 - w.s1, w.s0];
    let k = if b[1] < b[0] { 1 } else { 0 };
    if b[2] < b[k] {
        2
    } else {
        k
    }
}

/// A segment-edge pair certified globally closest: the plane through its closest points,
/// normal to c*, has both segment end points on one side and all three triangle vertices
/// on the other (up to [`SEPARATION_SLACK`]). Starting from edge `k`, a failing third
/// vertex moves the walk to the edge at that vertex; `None` when nothing is certified.
#[inline(always)]
fn edge_walk(p: &Point3<f64>, u: &Vector3<f64>, f: &TriFrame, mut k: usize) -> Option<SegTri> {
    let seg = Seg::new(*p, *u);
    let size = u
        .amax()
        .max(f.e[0].amax())
        .max(f.e[1].amax())
        .max(f.e[2].amax());
    for _ in 0..WALK_STEPS {
        let (t, s) = segment_params(&seg, &f.edge(k));
        let (pl, pt) = (p + u * t, f.v[k] + f.e[k] * s);
        let c = pt - pl;
        if (f.v[(k + 2) % 3] - pt).dot(&c) < 0.0 {
            k = if s < 0.5 { (k + 2) % 3 } else { (k + 1) % 3 };
            continue;
        }
        let tol = SEPARATION_SLACK * size * c.amax();
        let hl = (p - pl).dot(&c).max((p + u - pl).dot(&c));
        let ht = (0..3)
            .map(|i| (f.v[i] - pt).dot(&c))
            .fold(f64::INFINITY, f64::min);
        if (hl <= tol) & (ht >= -tol) {
            return Some(SegTri {
                d2: c.norm_squared(),
                t,
                s: edge_to_tri(k, s),
                pl,
                pt,
            });
        }
        return None;
    }
    None
}

/// The pair of end point `pv` (segment parameter `tv`) and its projection `w` into the face.
#[inline(always)]
fn face_point(f: &TriFrame, tv: f64, w: &Proj, pv: Point3<f64>) -> SegTri {
    let s = w.params();
    let pt = f.point_at(s);
    SegTri {
        d2: (pt - pv).norm_squared(),
        t: tv,
        s,
        pl: pv,
        pt,
    }
}

/// The nearest of the three segment-edge pairs (branch-free selection).
#[inline(always)]
fn nearest_edge(p: &Point3<f64>, u: &Vector3<f64>, f: &TriFrame) -> SegTri {
    let seg = Seg::new(*p, *u);
    let mut ts = [(0.0, 0.0); 3];
    let mut key = u64::MAX;
    for (k, tsk) in ts.iter_mut().enumerate() {
        *tsk = segment_params(&seg, &f.edge(k));
        let (t, s) = *tsk;
        key = key.min(min_key(
            ((f.v[k] - p) + f.e[k] * s - u * t).norm_squared(),
            k,
        ));
    }
    let kb = key_index(key);
    let (t, s) = ts[kb];
    let d2 = ((f.v[kb] - p) + f.e[kb] * s - u * t).norm_squared();
    SegTri {
        d2,
        t,
        s: edge_to_tri(kb, s),
        pl: p + u * t,
        pt: f.v[kb] + f.e[kb] * s,
    }
}

/// LT: line segment to triangle (6.4.5).
#[inline]
pub fn lt(a: &Lss, b: &Tss) -> DistanceResult {
    let [p0, p1] = a.vertices();
    let f = TriFrame::new(b);
    let r = segment_triangle(p0, &(p1 - p0), &f);
    let c = Closest {
        a: r.pl,
        b: r.pt,
        param_a: PrimitiveParam::Line(r.t),
        param_b: PrimitiveParam::Triangle(r.s.0, r.s.1),
    };
    assemble(c, a.radius(), b.radius(), Geom::Line(a), Geom::Frame(&f))
}

#[cfg(test)]
mod tests;
