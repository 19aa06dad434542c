//! PT: point-swept sphere to triangle-swept sphere, (6.19)-(6.22) and Table 6.2.
//!
//! The plane projection (6.21) is solved by the backward-stable QR scheme of [`TriFrame`]. In
//! region 0 of Table 6.2 the projection is the answer; outside, the closest point lies on an
//! edge whose constraint (6.6) is violated (in the vertex regions 1, 3, 5 that is not always
//! the vertex itself: for obtuse triangles it can be inside an edge). Since the region test
//! of a sliver is ill-conditioned, all three edges (PL) are evaluated and the nearest taken,
//! which is exact whatever region the rounded projection reports. A flat triangle (see
//! [`TriFrame`]) has no face candidate: it is the union of its edges, i.e. its longest edge.
//!
//! Well-shaped triangles (the common case) take a cheaper exact path first: the Voronoi
//! regions of Table 6.2 classified by dot products with early returns (vertex, edge, face),
//! whose barycentric numerators are well conditioned for such triangles.

use super::assemble::{assemble, edge_to_tri, key_index, min_key, Closest, Geom};
use super::point_line::point_segment_param_pre;
use super::triangle_frame::TriFrame;
use crate::primitives::{Pss, Tss};
use crate::result::{DistanceResult, PrimitiveParam};
use nalgebra::Point3;

/// Triangle parameters (s0, s1) of the point of `f` closest to `p`.
#[inline(always)]
pub(crate) fn point_triangle_params(p: &Point3<f64>, f: &TriFrame) -> (f64, f64) {
    let w = f.project(p);
    if !f.flat & w.inside() {
        return w.params();
    }
    let mut s = [0.0; 3];
    let mut key = u64::MAX;
    for (k, sk) in s.iter_mut().enumerate() {
        *sk = point_segment_param_pre(p, &f.v[k], &f.e[k], f.inv_ee[k]);
        key = key.min(min_key((p - (f.v[k] + f.e[k] * *sk)).norm_squared(), k));
    }
    let k = key_index(key);
    edge_to_tri(k, s[k])
}

/// Shape threshold of the Voronoi classification: a triangle with 4 area^2 above this times
/// l_max^4 (every angle at least ~0.6 degrees) has barycentric coordinates that lose at most
/// about two digits; thinner ones take the QR path.
const WELL_SHAPED: f64 = 1e-4;

/// Table 6.2 as Voronoi regions of a well-shaped triangle, with early returns: vertex
/// regions from the two dot products with the adjacent edges, edge regions from the sign of
/// the opposite barycentric numerator, the face last; one division on every path (correct for
/// obtuse triangles: a region is only taken when its own conditions hold). `None` for
/// triangles that are not well shaped.
#[inline(always)]
fn voronoi_params(p: &Point3<f64>, t: &Tss) -> Option<(f64, f64)> {
    let [v0, v1, v2] = t.vertices();
    let (ab, ac, ap) = (v1 - v0, v2 - v0, p - v0);
    let (aa, cc, x) = (ab.norm_squared(), ac.norm_squared(), ab.dot(&ac));
    let area4 = aa * cc - x * x;
    let lmax = aa.max(cc).max(aa + cc - 2.0 * x);
    if area4 <= WELL_SHAPED * lmax * lmax {
        return None;
    }
    let (d1, d2) = (ab.dot(&ap), ac.dot(&ap));
    if (d1 <= 0.0) & (d2 <= 0.0) {
        return Some((0.0, 0.0));
    }
    // Dot products of the edges with p - v1 and p - v2.
    let (d3, d4, d5, d6) = (d1 - aa, d2 - x, d1 - x, d2 - cc);
    if (d3 >= 0.0) & (d4 <= d3) {
        return Some((1.0, 0.0));
    }
    if (d6 >= 0.0) & (d5 <= d6) {
        return Some((0.0, 1.0));
    }
    // Barycentric numerators (times 4 area^2) of v2, v1 and v0.
    let vc = aa * d2 - x * d1;
    if (vc <= 0.0) & (d1 >= 0.0) & (d3 <= 0.0) {
        return Some((d1 / (d1 - d3), 0.0));
    }
    let vb = cc * d1 - x * d2;
    if (vb <= 0.0) & (d2 >= 0.0) & (d6 <= 0.0) {
        return Some((0.0, d2 / (d2 - d6)));
    }
    let va = area4 - vb - vc;
    let (g, h) = (d4 - d3, d5 - d6);
    if (va <= 0.0) & (g >= 0.0) & (h >= 0.0) {
        let w = g / (g + h);
        return Some((1.0 - w, w));
    }
    let r = 1.0 / area4;
    Some((vb * r, vc * r))
}

/// PT: point to triangle, (6.19)-(6.22) and Table 6.2.
#[inline]
pub fn pt(a: &Pss, b: &Tss) -> DistanceResult {
    let s = match voronoi_params(a.center(), b) {
        Some(s) => s,
        None => point_triangle_params(a.center(), &TriFrame::new(b)),
    };
    let c = Closest {
        a: *a.center(),
        b: b.point_at(s.0, s.1),
        param_a: PrimitiveParam::Point,
        param_b: PrimitiveParam::Triangle(s.0, s.1),
    };
    assemble(c, a.radius(), b.radius(), Geom::Point, Geom::Triangle(b))
}

#[cfg(test)]
mod tests {
    use super::super::testkit::*;
    use super::*;
    use crate::primitives::Ssv;
    use nalgebra::Vector3;

    #[test]
    fn all_seven_regions_of_fig_6_3() {
        let t = tss([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], 0.0);
        let cases = [
            ([0.5, 0.5, 3.0], (0.25, 0.25), 3.0),         // 0: face
            ([-1.0, -1.0, 0.0], (0.0, 0.0), 2f64.sqrt()), // 1: v0
            ([1.0, -2.0, 0.0], (0.5, 0.0), 2.0),          // 2: edge v0v1
            ([3.0, -1.0, 0.0], (1.0, 0.0), 2f64.sqrt()),  // 3: v1
            ([2.0, 2.0, 0.0], (0.5, 0.5), 2f64.sqrt()),   // 4: edge v1v2
            ([-1.0, 3.0, 0.0], (0.0, 1.0), 2f64.sqrt()),  // 5: v2
            ([-4.0, 1.0, 0.0], (0.0, 0.5), 4.0),          // 6: edge v2v0
        ];
        for (p, s, d) in cases {
            let r = pt(&pss(p, 0.0), &t);
            assert!((r.distance - d).abs() < 1e-15, "{p:?} {r:?}");
            let PrimitiveParam::Triangle(a, b) = r.param_b else {
                panic!()
            };
            assert!(
                (a - s.0).abs() < 1e-15 && (b - s.1).abs() < 1e-15,
                "{p:?} {r:?}"
            );
        }
    }

    #[test]
    fn obtuse_vertex_region_needs_an_edge() {
        // Obtuse at v0: a point with s0 < 0 and s1 < 0 whose closest point is inside edge v0v2.
        let t = tss([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [-3.0, 1.0, 0.0], 0.0);
        let p = pss([-1.0, -0.5, 0.0], 0.0);
        let r = pt(&p, &t);
        let brute = brute_force(&p.into(), &t.into(), 2000);
        assert!((r.distance - brute).abs() < 1e-6, "{r:?} {brute}");
        let PrimitiveParam::Triangle(a, b) = r.param_b else {
            panic!()
        };
        assert!(a == 0.0 && b > 0.0 && b < 1.0, "{r:?}");
    }

    #[test]
    fn point_in_face_uses_triangle_normal() {
        let t = tss([0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0], 0.5);
        let r = pt(&pss([0.25, 0.25, 1.0], 0.5), &t);
        assert_eq!(r.distance, -1.0);
        assert!((r.normal - Vector3::z()).norm() < 1e-15);
    }

    #[test]
    fn flat_triangles_are_their_longest_edge() {
        let p = pss([1.0, 1.0, 0.0], 0.0);
        // Collinear: v1 in the middle, longest edge v2v0.
        let col = tss([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [3.0, 0.0, 0.0], 0.0);
        let r = pt(&p, &col);
        assert!((r.distance - 1.0).abs() < 1e-15, "{r:?}");
        assert!((r.closest_b - p3([1.0, 0.0, 0.0])).norm() < 1e-15);
        // All three vertices coincident.
        let dot = tss([2.0, 1.0, 0.0], [2.0, 1.0, 0.0], [2.0, 1.0, 0.0], 0.0);
        assert!((pt(&p, &dot).distance - 1.0).abs() < 1e-15);
        // Point on the flat triangle: unit(e x y) for the longest edge e = v0 - v2 = -x.
        let on = pt(&pss([2.0, 0.0, 0.0], 0.0), &col);
        assert_eq!(on.distance, 0.0);
        assert!((on.normal + Vector3::z()).norm() < 1e-15, "{on:?}");
    }

    #[test]
    fn random_against_certificate_brute_force_and_motion() {
        let mut rng = rng(21);
        for i in 0..3000 {
            let scale = log_scale(&mut rng);
            let a: Ssv = Pss::new(rand_point(&mut rng, scale), 0.0).unwrap().into();
            let b: Ssv = rand_tss(&mut rng, scale).into();
            let r = distance(&a, &b);
            check_result(&r, &a, &b, scale_of(&a, &b));
            if i % 10 == 0 {
                let brute = brute_force(&a, &b, 200);
                assert!(r.distance <= brute + 1e-12 * scale);
                assert!(brute - r.distance <= 0.02 * scale);
                check_rigid(&a, &b, &rand_pose(&mut rng, scale), 4.0 * scale);
            }
        }
    }

    /// Slivers: the third vertex a relative height 10^-k off the first edge.
    #[test]
    fn slivers_and_near_flat_triangles() {
        let mut rng = rng(22);
        for k in 0..=16 {
            for _ in 0..100 {
                let scale = log_scale(&mut rng);
                let v0 = rand_point(&mut rng, scale);
                let e = rand_point(&mut rng, scale).coords;
                let off = rand_point(&mut rng, scale).coords * 10f64.powi(-k);
                let v2 = v0 + e * rand::Rng::random_range(&mut rng, -0.5..1.5) + off;
                let b: Ssv = Tss::new(v0, v0 + e, v2, 0.0).unwrap().into();
                let a: Ssv = Pss::new(rand_point(&mut rng, scale), 0.0).unwrap().into();
                let r = distance(&a, &b);
                check_result_tol(&r, &a, &b, scale_of(&a, &b), 2e-10);
            }
        }
    }

    use super::super::distance;
}
