//! Self-tests of the KKT reference solver in `tests/reference/mod.rs`: hand-derived
//! configurations, dense sampling with local refinement, and its duality certificate.

mod reference;

use nalgebra::{Point3, Vector3};
use proptest::prelude::*;
use reference::{certified_gap, closest, point, Closest};

fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}

/// Largest absolute coordinate (at least 1): the scale of rounding errors.
fn scale(a: &[Point3<f64>], b: &[Point3<f64>]) -> f64 {
    a.iter()
        .chain(b)
        .flat_map(|v| v.iter().copied())
        .fold(1.0, |m, x| m.max(x.abs()))
}

/// Checks that `sol` is feasible and self-consistent, and that its certificate is tight.
fn check_solution(a: &[Point3<f64>], b: &[Point3<f64>], sol: &Closest) {
    let tol = 1e-12 * scale(a, b);
    for (v, w, q) in [(a, sol.bary_a, sol.point_a), (b, sol.bary_b, sol.point_b)] {
        assert!(w.iter().all(|&x| x >= 0.0), "weights {w:?}");
        assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-14, "weights {w:?}");
        assert!(w[v.len()..].iter().all(|&x| x == 0.0), "weights {w:?}");
        assert!((point(v, &w) - q).norm() <= tol);
    }
    assert!(((sol.point_b - sol.point_a).norm() - sol.dist).abs() <= tol);
    // The certificate's direction `(point_b - point_a) / dist` carries a rounding error of
    // ~eps * scale / dist, which the bound multiplies by the simplices' extent: near contact
    // (dist 3e-6 at scale 2 gave a gap of 1.1e-9) the tolerance grows as scale^2 / dist.
    let gap = certified_gap(a, b, sol);
    let s = scale(a, b);
    assert!(
        gap <= 1e-10 * s + 1e-14 * s * s / sol.dist.max(f64::MIN_POSITIVE),
        "gap {gap} for {a:?} {b:?} {sol:?}"
    );
}

/// Checks the reference distance of a hand-derived configuration.
fn expect(a: &[Point3<f64>], b: &[Point3<f64>], d: f64) -> Closest {
    let sol = closest(a, b);
    check_solution(a, b, &sol);
    assert!(
        (sol.dist - d).abs() < 1e-14,
        "{} != {d} for {a:?} {b:?}",
        sol.dist
    );
    let back = closest(b, a);
    assert!(
        (back.dist - d).abs() < 1e-14,
        "swapped: {} != {d}",
        back.dist
    );
    sol
}

#[test]
fn hand_derived_point_cases() {
    // 3-4-5 right triangle: |(3,4,0)| = 5.
    let s = expect(&[p(0., 0., 0.)], &[p(3., 4., 0.)], 5.0);
    assert_eq!(s.point_b, p(3., 4., 0.));
    // Point above segment interior: foot (1,0,0), distance 2.
    let seg = [p(-1., 0., 0.), p(3., 0., 0.)];
    let s = expect(&[p(1., 2., 0.)], &seg, 2.0);
    assert!((s.point_b - p(1., 0., 0.)).norm() < 1e-15);
    // Point beyond the end (5,0,0)->(3,0,0) with lateral 3: sqrt(2^2+3^2)... use 3-4-5.
    let s = expect(&[p(7., 3., 0.)], &seg, 5.0);
    assert!((s.point_b - seg[1]).norm() < 1e-15);
    // Point above the triangle interior, height 2.5.
    let tri = [p(0., 0., 0.), p(4., 0., 0.), p(0., 4., 0.)];
    let s = expect(&[p(1., 1., 2.5)], &tri, 2.5);
    assert!((s.point_b - p(1., 1., 0.)).norm() < 1e-15);
    // Point outside the hypotenuse x + y = 4 in the plane: foot (2,2,0), distance 3*sqrt(2)/... :
    // (5,5,0) - (2,2,0) = (3,3,0), length 3 sqrt 2.
    expect(&[p(5., 5., 0.)], &tri, 3.0 * 2f64.sqrt());
    // Point beyond vertex (4,0,0) in the direction (3,-4,0)/5 * 5: nearest is the vertex.
    let s = expect(&[p(7., -4., 0.)], &tri, 5.0);
    assert!((s.point_b - tri[1]).norm() < 1e-15);
}

#[test]
fn hand_derived_segment_cases() {
    // Skew perpendicular segments crossing above each other: distance is the height 3.
    let a = [p(-1., 0., 0.), p(1., 0., 0.)];
    let s = expect(&a, &[p(0., -1., 3.), p(0., 1., 3.)], 3.0);
    assert!((s.point_a - p(0., 0., 0.)).norm() < 1e-15);
    // Parallel, disjoint along the line: end (1,0,0) to start (4,4,0): 3-4-5.
    expect(&a, &[p(4., 4., 0.), p(6., 4., 0.)], 5.0);
    // Parallel, overlapping along the line: the line gap 2.
    expect(&a, &[p(0., 2., 0.), p(5., 2., 0.)], 2.0);
    // Collinear and overlapping: 0.  Collinear with a gap of 1.5.
    expect(&a, &[p(0.5, 0., 0.), p(5., 0., 0.)], 0.0);
    expect(&a, &[p(2.5, 0., 0.), p(5., 0., 0.)], 1.5);
    // Crossing segments: 0.  Zero-length segment acting as a point.
    expect(&a, &[p(0.25, -1., 0.), p(0.25, 1., 0.)], 0.0);
    expect(&a, &[p(0., 4., 3.), p(0., 4., 3.)], 5.0);
    // End of b closest to the interior of a: b from (0,3,4) upwards -> distance 5.
    expect(&a, &[p(0., 3., 4.), p(0., 6., 8.)], 5.0);
}

#[test]
fn hand_derived_triangle_cases() {
    let tri = [p(0., 0., 0.), p(4., 0., 0.), p(0., 4., 0.)];
    // Segment piercing the triangle at (1,1,0): 0.
    expect(&[p(1., 1., -1.), p(1., 1., 2.)], &tri, 0.0);
    // Segment parallel to the plane above the interior, height 2.
    expect(&[p(0.5, 0.5, 2.), p(1.5, 1., 2.)], &tri, 2.0);
    // Segment below the plane but beside the triangle: from edge x=0 ... (-3, 1, -4) ->
    // closest triangle point (0,1,0), distance 5, segment end nearest.
    expect(&[p(-3., 1., -4.), p(-6., 1., -8.)], &tri, 5.0);
    // Parallel triangles overlapping in projection: plane gap 1.5.
    let up = tri.map(|v| v + Vector3::new(1., 1., 1.5));
    expect(&tri, &up, 1.5);
    // Edge-edge skew: b's edge along y at x = -3, z = 4 above... the nearest triangle edge is
    // x = 0 (y in [0,4]); b: (-3,1,4)-(-3,2,4)-(-6,1,8) -> vertex/edge (-3,*,4) to (0,*,0): 5.
    expect(&tri, &[p(-3., 1., 4.), p(-3., 2., 4.), p(-6., 1., 8.)], 5.0);
    // Coplanar overlapping triangles: 0. Coplanar disjoint: hypotenuse gap.
    expect(&tri, &[p(1., 1., 0.), p(9., 1., 0.), p(1., 9., 0.)], 0.0);
    expect(
        &tri,
        &[p(3., 3., 0.), p(9., 3., 0.), p(3., 9., 0.)],
        2f64.sqrt(),
    );
    // Degenerate triangles: collinear (acts as segment), all vertices equal (a point).
    expect(&[p(0., 2., 3.), p(0., 1., 3.), p(0., 0.5, 3.)], &tri, 3.0);
    expect(&[p(1., 1., 3.); 3], &tri, 3.0);
}

/// Two triangles 3e-6 apart (found by `reference_certificate`): the certificate's gap of
/// 1.1e-9 is the direction's rounding near contact, within the scaled tolerance.
#[test]
fn near_contact_certificate() {
    let a = [
        p(1.341298443260002, 0.18551064598797726, 0.8566085838714025),
        p(-1.7772524400305454, -0.6605991848005895, 0.3037504605387909),
        p(
            -1.5534802730463446,
            1.2192173867855771,
            -0.24783721777803785,
        ),
    ];
    let b = [
        p(-1.616860917836227, -1.661328586183339, 0.9676744199235229),
        p(0.553988189973016, -1.6972656140578493, 0.22372533996516417),
        p(1.8539651734264804, 1.1222446732243574, 0.46207352648323174),
    ];
    let sol = closest(&a, &b);
    assert!(sol.dist > 0.0 && sol.dist < 1e-5, "{sol:?}");
    check_solution(&a, &b, &sol);
}

/// Point of simplex `v` at parameters `t` (first `v.len() - 1` used), as in (6.4)/(6.5).
fn at(v: &[Point3<f64>], t: &[f64]) -> Point3<f64> {
    let mut q = v[0];
    for (k, &tk) in t.iter().enumerate().take(v.len() - 1) {
        q += (v[k + 1] - v[0]) * tk;
    }
    q
}

/// Whether parameters `t` of an `n`-vertex simplex satisfy (6.6).
fn feasible(t: &[f64], n: usize) -> bool {
    let t = &t[..n - 1];
    t.iter().all(|&x| x >= 0.0) && t.iter().sum::<f64>() <= 1.0
}

/// Minimum of the distance over a grid of `steps` per parameter in the box
/// `lo +- half` (clipped to the simplices), returning the minimum and where it is.
fn grid_min(
    a: &[Point3<f64>],
    b: &[Point3<f64>],
    lo: [f64; 4],
    half: f64,
    steps: usize,
) -> (f64, [f64; 4]) {
    let (ka, kb) = (a.len() - 1, b.len() - 1);
    let dims = ka + kb;
    let mut best = (f64::INFINITY, lo);
    let total = (steps + 1).pow(dims as u32);
    for idx in 0..total {
        let mut t = [0.0; 4];
        let mut r = idx;
        for (k, tk) in t.iter_mut().enumerate().take(dims) {
            *tk = (lo[k] - half + 2.0 * half * (r % (steps + 1)) as f64 / steps as f64)
                .clamp(0.0, 1.0);
            r /= steps + 1;
        }
        let (ta, tb) = t.split_at(ka);
        if !feasible(ta, a.len()) || !feasible(tb, b.len()) {
            continue;
        }
        let d = (at(b, tb) - at(a, ta)).norm();
        if d < best.0 {
            best = (d, t);
        }
    }
    best
}

/// Dense sampling: a coarse grid over the parameter domain, then repeated zooming.
fn sampled_min(a: &[Point3<f64>], b: &[Point3<f64>]) -> f64 {
    let dims = a.len() + b.len() - 2;
    let steps = [0, 400, 60, 16, 8][dims];
    let (mut best, mut t) = grid_min(a, b, [0.5; 4], 0.5, steps.max(1));
    let mut half = 1.0 / steps.max(1) as f64;
    for _ in 0..60 {
        let (d, tt) = grid_min(a, b, t, half, 6);
        if d < best {
            best = d;
            t = tt;
        }
        half *= 0.6;
    }
    best
}

fn pt3(r: f64) -> impl Strategy<Value = Point3<f64>> {
    prop::array::uniform3(-r..r).prop_map(Point3::from)
}

/// 1-3 vertices, either random or snapped to a coarse lattice (degenerate cases).
fn simplex(n: usize) -> impl Strategy<Value = Vec<Point3<f64>>> {
    prop_oneof![
        prop::collection::vec(pt3(2.0), n),
        prop::collection::vec(pt3(2.0).prop_map(|v| v.map(|x| x.round())), n),
    ]
}

fn pair() -> impl Strategy<Value = (Vec<Point3<f64>>, Vec<Point3<f64>>)> {
    (1usize..=3, 1usize..=3).prop_flat_map(|(na, nb)| (simplex(na), simplex(nb)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]
    /// The reference is never above dense sampling (it is feasible, so never below the true
    /// minimum either), its certificate is tight, and it is symmetric.
    #[test]
    fn reference_matches_dense_sampling((a, b) in pair()) {
        let sol = closest(&a, &b);
        check_solution(&a, &b, &sol);
        let sampled = sampled_min(&a, &b);
        let tol = 1e-12 * scale(&a, &b);
        prop_assert!(sol.dist <= sampled + tol, "ref {} > sampled {sampled}", sol.dist);
        prop_assert!((closest(&b, &a).dist - sol.dist).abs() <= tol);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20000))]
    /// Duality certificate on many cases, including vertex permutations (which must not
    /// change the distance).
    #[test]
    fn reference_certificate((a, b) in pair(), rot in 0usize..3) {
        let sol = closest(&a, &b);
        check_solution(&a, &b, &sol);
        let mut ar = a.clone();
        ar.rotate_left(rot % a.len());
        let mut br = b.clone();
        br.reverse();
        let perm = closest(&ar, &br);
        prop_assert!((perm.dist - sol.dist).abs() <= 1e-12 * scale(&a, &b));
    }
}
