//! The distance functions of Table 6.1 (6.4.1-6.4.6) and the dispatch over [`Ssv`].
//!
//! Every function returns the signed distance `d = |c*| - r_a - r_b` (negative on overlap),
//! the closest points `closest_a`/`closest_b` on the underlying primitives with their
//! parameters ((6.4)-(6.6), always inside their domain), the surface points of (6.11) and
//! the unit normal from a to b. The algorithms are exact for all inputs, use only relative
//! (scale invariant) degeneracy tests and never produce NaN:
//! * LL solves the infinite-line problem from components orthogonal to one edge (no normal
//!   equations, no parallel epsilon) and saturates in two clamp-and-recompute steps;
//! * PT projects with a precomputed dual basis and resolves the regions of Table 6.2 on the
//!   violated edges; LT and TT enumerate edge-edge pairs, vertex-face projections and the
//!   edge-piercing test, evaluating every candidate exactly;
//! * a zero-length segment behaves as a point, a flat triangle (angle at v0 with
//!   sin^2 <= 1e-20, which includes collinear and coincident vertices) as its longest edge.
//!
//! # Normal rule
//! If |c*| > 0 the normal is n = c*/|c*| (computed with rescaling, so it stays unit even for
//! |c*| near the underflow limit). If c* = 0 (the primitives touch or intersect) n is taken
//! from the geometry, in order of preference:
//! 1. the unit normal `unit(e0 x e1)` of triangle b if b is a non-flat triangle, else of
//!    triangle a if a is a non-flat triangle;
//! 2. `unit(e_a x e_b)` for two non-parallel lines (a flat triangle counts as its longest
//!    edge; parallel means sin^2 of the angle <= 1e-20);
//! 3. a unit vector perpendicular to the first non-degenerate line direction e (a's, else
//!    b's): `unit(e x axis_k)` with axis_k the coordinate axis of the smallest |e_k|;
//! 4. otherwise (all points) `+z = (0, 0, 1)`.
//!
//! Then `point_a = closest_a + r_a n` and `point_b = closest_b - r_b n`. When a segment edge
//! pierces a triangle, `closest_a` and `closest_b` are set to the same piercing point, so
//! c* = 0 exactly and the rule applies.

mod assemble;
mod edge_pairs;
mod line_line;
mod line_triangle;
mod point_line;
mod point_point;
mod point_triangle;
#[cfg(test)]
mod testkit;
mod triangle_frame;
mod triangle_triangle;

pub use line_line::ll;
pub use line_triangle::lt;
pub use point_line::pl;
pub use point_point::pp;
pub use point_triangle::pt;
pub use triangle_triangle::tt;

use crate::primitives::Ssv;
use crate::result::DistanceResult;

/// Distance between any two SSVs; the lower-triangle pairs of Table 6.1 use the swap relation.
#[inline]
pub fn distance(a: &Ssv, b: &Ssv) -> DistanceResult {
    match (a, b) {
        (Ssv::Point(a), Ssv::Point(b)) => pp(a, b),
        (Ssv::Point(a), Ssv::Line(b)) => pl(a, b),
        (Ssv::Point(a), Ssv::Triangle(b)) => pt(a, b),
        (Ssv::Line(a), Ssv::Point(b)) => pl(b, a).swapped(),
        (Ssv::Line(a), Ssv::Line(b)) => ll(a, b),
        (Ssv::Line(a), Ssv::Triangle(b)) => lt(a, b),
        (Ssv::Triangle(a), Ssv::Point(b)) => pt(b, a).swapped(),
        (Ssv::Triangle(a), Ssv::Line(b)) => lt(b, a).swapped(),
        (Ssv::Triangle(a), Ssv::Triangle(b)) => tt(a, b),
    }
}
