//! Segment-pair distance query with the enlarged-OBB pre-check (6.7) and exact pruning of
//! SSV pairs by cheap lower bounds (see `bounds.rs`).

use super::bounds::{self, Columns};
use super::Segment;
use crate::distance::distance;
use crate::primitives::Ssv;
use crate::result::DistanceResult;

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
    /// The distance is at least `d_a`: the OBBs enlarged by `d_a / 2` do not overlap, or
    /// (with [`PairQuery::WithinActivation`]) no SSV pair is closer than `d_a`.
    Beyond,
    /// The exact closest SSV pair (with [`PairQuery::Closest`] its distance may exceed `d_a`).
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

/// How a segment pair is evaluated once the enlarged OBBs overlap.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PairQuery {
    /// Always the exact closest SSV pair (its distance may exceed `d_a`).
    #[default]
    Closest,
    /// The exact closest pair only if it is closer than `d_a`; otherwise
    /// [`PairDistance::Beyond`]. SSV pairs whose sphere bound is `>= d_a` are never evaluated,
    /// so "beyond" then means exactly "distance >= d_a".
    WithinActivation,
}

/// Segment-pair query at the current world poses (6.7): the OBBs enlarged by `d_a / 2`
/// first, then the exact closest SSV pair.
#[inline]
pub fn segment_pair_distance(a: &Segment, b: &Segment, activation_distance: f64) -> PairDistance {
    segment_pair_query(a, b, activation_distance, PairQuery::Closest)
}

/// Segment-pair query with an explicit [`PairQuery`] policy.
#[inline]
pub fn segment_pair_query(
    a: &Segment,
    b: &Segment,
    activation_distance: f64,
    query: PairQuery,
) -> PairDistance {
    segment_pair_query_hinted(a, b, activation_distance, query, None)
}

/// [`segment_pair_query`] evaluating the SSV pair `hint` first (e.g. the closest pair of the
/// previous update: temporal coherence makes it the likely winner, so the bounds prune
/// nearly all others). The result does not depend on the hint, only the work does.
#[inline]
pub(crate) fn segment_pair_query_hinted(
    a: &Segment,
    b: &Segment,
    activation_distance: f64,
    query: PairQuery,
    hint: Option<(usize, usize)>,
) -> PairDistance {
    let margin = 0.5 * activation_distance;
    if !a.world_obb().overlaps(b.world_obb(), margin) {
        return PairDistance::Beyond;
    }
    let cutoff = match query {
        PairQuery::Closest => f64::INFINITY,
        PairQuery::WithinActivation => activation_distance,
    };
    match search(a, b, cutoff, &mut distance, hint) {
        Some(c) => PairDistance::Computed(c),
        None => PairDistance::Beyond,
    }
}

/// Exact closest SSV pair, skipping SSV pairs whose cheap lower bounds (box-frame intervals,
/// bounding spheres) cannot beat the best distance found so far.
#[inline]
pub fn closest_ssv_pair(a: &Segment, b: &Segment) -> ClosestPair {
    match closest_ssv_pair_with(a, b, f64::INFINITY, distance) {
        Some(c) => c,
        None => closest_ssv_pair_brute_force(a, b),
    }
}

/// The exact closest SSV pair if its distance is below `cutoff` (`None` otherwise), using
/// the caller's SSV distance function (e.g. a reference solver in tests). `dist` is called
/// only for pairs whose lower bounds are below both `cutoff` and the best so far.
pub fn closest_ssv_pair_with<F>(
    a: &Segment,
    b: &Segment,
    cutoff: f64,
    mut dist: F,
) -> Option<ClosestPair>
where
    F: FnMut(&Ssv, &Ssv) -> DistanceResult,
{
    search(a, b, cutoff, &mut dist, None)
}

/// The pruned search: the hint (or, for an unbounded search, the pair with the smallest
/// bounds) first, then every pair whose bounds do not exclude the best so far.
#[inline(always)]
fn search<F>(
    a: &Segment,
    b: &Segment,
    cutoff: f64,
    dist: &mut F,
    hint: Option<(usize, usize)>,
) -> Option<ClosestPair>
where
    F: FnMut(&Ssv, &Ssv) -> DistanceResult,
{
    let cols = Columns::new(a, b);
    if cols.all_excluded(cutoff) {
        return None;
    }
    let (wa, wb) = (a.world_ssvs(), b.world_ssvs());
    let mut best: Option<ClosestPair> = None;
    let mut best_d = cutoff;
    let mut consider = |i: usize, j: usize, best_d: &mut f64| {
        let result = dist(&wa[i], &wb[j]);
        if result.distance < *best_d {
            *best_d = result.distance;
            best = Some(ClosestPair {
                result,
                ssv_a: i,
                ssv_b: j,
            });
        }
    };
    let seed = match hint {
        Some((i, j)) if i < wa.len() && j < wb.len() => Some((i, j)),
        _ if cutoff == f64::INFINITY => bounds::seed(a, b, &cols),
        _ => None,
    };
    if let Some((i, j)) = seed {
        consider(i, j, &mut best_d);
    }
    for i in 0..wa.len() {
        let (row, row_sq) = bounds::row(a, b, i);
        if bounds::excludes(row_sq, best_d) {
            continue;
        }
        for j in 0..wb.len() {
            if bounds::excludes(cols.bound_sq(j), best_d)
                || seed == Some((i, j))
                || bounds::pair_excludes(a, b, &cols, i, &row, j, best_d)
            {
                continue;
            }
            consider(i, j, &mut best_d);
        }
    }
    best
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
            let better = match &best {
                None => true,
                Some(c) => result.distance < c.result.distance,
            };
            if better {
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
