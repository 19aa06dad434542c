//! Collision models (thesis 6.7-6.8): update-then-query equals brute force over every pair
//! and SSV pair (library and independent reference), global minimum, and input errors.

mod model_support;

use biped_ssv::format;
use biped_ssv::segment::closest_ssv_pair_brute_force;
use biped_ssv::{CollisionModel, ModelError, PairDistance, PairQuery, Pss, Segment, Ssv};
use model_support::{data_path, pose, ref_segment_distance};
use nalgebra::{Isometry3, Point3};
use proptest::prelude::*;

/// Checks every pair of the last update against brute force; returns the global minimum.
fn check_against_brute_force(model: &CollisionModel) -> Option<f64> {
    let d_a = model.activation_distance();
    let within = model.pair_query() == PairQuery::WithinActivation;
    let mut min: Option<f64> = None;
    for (pair, result) in model.distances() {
        let (a, b) = (&model.segments()[pair.a], &model.segments()[pair.b]);
        let reference = ref_segment_distance(a, b);
        match result {
            PairDistance::Beyond => {
                assert!(
                    reference >= d_a - 1e-12,
                    "{} {} rejected at {reference}",
                    a.name(),
                    b.name()
                )
            }
            PairDistance::Computed(c) => {
                assert!(!within || c.result.distance < d_a);
                let brute = closest_ssv_pair_brute_force(a, b);
                assert!((c.result.distance - brute.result.distance).abs() <= 1e-12);
                assert!(
                    (c.result.distance - reference).abs() <= 1e-9,
                    "{} {}",
                    a.name(),
                    b.name()
                );
                let direct =
                    biped_ssv::distance(&a.world_ssvs()[c.ssv_a], &b.world_ssvs()[c.ssv_b]);
                assert_eq!(direct.distance, c.result.distance);
                min = Some(min.map_or(c.result.distance, |m: f64| m.min(c.result.distance)));
            }
        }
    }
    let reported = model.min_distance().map(|(_, c)| c.result.distance);
    assert_eq!(reported, min);
    min
}

#[test]
fn humanoid_postures_equal_brute_force() {
    let mut loaded = format::load(data_path("humanoid.toml")).unwrap();
    for (name, poses) in &loaded.poses {
        loaded.model.update(poses).unwrap();
        let min = check_against_brute_force(&loaded.model);
        // The cheaper policy agrees on every pair closer than d_a and on the minimum.
        let mut within = loaded.model.clone();
        within.set_pair_query(PairQuery::WithinActivation);
        within.update(poses).unwrap();
        assert_eq!(check_against_brute_force(&within), min);
        for (x, y) in within.results().iter().zip(loaded.model.results()) {
            let close = y.distance().filter(|&d| d < within.activation_distance());
            assert_eq!(x.distance(), close);
        }
        let computed = loaded
            .model
            .results()
            .iter()
            .filter(|r| r.computed().is_some())
            .count();
        println!(
            "{name}: {computed} of {} pairs computed, min distance {min:?}",
            loaded.model.pairs().len()
        );
        assert!(
            min.is_some_and(|m| m > 0.0),
            "posture {name} collides: {min:?}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(60))]

    /// Random perturbations of the standing posture (every body moved by up to 4 cm and
    /// rotated by up to 0.3 rad): the model still equals brute force.
    #[test]
    fn perturbed_postures_equal_brute_force(
        offsets in prop::collection::vec(pose(0.04), 15),
        scale in 0.0..0.1f64,
    ) {
        let mut loaded = format::load(data_path("humanoid.toml")).unwrap();
        let standing = &loaded.poses["standing"];
        let poses: Vec<Isometry3<f64>> = standing
            .iter()
            .zip(&offsets)
            .map(|(p, o)| {
                let small = Isometry3::from_parts(o.translation, o.rotation.powf(scale));
                p * small
            })
            .collect();
        loaded.model.update(&poses).unwrap();
        let min = check_against_brute_force(&loaded.model);
        loaded.model.set_pair_query(PairQuery::WithinActivation);
        loaded.model.update(&poses).unwrap();
        let close = min.filter(|&m| m < loaded.model.activation_distance());
        prop_assert_eq!(check_against_brute_force(&loaded.model), close);
    }
}

fn point_segment(name: &str) -> Segment {
    Segment::new(
        name,
        vec![Ssv::from(Pss::new(Point3::origin(), 0.1).unwrap())],
    )
    .unwrap()
}

#[test]
fn model_errors() {
    let bodies = || vec!["a".to_string(), "b".to_string()];
    assert_eq!(
        CollisionModel::new(bodies(), -1.0).unwrap_err(),
        ModelError::BadActivationDistance(-1.0)
    );
    assert!(CollisionModel::new(bodies(), f64::NAN).is_err());
    assert_eq!(
        CollisionModel::new(vec!["a".into(), "a".into()], 0.1).unwrap_err(),
        ModelError::DuplicateName("a".into())
    );
    let mut m = CollisionModel::new(bodies(), 0.1).unwrap();
    assert!(matches!(
        m.add_segment(point_segment("s"), 2),
        Err(ModelError::BodyOutOfRange { .. })
    ));
    let s0 = m.add_segment(point_segment("s0"), 0).unwrap();
    let s1 = m.add_segment(point_segment("s1"), 1).unwrap();
    assert_eq!(
        m.add_segment(point_segment("s0"), 1).unwrap_err(),
        ModelError::DuplicateName("s0".into())
    );
    assert_eq!(m.add_pair(s0, s0).unwrap_err(), ModelError::SelfPair(s0));
    assert!(matches!(
        m.add_pair(s0, 5),
        Err(ModelError::SegmentOutOfRange { .. })
    ));
    m.add_pair(s0, s1).unwrap();
    let id = Isometry3::identity();
    assert_eq!(
        m.update(&[id]).unwrap_err(),
        ModelError::PoseCount {
            expected: 2,
            got: 1
        }
    );
    let mut bad = id;
    bad.translation.vector.x = f64::NAN;
    assert_eq!(
        m.update(&[id, bad]).unwrap_err(),
        ModelError::NonFinitePose(1)
    );
    // Two unit-0.1 spheres 0.25 apart: 0.05 gap, computed (< d_a = 0.1).
    let mut apart = id;
    apart.translation.vector.x = 0.25;
    m.update(&[id, apart]).unwrap();
    let d = m.results()[0].distance().unwrap();
    assert!((d - 0.05).abs() < 1e-15);
    // 0.5 apart: 0.3 gap, beyond d_a.
    apart.translation.vector.x = 0.5;
    m.update(&[id, apart]).unwrap();
    assert_eq!(m.results()[0], PairDistance::Beyond);
    assert!(m.min_distance().is_none());
}
