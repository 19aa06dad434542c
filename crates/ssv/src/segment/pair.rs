//! Segment-pair distance query with the enlarged-OBB pre-check (6.7) and exact pruning of
//! SSV pairs by bounding spheres.

use super::Segment;
use crate::distance::distance;
use crate::primitives::Ssv;
use crate::result::DistanceResult;

/// Slack on the sphere bound so that rounding can never prune the true closest pair.
const PRUNE_SLACK: f64 = 1e-12;

/// The closest pair of SSVs between two segments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosestPair {
    /// Full distance result between the two SSVs (world frame).
    pub result: DistanceResult,
    /// Index of the SSV in the first segment.
    pub ssv_a: usize,
    /// Index of the SSV in the second segment.
    pub ssv_b: usize,
}

/// Outcome of a segment-pair query.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PairDistance {
    /// The OBBs enlarged by `d_a / 2` do not overlap: the distance is at least `d_a`.
    Beyond,
    /// The boxes overlap: the exact closest SSV pair (its distance may still exceed `d_a`).
    Computed(ClosestPair),
}

impl PairDistance {
    /// The closest pair, if it was computed.
    #[inline]
    pub fn computed(&self) -> Option<&ClosestPair> {
        match self {
            PairDistance::Beyond => None,
            PairDistance::Computed(c) => Some(c),
        }
    }
    /// Signed distance if computed, else `None` ("beyond d_a").
    #[inline]
    pub fn distance(&self) -> Option<f64> {
        self.computed().map(|c| c.result.distance)
    }
}

/// Segment-pair query at the current world poses (6.7): the enlarged-OBB test first, then
/// the closest SSV pair.
#[inline]
pub fn segment_pair_distance(a: &Segment, b: &Segment, activation_distance: f64) -> PairDistance {
    if !a
        .world_obb()
        .overlaps(b.world_obb(), 0.5 * activation_distance)
    {
        return PairDistance::Beyond;
    }
    PairDistance::Computed(closest_ssv_pair(a, b))
}

/// Exact closest SSV pair, skipping pairs whose bounding-sphere lower bound cannot beat the
/// best distance found so far. Starts from the pair with the smallest bound.
#[inline]
pub fn closest_ssv_pair(a: &Segment, b: &Segment) -> ClosestPair {
    closest_ssv_pair_with(a, b, distance)
}

/// [`closest_ssv_pair`] with a caller-supplied SSV distance function (e.g. a reference
/// solver in tests); `dist` is called only for pairs the sphere bound cannot exclude.
pub fn closest_ssv_pair_with<F>(a: &Segment, b: &Segment, mut dist: F) -> ClosestPair
where
    F: FnMut(&Ssv, &Ssv) -> DistanceResult,
{
    let (sa, sb) = (a.world_spheres(), b.world_spheres());
    let (mut seed_a, mut seed_b, mut seed_lb) = (0, 0, f64::INFINITY);
    for (i, s) in sa.iter().enumerate() {
        for (j, t) in sb.iter().enumerate() {
            let lb = s.distance_lower_bound(t);
            if lb < seed_lb {
                (seed_a, seed_b, seed_lb) = (i, j, lb);
            }
        }
    }
    let (wa, wb) = (a.world_ssvs(), b.world_ssvs());
    let mut best = ClosestPair {
        result: dist(&wa[seed_a], &wb[seed_b]),
        ssv_a: seed_a,
        ssv_b: seed_b,
    };
    for (i, s) in sa.iter().enumerate() {
        for (j, t) in sb.iter().enumerate() {
            if (i, j) == (seed_a, seed_b) || !may_beat(s, t, best.result.distance) {
                continue;
            }
            let result = dist(&wa[i], &wb[j]);
            if result.distance < best.result.distance {
                best = ClosestPair {
                    result,
                    ssv_a: i,
                    ssv_b: j,
                };
            }
        }
    }
    best
}

/// Whether the sphere bound allows a distance below `best` (squared form, no sqrt).
#[inline]
fn may_beat(s: &super::BoundingSphere, t: &super::BoundingSphere, best: f64) -> bool {
    let reach = best + s.radius + t.radius + PRUNE_SLACK;
    reach > 0.0 && (t.center - s.center).norm_squared() < reach * reach
}

/// Reference: the closest SSV pair by evaluating every pair (for tests and benchmarks).
pub fn closest_ssv_pair_brute_force(a: &Segment, b: &Segment) -> ClosestPair {
    closest_ssv_pair_brute_force_with(a, b, distance)
}

/// [`closest_ssv_pair_brute_force`] with a caller-supplied SSV distance function.
pub fn closest_ssv_pair_brute_force_with<F>(a: &Segment, b: &Segment, mut dist: F) -> ClosestPair
where
    F: FnMut(&Ssv, &Ssv) -> DistanceResult,
{
    let mut best: Option<ClosestPair> = None;
    for (i, x) in a.world_ssvs().iter().enumerate() {
        for (j, y) in b.world_ssvs().iter().enumerate() {
            let result = dist(x, y);
            if best.map_or(true, |c| result.distance < c.result.distance) {
                best = Some(ClosestPair {
                    result,
                    ssv_a: i,
                    ssv_b: j,
                });
            }
        }
    }
    best.unwrap_or_else(|| ClosestPair {
        result: dist(&a.world_ssvs()[0], &b.world_ssvs()[0]),
        ssv_a: 0,
        ssv_b: 0,
    })
}
