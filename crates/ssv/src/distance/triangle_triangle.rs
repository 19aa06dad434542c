//! TT: triangle-swept sphere to triangle-swept sphere (6.4.6).
//!
//! The enumeration of 6.4.6: nine edge-edge pairs (LL) and six vertex-face projections
//! (6.21), plus the intersection test: an edge of one triangle piercing the other gives
//! c* = 0. For two triangles that do not intersect, one point of a closest pair lies on a
//! boundary, so the minimum over these candidates is exact; intersecting (non-coplanar)
//! triangles always have an edge piercing the other one, and overlapping coplanar triangles
//! have crossing edges or a vertex inside the other face. The piercing test only runs when
//! each triangle straddles the other's plane (necessary for a non-coplanar intersection);
//! the edge pairs reuse the frames' edge data ([`super::edge_pairs`]) and the selections
//! are branch-free arg-mins. A flat triangle has no face candidates: it is the union of its
//! edges (its longest edge).
//!
//! Two cheap certificates end the search early (PQP-style): a triangle entirely on one side
//! of the other's plane whose nearest vertex projects into the other face is at exactly that
//! height, and an edge pair whose connecting plane (normal to c*) separates the triangles
//! (all six vertices tested, with a 1e-12 relative slack) is the closest pair. A short walk
//! over edge pairs (start at the vertices nearest to the other plane, move towards the
//! vertex beyond the plane) finds that pair with one to three LL solves in most separated
//! configurations. Only when no certificate holds are all candidates compared.

use super::assemble::{assemble, clamp01, edge_to_tri, Closest, Geom};
use super::edge_pairs::{edge_pair, nearest_edge_pair};
use super::triangle_frame::{Proj, TriFrame};
use crate::primitives::Tss;
use crate::result::{DistanceResult, PrimitiveParam};
use nalgebra::Point3;

/// Best candidate so far: squared distance, parameters and points on a and b.
#[derive(Debug, Clone, Copy)]
struct Best {
    d2: f64,
    sa: (f64, f64),
    sb: (f64, f64),
    pa: Point3<f64>,
    pb: Point3<f64>,
}

/// Triangle parameters (s0, s1) of the vertices v0, v1, v2.
const VERTEX: [(f64, f64); 3] = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)];

/// Projections (6.21) of the three vertices of `a` onto the plane of `b`.
#[inline(always)]
fn project_vertices(a: &TriFrame, b: &TriFrame) -> [Proj; 3] {
    [b.project(&a.v[0]), b.project(&a.v[1]), b.project(&a.v[2])]
}

/// True when the vertices lie strictly on both sides of the plane.
#[inline(always)]
fn straddles(w: &[Proj; 3]) -> bool {
    let pos = (w[0].h > 0.0) | (w[1].h > 0.0) | (w[2].h > 0.0);
    let neg = (w[0].h < 0.0) | (w[1].h < 0.0) | (w[2].h < 0.0);
    pos & neg
}

/// Puts a candidate of the pair (a, b) into query order.
#[inline(always)]
fn order(x: Best, swap: bool) -> Best {
    if swap {
        Best {
            sa: x.sb,
            sb: x.sa,
            pa: x.pb,
            pb: x.pa,
            ..x
        }
    } else {
        x
    }
}

/// The first edge of `a` piercing the (non-flat) triangle `b` (6.46): c* = 0 at that point.
#[inline(always)]
fn piercing(a: &TriFrame, b: &TriFrame, w: &[Proj; 3], swap: bool) -> Option<Best> {
    for i in 0..3 {
        let (h0, h1) = (w[i].h, w[(i + 1) % 3].h);
        if ((h0 < 0.0) & (h1 > 0.0)) | ((h0 > 0.0) & (h1 < 0.0)) {
            let t = clamp01(h0 / (h0 - h1));
            let p = a.v[i] + a.e[i] * t;
            let wp = b.project(&p);
            if wp.inside() {
                let x = Best {
                    d2: 0.0,
                    sa: edge_to_tri(i, t),
                    sb: wp.params(),
                    pa: p,
                    pb: p,
                };
                return Some(order(x, swap));
            }
        }
    }
    None
}

/// The vertex-face candidates of the vertices of `a` over the (non-flat) face of `b`.
#[inline(always)]
fn vertex_face(a: &TriFrame, b: &TriFrame, w: &[Proj; 3], swap: bool, best: &mut Best) {
    let (mut dv, mut iv) = (f64::INFINITY, 0);
    for (i, wi) in w.iter().enumerate() {
        let d = if wi.inside() {
            wi.h * wi.h * b.inv_nn
        } else {
            f64::INFINITY
        };
        iv = if d < dv { i } else { iv };
        dv = dv.min(d);
    }
    if dv < best.d2 {
        let sb = w[iv].params();
        let x = Best {
            d2: dv,
            sa: VERTEX[iv],
            sb,
            pa: a.v[iv],
            pb: b.point_at(sb),
        };
        *best = order(x, swap);
    }
}

/// The nearest of the nine edge-edge pairs (branch-free selection of the minimum).
#[inline(always)]
fn edge_pairs(a: &TriFrame, b: &TriFrame) -> Best {
    let (d2, ij, s, t) = nearest_edge_pair(a, b);
    let (i, j) = (ij / 3, ij % 3);
    Best {
        d2,
        sa: edge_to_tri(i, s),
        sb: edge_to_tri(j, t),
        pa: a.v[i] + a.e[i] * s,
        pb: b.v[j] + b.e[j] * t,
    }
}

/// Early exit when `a` lies on one side of the (non-flat) plane of `b`: its vertex nearest
/// to the plane bounds every point of `a` from below, so if that vertex projects into `b`
/// the vertex-face pair is the closest pair.
#[inline(always)]
fn one_sided_vertex_face(a: &TriFrame, b: &TriFrame, w: &[Proj; 3], swap: bool) -> Option<Best> {
    let k = nearest_to_plane(w);
    if b.flat || straddles(w) || !w[k].inside() {
        return None;
    }
    let sb = w[k].params();
    let x = Best {
        d2: w[k].h * w[k].h * b.inv_nn,
        sa: VERTEX[k],
        sb,
        pa: a.v[k],
        pb: b.point_at(sb),
    };
    Some(order(x, swap))
}

/// Index of the vertex with the smallest |height| over the plane.
#[inline(always)]
fn nearest_to_plane(w: &[Proj; 3]) -> usize {
    let h = [w[0].h.abs(), w[1].h.abs(), w[2].h.abs()];
    let k = if h[1] < h[0] { 1 } else { 0 };
    if h[2] < h[k] {
        2
    } else {
        k
    }
}

/// Relative slack of the separation test: a vertex may lie this fraction of the triangles'
/// size beyond the plane, so the certified pair is within 2e-12 of that size from optimal.
const SEPARATION_SLACK: f64 = 1e-12;

/// Whether the plane through the closest points `pa`, `pb` of a candidate pair, normal to
/// c* = pb - pa, separates the triangles (every vertex of `a` on the side of `pa`, every
/// vertex of `b` on the side of `pb`, up to [`SEPARATION_SLACK`]). Then no pair is closer
/// than |c*| (minus that slack): the candidate is the closest pair. All six vertices are
/// tested; relying on the optimality of the edge pair for the edge end points is not safe
/// when c* is tiny and its direction is dominated by rounding.
#[inline(always)]
fn separates(a: &TriFrame, b: &TriFrame, pa: &Point3<f64>, pb: &Point3<f64>, size: f64) -> bool {
    let c = pb - pa;
    let tol = SEPARATION_SLACK * size * c.amax();
    let ha = (0..3)
        .map(|k| (a.v[k] - pa).dot(&c))
        .fold(f64::NEG_INFINITY, f64::max);
    let hb = (0..3)
        .map(|k| (b.v[k] - pb).dot(&c))
        .fold(f64::INFINITY, f64::min);
    (ha <= tol) & (hb >= -tol)
}

/// The size of two triangles for [`SEPARATION_SLACK`]: their largest edge component.
#[inline(always)]
fn size_of(a: &TriFrame, b: &TriFrame) -> f64 {
    let m = |f: &TriFrame| f.e[0].amax().max(f.e[1].amax()).max(f.e[2].amax());
    m(a).max(m(b))
}

/// Steps of [`edge_walk`] before the full enumeration takes over.
const WALK_STEPS: usize = 3;

/// The edge of a triangle to start from: of the two edges at the vertex nearest to the other
/// plane, the one whose other end is nearer too.
#[inline(always)]
fn start_edge(w: &[Proj; 3]) -> usize {
    let k = nearest_to_plane(w);
    let (next, prev) = ((k + 1) % 3, (k + 2) % 3);
    if w[next].h.abs() <= w[prev].h.abs() {
        k
    } else {
        prev
    }
}

/// The edge to move to when the third vertex of a triangle lies beyond the plane of the
/// edge pair: the edge joining that vertex to the end point nearer to the closest point.
#[inline(always)]
fn next_edge(i: usize, s: f64) -> usize {
    if s < 0.5 {
        (i + 2) % 3
    } else {
        (i + 1) % 3
    }
}

/// A few steps of a feature walk over edge pairs (PQP-style): solve one edge pair, accept it
/// if its connecting plane separates the triangles ([`separates`], which proves it globally
/// closest), else move each failing side to the edge at its offending vertex. `None` when no
/// pair is certified within [`WALK_STEPS`] steps.
#[inline(always)]
fn edge_walk(
    a: &TriFrame,
    b: &TriFrame,
    wa: &[Proj; 3],
    wb: &[Proj; 3],
    size: f64,
) -> Option<Best> {
    let (mut i, mut j) = (start_edge(wa), start_edge(wb));
    for _ in 0..WALK_STEPS {
        let (d2, s, t) = edge_pair(a, b, i, j);
        let (pa, pb) = (a.v[i] + a.e[i] * s, b.v[j] + b.e[j] * t);
        // The third vertices first: a side whose third vertex lies beyond the plane moves
        // to the edge at that vertex.
        let c = pb - pa;
        let fail_a = (a.v[(i + 2) % 3] - pa).dot(&c) > 0.0;
        let fail_b = (b.v[(j + 2) % 3] - pb).dot(&c) < 0.0;
        if !(fail_a | fail_b) {
            if !separates(a, b, &pa, &pb, size) {
                return None;
            }
            return Some(Best {
                d2,
                sa: edge_to_tri(i, s),
                sb: edge_to_tri(j, t),
                pa,
                pb,
            });
        }
        if fail_a {
            i = next_edge(i, s);
        }
        if fail_b {
            j = next_edge(j, t);
        }
    }
    None
}

/// Closest pair of two triangles; a flat triangle contributes only its edges. Cheap exits
/// first: intersection (piercing edge), a one-sided triangle over the other's face, an edge
/// pair with a separating plane; otherwise the full enumeration.
#[inline(always)]
fn enumerate(a: &TriFrame, b: &TriFrame) -> Best {
    let (wa, wb) = (project_vertices(a, b), project_vertices(b, a));
    // Non-coplanar triangles can only intersect if each straddles the other's plane (a flat
    // triangle, i.e. a segment, only has to straddle).
    let (sa, sb) = (!b.flat & straddles(&wa), !a.flat & straddles(&wb));
    if sa & (sb | a.flat) {
        if let Some(x) = piercing(a, b, &wa, false) {
            return x;
        }
    }
    if sb & (sa | b.flat) {
        if let Some(x) = piercing(b, a, &wb, true) {
            return x;
        }
    }
    if let Some(x) = one_sided_vertex_face(a, b, &wa, false) {
        return x;
    }
    if let Some(x) = one_sided_vertex_face(b, a, &wb, true) {
        return x;
    }
    let size = size_of(a, b);
    if let Some(x) = edge_walk(a, b, &wa, &wb, size) {
        return x;
    }
    let mut best = edge_pairs(a, b);
    if separates(a, b, &best.pa, &best.pb, size) {
        return best;
    }
    if !b.flat {
        vertex_face(a, b, &wa, false, &mut best);
    }
    if !a.flat {
        vertex_face(b, a, &wb, true, &mut best);
    }
    best
}

/// TT: triangle to triangle (6.4.6).
#[inline]
pub fn tt(a: &Tss, b: &Tss) -> DistanceResult {
    let (fa, fb) = (TriFrame::new(a), TriFrame::new(b));
    let r = enumerate(&fa, &fb);
    let c = Closest {
        a: r.pa,
        b: r.pb,
        param_a: PrimitiveParam::Triangle(r.sa.0, r.sa.1),
        param_b: PrimitiveParam::Triangle(r.sb.0, r.sb.1),
    };
    assemble(
        c,
        a.radius(),
        b.radius(),
        Geom::Frame(&fa),
        Geom::Frame(&fb),
    )
}

#[cfg(test)]
mod tests;
