//! Adversarial families for the closed-form distance functions: near-parallel and
//! near-degenerate configurations, exact touching, and intersecting primitives.

mod reference;
mod support;

/// Near-parallel segments (angles down to 1e-12 rad and exactly 0), segments near-parallel
/// to triangle planes and edges, sliver triangles, tiny segments, nearly coincident points.
mod near_degenerate {
    crate::support::pair_tests!(crate::support::families::near_degenerate, 30_000);
}

/// Radii summing exactly to the primitive distance (signed distance 0).
mod touching {
    crate::support::pair_tests!(crate::support::families::touching, 15_000);
}

/// Crossing segments, segments piercing triangles, intersecting triangles, points on them.
mod intersecting {
    crate::support::pair_tests!(crate::support::families::intersecting, 15_000);
}

/// Regression: minimal reproducer found by `near_degenerate::pt` against a draft PT (error
/// 1.7e-8 from the ill-conditioned dual-basis projection). The point lies exactly on edge v0v1
/// (p = v0 + 0.3 (v1 - v0), all products exact), so the distance is 0; the triangle is a
/// sliver obtuse at v0 (v2 off the line v0v1 by 1e-9).
#[test]
fn pt_point_on_edge_of_sliver() {
    let p = nalgebra::Point3::new;
    let a = biped_ssv::Pss::new(p(-0.3, 0.0, -0.3), 0.0).unwrap().into();
    let b = biped_ssv::Tss::new(
        p(0.0, 0.0, 0.0),
        p(-1.0, 0.0, -1.0),
        p(1.0, 0.0, 1.0 + 1e-9),
        0.0,
    )
    .unwrap()
    .into();
    assert_eq!(support::reference_distance(&a, &b), 0.0);
    support::check_pair(&a, &b).unwrap();
}
