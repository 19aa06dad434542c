use super::*;
use crate::primitives::{Lss, Pss, Tss};
use nalgebra::{Isometry3, Point3, Vector3};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

fn point(rng: &mut StdRng, s: f64) -> Point3<f64> {
    Point3::new(
        rng.random_range(-s..s),
        rng.random_range(-s..s),
        rng.random_range(-s..s),
    )
}

/// A segment of 1-8 random PSS/LSS/TSS around the origin.
fn random_segment(rng: &mut StdRng) -> Segment {
    let n = rng.random_range(1..9);
    let ssvs = (0..n)
        .map(|_| {
            let r = rng.random_range(0.0..0.05);
            match rng.random_range(0..3) {
                0 => Pss::new(point(rng, 0.2), r).unwrap().into(),
                1 => Lss::new(point(rng, 0.2), point(rng, 0.2), r)
                    .unwrap()
                    .into(),
                _ => Tss::new(point(rng, 0.2), point(rng, 0.2), point(rng, 0.2), r)
                    .unwrap()
                    .into(),
            }
        })
        .collect();
    Segment::new("s", ssvs).unwrap()
}

fn random_pose(rng: &mut StdRng) -> Isometry3<f64> {
    let axis = Vector3::new(rng.random(), rng.random(), rng.random::<f64>()) * 3.0;
    Isometry3::new(point(rng, 0.3).coords, axis)
}

/// The warm start changes only the work: for every hint (valid or out of range) and both
/// policies the result equals brute force over all SSV pairs.
#[test]
fn any_hint_gives_the_brute_force_result() {
    let mut rng = StdRng::seed_from_u64(5);
    let mut computed = 0;
    for _ in 0..400 {
        let (mut a, mut b) = (random_segment(&mut rng), random_segment(&mut rng));
        a.set_pose(&random_pose(&mut rng));
        b.set_pose(&random_pose(&mut rng));
        let brute = closest_ssv_pair_brute_force(&a, &b).result.distance;
        let d_a = rng.random_range(0.0..0.2);
        let overlap = a.world_obb().overlaps(b.world_obb(), 0.5 * d_a);
        let mut hints = vec![None, Some((a.len(), 0)), Some((0, b.len() + 3))];
        for i in 0..a.len() {
            for j in 0..b.len() {
                hints.push(Some((i, j)));
            }
        }
        for hint in hints {
            let closest = segment_pair_query_hinted(&a, &b, d_a, PairQuery::Closest, hint);
            let within = segment_pair_query_hinted(&a, &b, d_a, PairQuery::WithinActivation, hint);
            match closest.distance() {
                Some(d) => assert_eq!(d, brute, "{hint:?}"),
                None => assert!(!overlap && brute >= d_a - 1e-12),
            }
            match within.distance() {
                Some(d) => assert_eq!(d, brute, "{hint:?}"),
                None => assert!(brute >= d_a || !overlap, "{hint:?} {brute} {d_a}"),
            }
            if let Some(c) = closest.computed() {
                computed += 1;
                let again = distance(&a.world_ssvs()[c.ssv_a], &b.world_ssvs()[c.ssv_b]);
                assert_eq!(again, c.result);
            }
        }
    }
    assert!(computed > 2000, "{computed}");
}
