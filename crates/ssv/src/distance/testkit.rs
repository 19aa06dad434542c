//! Test-only helpers: constructors, random inputs over many scales, a dense-sampling brute
//! force, and the duality-gap certificate that checks optimality independently.

use super::distance;
use crate::primitives::{Lss, Pss, Ssv, Tss};
use crate::result::{DistanceResult, PrimitiveParam};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

pub fn p3(a: [f64; 3]) -> Point3<f64> {
    Point3::from(a)
}
pub fn pss(p: [f64; 3], r: f64) -> Pss {
    Pss::new(p3(p), r).unwrap()
}
pub fn lss(a: [f64; 3], b: [f64; 3], r: f64) -> Lss {
    Lss::new(p3(a), p3(b), r).unwrap()
}
pub fn tss(a: [f64; 3], b: [f64; 3], c: [f64; 3], r: f64) -> Tss {
    Tss::new(p3(a), p3(b), p3(c), r).unwrap()
}
pub fn rng(seed: u64) -> StdRng {
    StdRng::seed_from_u64(seed)
}
/// A random length scale in 1e-6 ... 1e6.
pub fn log_scale(rng: &mut StdRng) -> f64 {
    10f64.powf(rng.random_range(-6.0..6.0))
}
pub fn rand_point(rng: &mut StdRng, scale: f64) -> Point3<f64> {
    Point3::new(
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
    ) * scale
}
pub fn rand_lss(rng: &mut StdRng, scale: f64) -> Lss {
    Lss::new(rand_point(rng, scale), rand_point(rng, scale), 0.0).unwrap()
}
pub fn rand_tss(rng: &mut StdRng, scale: f64) -> Tss {
    let (a, b, c) = (
        rand_point(rng, scale),
        rand_point(rng, scale),
        rand_point(rng, scale),
    );
    Tss::new(a, b, c, 0.0).unwrap()
}
pub fn rand_pose(rng: &mut StdRng, scale: f64) -> Isometry3<f64> {
    let q = UnitQuaternion::from_scaled_axis(
        Vector3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        ) * 3.0,
    );
    Isometry3::from_parts(Translation3::from(rand_point(rng, scale).coords), q)
}

/// Largest coordinate or radius magnitude involved.
pub fn scale_of(a: &Ssv, b: &Ssv) -> f64 {
    let m = a
        .vertices()
        .iter()
        .chain(b.vertices())
        .map(|v| v.coords.amax());
    m.fold(a.radius().max(b.radius()), f64::max)
}

/// Point of a primitive at a parameter.
pub fn eval(s: &Ssv, p: &PrimitiveParam) -> Point3<f64> {
    match (s, *p) {
        (Ssv::Point(x), PrimitiveParam::Point) => *x.center(),
        (Ssv::Line(l), PrimitiveParam::Line(t)) => l.point_at(t),
        (Ssv::Triangle(t), PrimitiveParam::Triangle(a, b)) => t.point_at(a, b),
        _ => panic!("parameter kind {p:?} does not match primitive"),
    }
}

fn in_domain(p: &PrimitiveParam) -> bool {
    match *p {
        PrimitiveParam::Point => true,
        PrimitiveParam::Line(s) => (0.0..=1.0).contains(&s),
        PrimitiveParam::Triangle(a, b) => a >= 0.0 && b >= 0.0 && a + b <= 1.0 + 1e-15,
    }
}

/// Minimum of |S_b(x) - S_a(y)| over an n-per-dimension parameter grid.
pub fn brute_force(a: &Ssv, b: &Ssv, n: usize) -> f64 {
    let pa = samples(a, n);
    let pb = samples(b, n);
    let mut best = f64::INFINITY;
    for x in &pa {
        for y in &pb {
            best = best.min((x - y).norm());
        }
    }
    best - a.radius() - b.radius()
}

fn samples(s: &Ssv, n: usize) -> Vec<Point3<f64>> {
    let k = |i: usize| i as f64 / n as f64;
    match s {
        Ssv::Point(p) => vec![*p.center()],
        Ssv::Line(l) => (0..=n).map(|i| l.point_at(k(i))).collect(),
        Ssv::Triangle(t) => {
            let mut v = Vec::new();
            for i in 0..=n {
                for j in 0..=(n - i) {
                    v.push(t.point_at(k(i), k(j)));
                }
            }
            v
        }
    }
}

/// Lower bound on the primitive distance from the separating direction n (weak duality):
/// min_b n.b - max_a n.a over the vertices.
pub fn dual_bound(a: &Ssv, b: &Ssv, n: &Vector3<f64>) -> f64 {
    let hi = a
        .vertices()
        .iter()
        .map(|v| n.dot(&v.coords))
        .fold(f64::MIN, f64::max);
    let lo = b
        .vertices()
        .iter()
        .map(|v| n.dot(&v.coords))
        .fold(f64::MAX, f64::min);
    lo - hi
}

/// Structural checks of a result plus, when |c*| is not tiny, the duality-gap certificate
/// |c*| - dual_bound <= tol (an independent proof of optimality).
pub fn check_result(r: &DistanceResult, a: &Ssv, b: &Ssv, scale: f64) {
    check_result_tol(r, a, b, scale, 1e-11)
}

/// [`check_result`] with a relative duality-gap tolerance (near-degenerate families).
pub fn check_result_tol(r: &DistanceResult, a: &Ssv, b: &Ssv, scale: f64, gap_tol: f64) {
    let tol = 1e-12 * scale;
    assert!(in_domain(&r.param_a) && in_domain(&r.param_b), "{r:?}");
    assert!((eval(a, &r.param_a) - r.closest_a).norm() <= tol, "{r:?}");
    assert!((eval(b, &r.param_b) - r.closest_b).norm() <= tol, "{r:?}");
    assert!((r.normal.norm() - 1.0).abs() < 1e-14, "{r:?}");
    let c = r.c_star().norm();
    assert!(
        (r.distance - (c - a.radius() - b.radius())).abs() <= tol,
        "{r:?}"
    );
    assert!((r.point_a - (r.closest_a + r.normal * a.radius())).norm() <= tol);
    assert!((r.point_b - (r.closest_b - r.normal * b.radius())).norm() <= tol);
    if c > 1e-4 * scale {
        let gap = c - dual_bound(a, b, &r.normal);
        assert!(
            gap <= gap_tol * scale,
            "gap {gap:e} scale {scale:e} {a:?} {b:?} {r:?}"
        );
    }
    let rev = distance(b, a);
    assert!(
        (rev.distance - r.distance).abs() <= tol,
        "swap {r:?} {rev:?}"
    );
}

/// Checks that a rigid motion of both SSVs leaves the distance unchanged.
pub fn check_rigid(a: &Ssv, b: &Ssv, pose: &Isometry3<f64>, scale: f64) {
    let d0 = distance(a, b).distance;
    let d1 = distance(&a.transformed(pose), &b.transformed(pose)).distance;
    assert!((d0 - d1).abs() <= 1e-11 * scale, "{d0} vs {d1}");
}
