//! PL: point-swept sphere to line-swept sphere, eqs. (6.13)-(6.18).

use super::assemble::{assemble, clamp01, inv_or_zero, Closest, Geom};
use crate::primitives::{Lss, Pss};
use crate::result::{DistanceResult, PrimitiveParam};
use nalgebra::{Point3, Vector3};

/// Segment parameter s* of (6.17) of the point on `a + s e` closest to `p`
/// (a zero-length segment gives s* = 0, i.e. it behaves as a point).
#[inline(always)]
pub(crate) fn point_segment_param(p: &Point3<f64>, a: &Point3<f64>, e: &Vector3<f64>) -> f64 {
    point_segment_param_pre(p, a, e, inv_or_zero(e.norm_squared()))
}

/// [`point_segment_param`] with the precomputed 1/|e|^2 (0 for a zero-length segment).
#[inline(always)]
pub(crate) fn point_segment_param_pre(
    p: &Point3<f64>,
    a: &Point3<f64>,
    e: &Vector3<f64>,
    inv_ee: f64,
) -> f64 {
    clamp01((p - a).dot(e) * inv_ee)
}

/// PL: point to line segment, eqs. (6.13)-(6.17).
#[inline]
pub fn pl(a: &Pss, b: &Lss) -> DistanceResult {
    let [v0, v1] = b.vertices();
    let s = point_segment_param(a.center(), v0, &(v1 - v0));
    let c = Closest {
        a: *a.center(),
        b: b.point_at(s),
        param_a: PrimitiveParam::Point,
        param_b: PrimitiveParam::Line(s),
    };
    assemble(c, a.radius(), b.radius(), Geom::Point, Geom::Line(b))
}

#[cfg(test)]
mod tests {
    use super::super::testkit::*;
    use super::*;

    #[test]
    fn three_regions_of_fig_6_2() {
        let l = lss([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], 0.1);
        for (p, s, d) in [
            ([-1.0, 1.0, 0.0], 0.0, 2f64.sqrt()),
            ([1.0, 0.0, 3.0], 0.5, 3.0),
            ([4.0, 0.0, 0.0], 1.0, 2.0),
        ] {
            let r = pl(&pss(p, 0.2), &l);
            assert_eq!(r.param_b, PrimitiveParam::Line(s));
            assert!((r.distance - (d - 0.3)).abs() < 1e-15);
        }
    }

    #[test]
    fn point_on_segment_uses_line_perpendicular() {
        let r = pl(
            &pss([1.0, 0.0, 0.0], 0.0),
            &lss([0.0; 3], [2.0, 0.0, 0.0], 0.0),
        );
        assert_eq!(r.distance, 0.0);
        assert!((r.normal - Vector3::z()).norm() < 1e-15);
    }

    #[test]
    fn zero_length_segment_is_a_point() {
        let r = pl(&pss([0.0, 3.0, 4.0], 0.0), &lss([0.0; 3], [0.0; 3], 1.0));
        assert_eq!(r.param_b, PrimitiveParam::Line(0.0));
        assert!((r.distance - 4.0).abs() < 1e-15);
    }

    #[test]
    fn matches_dense_sampling_and_certificate() {
        let mut rng = rng(11);
        for _ in 0..2000 {
            let scale = log_scale(&mut rng);
            let a = Pss::new(rand_point(&mut rng, scale), 0.0).unwrap();
            let b = rand_lss(&mut rng, scale);
            let r = pl(&a, &b);
            check_result(&r, &a.into(), &b.into(), scale);
            let brute = brute_force(&a.into(), &b.into(), 400);
            assert!(r.distance <= brute + 1e-12 * scale);
        }
    }
}
