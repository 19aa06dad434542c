//! Shared helpers of the `model_*` tests: an independent SSV distance (the KKT reference
//! solver of `tests/reference`, shares no code with `src/distance`), random SSVs and poses.

#![allow(dead_code)]

#[path = "../reference/mod.rs"]
mod reference;

use biped_ssv::{Lss, Pss, Segment, Ssv, Tss};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

/// Reference signed distance between two SSVs: simplex-simplex distance minus both radii.
pub fn ref_distance(a: &Ssv, b: &Ssv) -> f64 {
    reference::closest(a.vertices(), b.vertices()).dist - a.radius() - b.radius()
}

/// Reference minimum distance between two posed segments, by brute force over SSV pairs.
pub fn ref_segment_distance(a: &Segment, b: &Segment) -> f64 {
    let mut best = f64::INFINITY;
    for x in a.world_ssvs() {
        for y in b.world_ssvs() {
            best = best.min(ref_distance(x, y));
        }
    }
    best
}

/// Path of a file in the crate's `data/` directory.
pub fn data_path(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("data")
        .join(name)
}

/// A point with coordinates in [-s, s].
pub fn point(s: f64) -> impl Strategy<Value = Point3<f64>> {
    prop::array::uniform3(-s..s).prop_map(Point3::from)
}

/// A random SSV of any kind with vertices in [-s, s]^3 and radius in [0, r].
pub fn ssv(s: f64, r: f64) -> impl Strategy<Value = Ssv> {
    prop_oneof![
        (point(s), 0.0..r).prop_map(|(p, r)| Ssv::from(Pss::new(p, r).unwrap())),
        (point(s), point(s), 0.0..r).prop_map(|(a, b, r)| Ssv::from(Lss::new(a, b, r).unwrap())),
        (point(s), point(s), point(s), 0.0..r)
            .prop_map(|(a, b, c, r)| Ssv::from(Tss::new(a, b, c, r).unwrap())),
    ]
}

/// A random segment of 1..=n SSVs around `center`.
pub fn segment(n: usize, s: f64, r: f64) -> impl Strategy<Value = Segment> {
    prop::collection::vec(ssv(s, r), 1..=n).prop_map(|v| Segment::new("random", v).unwrap())
}

/// A random rigid pose with translation in [-t, t]^3.
pub fn pose(t: f64) -> impl Strategy<Value = Isometry3<f64>> {
    (
        prop::array::uniform3(-t..t),
        prop::array::uniform3(-3.2..3.2),
    )
        .prop_map(|(p, a)| {
            Isometry3::from_parts(
                Translation3::from(Vector3::from(p)),
                UnitQuaternion::from_scaled_axis(Vector3::from(a)),
            )
        })
}

/// Full reference result between two SSVs (reference closest points, radii applied).
pub fn ref_result(a: &Ssv, b: &Ssv) -> biped_ssv::DistanceResult {
    use biped_ssv::PrimitiveParam;
    let c = reference::closest(a.vertices(), b.vertices());
    let d = c.point_b - c.point_a;
    let normal = if c.dist > 0.0 {
        d / c.dist
    } else {
        Vector3::x()
    };
    let param = |n: usize, w: [f64; 3]| match n {
        1 => PrimitiveParam::Point,
        2 => PrimitiveParam::Line(w[1]),
        _ => PrimitiveParam::Triangle(w[1], w[2]),
    };
    biped_ssv::DistanceResult {
        distance: c.dist - a.radius() - b.radius(),
        point_a: c.point_a + normal * a.radius(),
        point_b: c.point_b - normal * b.radius(),
        normal,
        closest_a: c.point_a,
        closest_b: c.point_b,
        param_a: param(a.vertices().len(), c.bary_a),
        param_b: param(b.vertices().len(), c.bary_b),
    }
}

/// The mirror image `S pose S` of a rigid pose about a coordinate plane.
pub fn mirror_pose(pose: &Isometry3<f64>, plane: biped_ssv::MirrorPlane) -> Isometry3<f64> {
    let k = plane.normal_axis();
    let mut s = nalgebra::Matrix3::identity();
    s[(k, k)] = -1.0;
    let r = s * pose.rotation.to_rotation_matrix().into_inner() * s;
    let rot = nalgebra::Rotation3::from_matrix_unchecked(r);
    Isometry3::from_parts(
        Translation3::from(s * pose.translation.vector),
        UnitQuaternion::from_rotation_matrix(&rot),
    )
}
