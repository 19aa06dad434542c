//! Segments (thesis 6.6): exactness of the sphere-pruned closest-pair search against brute
//! force, mirrored segments against mirrored geometry, the enlarged-OBB pair query, and
//! construction errors.

mod model_support;

use biped_ssv::segment::{
    closest_ssv_pair, closest_ssv_pair_brute_force, closest_ssv_pair_brute_force_with,
    closest_ssv_pair_with, segment_pair_distance, segment_pair_query, SegmentError,
};
use biped_ssv::{MirrorPlane, PairDistance, PairQuery, Pss, Segment, Ssv};
use model_support::{mirror_pose, pose, ref_result, ref_segment_distance, segment};
use nalgebra::Point3;
use proptest::prelude::*;
use std::cell::Cell;

fn posed(seg: &Segment, p: &nalgebra::Isometry3<f64>) -> Segment {
    let mut s = seg.clone();
    s.set_pose(p);
    s
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Pruning is exact: with the same (reference) distance function, the pruned search finds
    /// the brute-force minimum, and it never evaluates more pairs than brute force.
    #[test]
    fn pruned_search_equals_brute_force_reference(
        a in segment(10, 0.4, 0.06),
        b in segment(10, 0.4, 0.06),
        pa in pose(0.6),
        pb in pose(0.6),
    ) {
        let (a, b) = (posed(&a, &pa), posed(&b, &pb));
        let calls = Cell::new(0usize);
        let counted = |x: &Ssv, y: &Ssv| {
            calls.set(calls.get() + 1);
            ref_result(x, y)
        };
        let pruned = closest_ssv_pair_with(&a, &b, f64::INFINITY, counted).unwrap();
        let brute = closest_ssv_pair_brute_force_with(&a, &b, ref_result);
        prop_assert_eq!(pruned.result.distance, brute.result.distance);
        prop_assert!(calls.get() <= a.len() * b.len());
        let again = ref_result(&a.world_ssvs()[pruned.ssv_a], &b.world_ssvs()[pruned.ssv_b]);
        prop_assert_eq!(again.distance, pruned.result.distance);
    }

    /// Deeply interpenetrating segments (negative distances): zero interval bounds must not
    /// prune, signed sphere bounds still may.
    #[test]
    fn pruned_search_exact_when_penetrating(
        a in segment(10, 0.3, 0.2),
        b in segment(10, 0.3, 0.2),
        pa in pose(0.1),
        pb in pose(0.1),
        cutoff in prop_oneof![Just(f64::INFINITY), -0.3..0.1f64],
    ) {
        let (a, b) = (posed(&a, &pa), posed(&b, &pb));
        let brute = closest_ssv_pair_brute_force_with(&a, &b, ref_result).result.distance;
        match closest_ssv_pair_with(&a, &b, cutoff, ref_result) {
            Some(c) => prop_assert_eq!(c.result.distance, brute),
            None => prop_assert!(brute >= cutoff),
        }
    }

    /// The same with the library's distance functions, cross-checked against the reference.
    #[test]
    fn pruned_search_equals_brute_force_library(
        a in segment(10, 0.4, 0.06),
        b in segment(10, 0.4, 0.06),
        pa in pose(0.6),
        pb in pose(0.6),
    ) {
        let (a, b) = (posed(&a, &pa), posed(&b, &pb));
        let pruned = closest_ssv_pair(&a, &b);
        let brute = closest_ssv_pair_brute_force(&a, &b);
        prop_assert!((pruned.result.distance - brute.result.distance).abs() <= 1e-12);
        let reference = ref_segment_distance(&a, &b);
        prop_assert!((pruned.result.distance - reference).abs() <= 1e-9);
    }

    /// A mirrored segment pair in the mirrored posture has the same distance as the original
    /// (the whole scene is mirrored), and the mirrored segment's world SSVs are the reflected
    /// world SSVs of the original.
    #[test]
    fn mirrored_segments_match_mirrored_geometry(
        a in segment(6, 0.3, 0.05),
        b in segment(6, 0.3, 0.05),
        pa in pose(0.5),
        pb in pose(0.5),
        k in 0usize..3,
    ) {
        let plane = MirrorPlane::ALL[k];
        let (ma, mb) = (a.mirrored("ma", plane), b.mirrored("mb", plane));
        let (a, b) = (posed(&a, &pa), posed(&b, &pb));
        let ma = posed(&ma, &mirror_pose(&pa, plane));
        let mb = posed(&mb, &mirror_pose(&pb, plane));
        for (m, o) in ma.world_ssvs().iter().zip(a.world_ssvs()) {
            for (p, q) in m.vertices().iter().zip(o.vertices()) {
                prop_assert!((p - plane.reflect(q)).norm() < 1e-12);
            }
        }
        let d = ref_segment_distance(&a, &b);
        let dm = ref_segment_distance(&ma, &mb);
        prop_assert!((d - dm).abs() < 1e-9, "{} vs {}", d, dm);
        let lib = closest_ssv_pair(&ma, &mb).result.distance;
        prop_assert!((lib - d).abs() < 1e-9, "{} vs {}", lib, d);
        // The mirrored segment's box contains its world SSVs.
        for s in ma.world_ssvs() {
            prop_assert!(ma.world_obb().contains_ssv(s, 1e-12));
        }
    }

    /// With a cutoff, the search returns the exact closest pair iff it is below the cutoff.
    #[test]
    fn cutoff_search_is_exact(
        a in segment(10, 0.4, 0.06),
        b in segment(10, 0.4, 0.06),
        pa in pose(0.6),
        pb in pose(0.6),
        cutoff in -0.1..0.4f64,
    ) {
        let (a, b) = (posed(&a, &pa), posed(&b, &pb));
        let brute = closest_ssv_pair_brute_force_with(&a, &b, ref_result).result.distance;
        match closest_ssv_pair_with(&a, &b, cutoff, ref_result) {
            Some(c) => prop_assert_eq!(c.result.distance, brute),
            None => prop_assert!(brute >= cutoff, "{} < {}", brute, cutoff),
        }
        // Same for the policy-level query with the library distance.
        let reference = ref_segment_distance(&a, &b);
        let d_a = cutoff.max(0.0);
        match segment_pair_query(&a, &b, d_a, PairQuery::WithinActivation) {
            PairDistance::Beyond => prop_assert!(reference >= d_a - 1e-9),
            PairDistance::Computed(c) => {
                prop_assert!(reference < d_a + 1e-9);
                prop_assert!((c.result.distance - reference).abs() <= 1e-9);
            }
        }
    }

    /// The pair query: "beyond" only when the true distance is >= d_a, otherwise the exact
    /// closest pair.
    #[test]
    fn pair_query_is_exact(
        a in segment(6, 0.25, 0.05),
        b in segment(6, 0.25, 0.05),
        pa in pose(0.6),
        pb in pose(0.6),
        d_a in 0.0..0.2f64,
    ) {
        let (a, b) = (posed(&a, &pa), posed(&b, &pb));
        let reference = ref_segment_distance(&a, &b);
        match segment_pair_distance(&a, &b, d_a) {
            PairDistance::Beyond => prop_assert!(reference >= d_a - 1e-12),
            PairDistance::Computed(c) => {
                prop_assert!((c.result.distance - reference).abs() <= 1e-9);
            }
        }
    }
}

#[test]
fn mirrored_copies_and_versions() {
    let p = |x: f64, y: f64, z: f64| Ssv::from(Pss::new(Point3::new(x, y, z), 0.1).unwrap());
    let seg = Segment::new("s", vec![p(0.0, 0.2, 0.0), p(1.0, 0.0, 0.5)]).unwrap();
    let sym = seg.with_mirrored_copies(&[0], MirrorPlane::Xz).unwrap();
    assert_eq!(sym.len(), 3);
    assert_eq!(sym.ssvs()[2], p(0.0, -0.2, 0.0));
    let v = sym.version("v", &[2, 1]).unwrap();
    assert_eq!(v.ssvs(), &[p(0.0, -0.2, 0.0), p(1.0, 0.0, 0.5)]);
    assert_eq!(v.name(), "v");
    for plane in MirrorPlane::ALL {
        let back = seg.mirrored("m", plane).mirrored("s", plane);
        assert_eq!(back.ssvs(), seg.ssvs());
        assert_eq!(plane.name().parse::<MirrorPlane>().unwrap(), plane);
    }
}

#[test]
fn segment_errors() {
    assert_eq!(
        Segment::new("empty", vec![]).unwrap_err(),
        SegmentError::Empty("empty".into())
    );
    let seg = Segment::new("s", vec![Pss::new(Point3::origin(), 0.1).unwrap().into()]).unwrap();
    let out = SegmentError::IndexOutOfRange {
        segment: "s".into(),
        index: 1,
        count: 1,
    };
    assert_eq!(seg.version("v", &[1]).unwrap_err(), out);
    assert_eq!(
        seg.with_mirrored_copies(&[1], MirrorPlane::Xy).unwrap_err(),
        out
    );
    assert!(matches!(seg.version("v", &[]), Err(SegmentError::Empty(_))));
    assert!("xw".parse::<MirrorPlane>().is_err());
}

/// Segments beyond the per-query column cache (more than 64 SSVs) stay exact.
#[test]
fn large_segments_equal_brute_force() {
    use model_support::ssv;
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let many = proptest::collection::vec(ssv(0.5, 0.05), 70..=80);
    for _ in 0..20 {
        let a = Segment::new("a", many.new_tree(&mut runner).unwrap().current()).unwrap();
        let b = Segment::new("b", many.new_tree(&mut runner).unwrap().current()).unwrap();
        let pb = pose(0.8).new_tree(&mut runner).unwrap().current();
        let (a, b) = (posed(&a, &nalgebra::Isometry3::identity()), posed(&b, &pb));
        let brute = closest_ssv_pair_brute_force_with(&a, &b, ref_result)
            .result
            .distance;
        for cutoff in [f64::INFINITY, 0.05, brute + 1e-3] {
            match closest_ssv_pair_with(&a, &b, cutoff, ref_result) {
                Some(c) => assert_eq!(c.result.distance, brute),
                None => assert!(brute >= cutoff),
            }
        }
    }
}
