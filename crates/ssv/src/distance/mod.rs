//! The distance functions of Table 6.1 (6.4.1-6.4.6) and the dispatch over [`Ssv`].
//!
//! Every function returns the signed distance `d = |c*| - r_a - r_b` (negative on overlap),
//! the closest points `closest_a`/`closest_b` on the underlying primitives with their
//! parameters ((6.4)-(6.6), always inside their domain), the surface points of (6.11) and
//! the unit normal from a to b. The algorithms are exact up to rounding for all inputs
//! (tested against a duality-gap certificate to 1e-11 of the coordinate scale; a triangle
//! treated as flat is within 1e-10 of its size from its edges), use only relative (scale
//! invariant) degeneracy tests and never produce NaN:
//! * LL takes the infinite-line solution (6.31) from the normal equations where the
//!   scale-invariant test (6.34) shows them well conditioned, and otherwise from components
//!   orthogonal to one edge (QR, exact in the parallel limit, no parallel table needed); the
//!   two saturation steps of Tables 6.3/6.4 are clamp-and-recompute;
//! * PT projects onto the plane (6.21) by QR with back substitution (backward stable for
//!   slivers) and otherwise takes the nearest of the three edges (exact in every region of
//!   Table 6.2, including obtuse vertex regions); LT and TT enumerate edge-edge pairs, vertex-face projections and the
//!   edge-piercing test, evaluating every candidate exactly and selecting without branches;
//! * a zero-length segment behaves as a point, a flat triangle (angle at v0 with
//!   sin^2 <= 1e-20, which includes collinear and coincident vertices) as the union of its
//!   edges, i.e. its longest edge.
//!
//! # Normal rule
//! If |c*| > 0 the normal is n = c*/|c*| (computed with rescaling, so it stays unit even for
//! |c*| near the underflow limit). If c* = 0 (the primitives touch or intersect) n is taken
//! from the geometry, in order of preference:
//! 1. the unit normal `unit(e0 x e1)` of triangle b if b is a non-flat triangle, else of
//!    triangle a if a is a non-flat triangle;
//! 2. `unit(e_a x e_b)` for two non-parallel lines (a flat triangle counts as its longest
//!    edge; parallel means sin^2 of the angle <= 1e-20);
//! 3. a unit vector perpendicular to the first non-zero line direction e (a's, else b's): `unit(e x axis_k)` with axis_k the coordinate axis of the smallest |e_k|;
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
///
/// # Example
///
/// A horizontal capsule 2 m above a rounded plate (triangle in the `z = 0` plane), both of
/// radius 0.5: the capsule's axis lies above the triangle's interior, so by hand
/// `d = 2 - 0.5 - 0.5 = 1`, the normal points straight up and the closest point on the plate
/// is the foot of the perpendicular.
///
/// ```
/// use biped_ssv::{distance, Lss, Ssv, Tss};
/// use nalgebra::{Point3, Vector3};
///
/// let arm = Lss::new(Point3::new(0.1, 0.1, 2.0), Point3::new(0.2, 0.1, 2.0), 0.5)?;
/// let plate = Tss::new(
///     Point3::origin(), Point3::new(1.0, 0.0, 0.0), Point3::new(0.0, 1.0, 0.0), 0.5,
/// )?;
/// let r = distance(&Ssv::from(plate), &Ssv::from(arm));
/// assert!((r.distance - 1.0).abs() < 1e-12);
/// assert!((r.normal - Vector3::z()).norm() < 1e-12);
/// assert!(r.closest_a.z.abs() < 1e-12 && (r.closest_a.y - 0.1).abs() < 1e-12);
/// assert!((r.connecting() - r.normal * r.distance).norm() < 1e-12);
/// # Ok::<(), biped_ssv::SsvError>(())
/// ```
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

#[cfg(test)]
mod tests {
    use super::testkit::*;
    use super::*;
    use crate::primitives::{Lss, Pss, Tss};
    use nalgebra::Point3;
    use rand::Rng;

    /// All nine pair types on a coarse lattice (many coincident, collinear and coplanar
    /// vertices) at scales 1e-6, 1 and 1e6: finite, certified results and swap symmetry.
    #[test]
    fn lattice_degeneracies_all_pair_types() {
        let mut rng = rng(99);
        for &scale in &[1e-6, 1.0, 1e6] {
            let pick = |rng: &mut rand::rngs::StdRng| {
                let c = |rng: &mut rand::rngs::StdRng| rng.random_range(0..3) as f64 * scale;
                Point3::new(c(rng), c(rng), c(rng))
            };
            for _ in 0..3000 {
                let make = |kind: u32, rng: &mut rand::rngs::StdRng| -> Ssv {
                    let r = rng.random_range(0..2) as f64 * 0.1 * scale;
                    match kind {
                        0 => Pss::new(pick(rng), r).unwrap().into(),
                        1 => Lss::new(pick(rng), pick(rng), r).unwrap().into(),
                        _ => Tss::new(pick(rng), pick(rng), pick(rng), r).unwrap().into(),
                    }
                };
                let (ka, kb) = (rng.random_range(0..3), rng.random_range(0..3));
                let (a, b) = (make(ka, &mut rng), make(kb, &mut rng));
                let r = distance(&a, &b);
                let all = [
                    r.distance,
                    r.normal.x,
                    r.normal.y,
                    r.normal.z,
                    r.point_a.x,
                    r.point_b.z,
                ];
                assert!(all.iter().all(|x| x.is_finite()), "{a:?} {b:?} {r:?}");
                check_result(&r, &a, &b, scale_of(&a, &b).max(scale));
                let brute = brute_force(&a, &b, 24);
                assert!(
                    r.distance <= brute + 1e-12 * scale,
                    "{a:?} {b:?} {r:?} {brute}"
                );
            }
        }
    }

    #[test]
    fn normal_rule_for_a_segment_through_a_flat_triangle() {
        // Flat triangle along x (longest edge), segment along y crossing it: unit(e_a x e_b).
        let flat = tss([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [1.0, 0.0, 0.0], 0.0);
        let seg = lss([1.5, -1.0, 0.0], [1.5, 1.0, 0.0], 0.0);
        let r = lt(&seg, &flat);
        assert_eq!(r.c_star().norm(), 0.0);
        // e_a = +y, e_b = longest edge v2 - v1... = (v0 - v2) direction or (v1 - v0): +-x.
        assert!((r.normal.z.abs() - 1.0).abs() < 1e-15, "{r:?}");
        let again = lt(&seg, &flat);
        assert_eq!(again, r);
    }
}
