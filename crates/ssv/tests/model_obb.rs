//! Oriented bounding boxes (thesis 6.7): containment of every SSV, tightness against the
//! body-frame AABB, the SAT overlap test against parry's independent cuboid test, and the
//! guarantee that boxes enlarged by d_a/2 never reject a pair closer than d_a.

mod model_support;

use biped_ssv::segment::MirrorPlane;
use biped_ssv::{Obb, Segment};
use model_support::{pose, ref_segment_distance, segment};
use nalgebra::{Isometry3, Matrix3, Rotation3, UnitQuaternion, Vector3};
use parry3d_f64::math::{Pose, Vector};
use parry3d_f64::query::intersection_test;
use parry3d_f64::shape::Cuboid;
use proptest::prelude::*;

/// Exact interval of the segment's SSVs along `u` (vertices +- radius).
fn interval(seg: &Segment, u: &Vector3<f64>) -> (f64, f64) {
    seg.ssvs()
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
            let r = s.radius();
            s.vertices().iter().fold((lo, hi), |(lo, hi), v| {
                let x = v.coords.dot(u);
                (lo.min(x - r), hi.max(x + r))
            })
        })
}

fn parry_pose(obb: &Obb) -> Pose {
    let q = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(obb.axes));
    let a = q.scaled_axis();
    let c = obb.center;
    Pose::new(Vector::new(c.x, c.y, c.z), Vector::new(a.x, a.y, a.z))
}

fn parry_overlap(a: &Obb, b: &Obb, margin: f64) -> bool {
    let h = |o: &Obb| {
        let e = o.half_extents.add_scalar(margin);
        Cuboid::new(Vector::new(e.x, e.y, e.z))
    };
    intersection_test(&parry_pose(a), &h(a), &parry_pose(b), &h(b))
        .unwrap()
        .intersecting
}

fn is_rotation(m: &Matrix3<f64>) -> bool {
    (m.transpose() * m - Matrix3::identity()).norm() < 1e-9 && (m.determinant() - 1.0).abs() < 1e-9
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// The fitted box, moved with its body, contains every moved SSV (radii included).
    #[test]
    fn obb_contains_every_ssv(seg in segment(8, 0.3, 0.1), p in pose(1.0)) {
        let mut seg = seg;
        prop_assert!(is_rotation(&seg.obb().axes));
        seg.set_pose(&p);
        for s in seg.world_ssvs() {
            prop_assert!(seg.world_obb().contains_ssv(s, 1e-12), "{:?} not in {:?}", s, seg.world_obb());
        }
    }

    /// The fit is at least as tight as the body-frame AABB and touches the SSVs on all six
    /// faces (extents equal the exact support intervals along the box axes).
    #[test]
    fn obb_is_tight(seg in segment(8, 0.3, 0.1)) {
        let obb = seg.obb();
        let aabb: f64 = (0..3)
            .map(|k| {
                let (lo, hi) = interval(&seg, &Vector3::ith(k, 1.0));
                hi - lo
            })
            .product();
        prop_assert!(obb.volume() <= aabb * (1.0 + 1e-9) + 1e-15);
        for k in 0..3 {
            let u = obb.axes.column(k).into_owned();
            let (lo, hi) = interval(&seg, &u);
            let c = u.dot(&obb.center.coords);
            prop_assert!((c - obb.half_extents[k] - lo).abs() < 1e-12);
            prop_assert!((c + obb.half_extents[k] - hi).abs() < 1e-12);
        }
    }

    /// The SAT test agrees with parry's cuboid-cuboid test (away from touching contact).
    #[test]
    fn sat_matches_parry(
        ha in prop::array::uniform3(0.01..0.5f64),
        hb in prop::array::uniform3(0.01..0.5f64),
        pa in pose(0.6),
        pb in pose(0.6),
        margin in 0.0..0.1f64,
    ) {
        let boxed = |h: [f64; 3], p: &Isometry3<f64>| Obb {
            center: p.translation.vector.into(),
            axes: p.rotation.to_rotation_matrix().into_inner(),
            half_extents: Vector3::from(h),
        };
        let (a, b) = (boxed(ha, &pa), boxed(hb, &pb));
        let ours = a.overlaps(&b, margin);
        prop_assert_eq!(ours, b.overlaps(&a, margin));
        // Compare only when parry's answer is robust: shrunk and grown boxes agree.
        let inner = parry_overlap(&a, &b, margin - 1e-6);
        let outer = parry_overlap(&a, &b, margin + 1e-6);
        if inner == outer {
            prop_assert_eq!(ours, inner);
        }
    }

    /// Boxes enlarged by d_a/2 never reject a pair whose true distance is below d_a
    /// (brute force over all SSV pairs with the independent reference solver).
    #[test]
    fn enlarged_obb_never_rejects_close_pairs(
        a in segment(5, 0.2, 0.05),
        b in segment(5, 0.2, 0.05),
        pa in pose(0.5),
        pb in pose(0.5),
        d_a in 0.0..0.3f64,
    ) {
        let (mut a, mut b) = (a, b);
        a.set_pose(&pa);
        b.set_pose(&pb);
        let d = ref_segment_distance(&a, &b);
        if d < d_a {
            prop_assert!(a.world_obb().overlaps(b.world_obb(), 0.5 * d_a), "d = {} < d_a = {}", d, d_a);
        }
    }

    /// The reflected box of a mirrored segment contains the mirrored SSVs and is a rotation.
    #[test]
    fn mirrored_obb_contains_mirrored_ssvs(seg in segment(6, 0.3, 0.1), k in 0usize..3) {
        let m = seg.mirrored("m", MirrorPlane::ALL[k]);
        prop_assert!(is_rotation(&m.obb().axes));
        prop_assert!((m.obb().volume() - seg.obb().volume()).abs() < 1e-15);
        for s in m.ssvs() {
            prop_assert!(m.obb().contains_ssv(s, 1e-12));
        }
    }
}

/// Parallel faces and edges (identical axes) must not produce a false separation.
#[test]
fn parallel_boxes() {
    let unit = Obb {
        center: [0.0, 0.0, 0.0].into(),
        axes: Matrix3::identity(),
        half_extents: Vector3::new(0.5, 0.5, 0.5),
    };
    for (dx, expect) in [(0.99, true), (1.0 - 1e-12, true), (1.01, false)] {
        let moved = Obb {
            center: [dx, 0.3, -0.2].into(),
            ..unit
        };
        assert_eq!(unit.overlaps(&moved, 0.0), expect, "dx = {dx}");
    }
    // Margins: gap 0.1 is closed by margin 0.05 on each box, not by 0.049.
    let far = Obb {
        center: [1.1, 0.0, 0.0].into(),
        ..unit
    };
    assert!(unit.overlaps(&far, 0.0501));
    assert!(!unit.overlaps(&far, 0.049));
}
