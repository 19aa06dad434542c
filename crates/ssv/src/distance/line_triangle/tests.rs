use super::super::distance;
use super::super::testkit::*;
use super::*;
use crate::primitives::Ssv;

fn unit_tri(r: f64) -> Tss {
    tss([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], r)
}

#[test]
fn hand_derived_configurations() {
    let t = unit_tri(0.0);
    // Vertical segment above the face: end point over face.
    let r = lt(&lss([0.5, 0.5, 1.0], [0.5, 0.5, 3.0], 0.0), &t);
    assert!((r.distance - 1.0).abs() < 1e-15);
    assert_eq!(r.param_a, PrimitiveParam::Line(0.0));
    // Segment parallel to the face, above it: any point of the overlap, distance 2.
    let r = lt(&lss([-1.0, 0.5, 2.0], [3.0, 0.5, 2.0], 0.0), &t);
    assert!((r.distance - 2.0).abs() < 1e-15, "{r:?}");
    // Skew to edge v1v2 outside the triangle: edge-edge pair.
    let r = lt(&lss([2.0, 2.0, -1.0], [2.0, 2.0, 1.0], 0.0), &t);
    assert!((r.distance - 2f64.sqrt()).abs() < 1e-15, "{r:?}");
    assert_eq!(r.param_a, PrimitiveParam::Line(0.5));
}

#[test]
fn piercing_segment_has_zero_distance_and_face_normal() {
    let t = unit_tri(0.2);
    let r = lt(&lss([0.5, 0.25, -1.0], [0.5, 0.25, 3.0], 0.1), &t);
    assert_eq!(r.c_star().norm(), 0.0);
    assert!((r.distance + 0.3).abs() < 1e-15);
    assert!((r.normal - nalgebra::Vector3::z()).norm() < 1e-15);
    assert_eq!(r.param_a, PrimitiveParam::Line(0.25));
    assert!((r.closest_a - p3([0.5, 0.25, 0.0])).norm() < 1e-15);
    // Oblique piercing.
    let r = lt(&lss([0.0, 0.0, -1.0], [1.0, 1.0, 1.0], 0.0), &t);
    assert_eq!(r.c_star().norm(), 0.0);
    assert!((r.closest_b - p3([0.5, 0.5, 0.0])).norm() < 1e-15);
}

#[test]
fn segment_in_the_triangle_plane() {
    let t = unit_tri(0.0);
    let r = lt(&lss([0.2, 0.2, 0.0], [0.5, 0.3, 0.0], 0.0), &t);
    assert!(r.distance.abs() < 1e-15);
    let r = lt(&lss([-1.0, 1.0, 0.0], [-3.0, 1.0, 0.0], 0.0), &t);
    assert!((r.distance - 1.0).abs() < 1e-15);
    let r = lt(&lss([-1.0, 1.0, 0.0], [3.0, 1.0, 0.0], 0.0), &t);
    assert!(r.distance.abs() < 1e-15);
}

#[test]
fn degenerate_inputs() {
    let t = unit_tri(0.0);
    let dot = lss([0.5, 0.5, 2.0], [0.5, 0.5, 2.0], 0.0);
    assert!((lt(&dot, &t).distance - 2.0).abs() < 1e-15);
    let col = tss([0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0], 0.0);
    let r = lt(&lss([0.0, 2.0, 0.0], [2.0, 0.0, 0.0], 0.0), &col);
    let want = ll_dist([0.0, 2.0, 0.0], [2.0, 0.0, 0.0], [0.0; 3], [2.0; 3]);
    assert!((r.distance - want).abs() < 1e-15, "{r:?} {want}");
}

fn ll_dist(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> f64 {
    super::super::ll(&lss(a, b, 0.0), &lss(c, d, 0.0)).distance
}

#[test]
fn random_against_certificate_brute_force_and_motion() {
    let mut rng = rng(31);
    for i in 0..3000 {
        let scale = log_scale(&mut rng);
        let a: Ssv = rand_lss(&mut rng, scale).into();
        let b: Ssv = rand_tss(&mut rng, scale).into();
        let r = distance(&a, &b);
        check_result(&r, &a, &b, scale_of(&a, &b));
        if i % 20 == 0 {
            let brute = brute_force(&a, &b, 80);
            assert!(r.distance <= brute + 1e-12 * scale);
            assert!(brute - r.distance <= 0.05 * scale);
            check_rigid(&a, &b, &rand_pose(&mut rng, scale), 4.0 * scale);
        }
    }
}

/// Segments nearly parallel to the plane and slivers.
#[test]
fn near_parallel_and_sliver_certificate() {
    let mut rng = rng(32);
    for k in 0..=16 {
        for _ in 0..100 {
            let scale = log_scale(&mut rng);
            let tri = rand_tss(&mut rng, scale);
            let [v0, v1, v2] = *tri.vertices();
            let n = (v1 - v0).cross(&(v2 - v0)).normalize();
            let p = rand_point(&mut rng, scale);
            let d = (v1 - v0) * rand::Rng::random_range(&mut rng, -2.0..2.0)
                + (v2 - v0) * rand::Rng::random_range(&mut rng, -2.0..2.0)
                + n * scale * 10f64.powi(-k);
            let a: Ssv = Lss::new(p, p + d, 0.0).unwrap().into();
            let sliver = Tss::new(
                v0,
                v1,
                v0 + (v1 - v0) * 0.3 + n * scale * 10f64.powi(-k),
                0.0,
            );
            for b in [tri, sliver.unwrap()] {
                let b: Ssv = b.into();
                let r = distance(&a, &b);
                check_result_tol(&r, &a, &b, scale_of(&a, &b), 2e-10);
            }
        }
    }
}
