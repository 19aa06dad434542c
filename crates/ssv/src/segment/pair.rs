//! Segment-pair distance query with the enlarged-OBB pre-check (6.7) and exact pruning of
//! SSV pairs by cheap lower bounds (see `bounds.rs`). The collision model warm-starts each
//! query with the previous update's closest SSV pair (temporal coherence): it sets a tight
//! best distance and the separating axis before any other pair is looked at.

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
    let mut cols = Columns::new();
    let (wa, wb) = (a.world_ssvs(), b.world_ssvs());
    let (sa, sb) = (a.world_spheres(), b.world_spheres());
    let mut best: Option<ClosestPair> = None;
    let mut best_d = cutoff;
    // Evaluates pair (i, j); returns its normal.
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
        result.normal
    };
    let seed = match hint {
        Some((i, j)) if i < wa.len() && j < wb.len() => Some((i, j)),
        _ if cutoff == f64::INFINITY => bounds::seed(a, b, &mut cols),
        _ => None,
    };
    // Any unit axis gives a valid bound; the seed pair's normal is a good one, else the
    // direction between the two boxes.
    let axis = match seed {
        Some((i, j)) => Some(consider(i, j, &mut best_d)),
        None => bounds::box_axis(a, b),
    };
    // Separating-axis bound along n: d(i, j) >= min_B_j(x . n) -
    // max_A_i(x . n) (radii included), so SSVs behind the first pair along n drop out
    // with one subtraction per pair.
    let lo_b = bounds::AxisSupport::new(wb, axis.as_ref());
    // Whole rows by the axis and row bounds, then pairs by the axis and sphere bounds (no
    // transform); the box-frame interval of a column is computed only for pairs that
    // survive those.
    for i in 0..wa.len() {
        let hi_a = bounds::axis_max(&wa[i], axis.as_ref());
        if bounds::axis_excludes(lo_b.min() - hi_a, best_d) {
            continue;
        }
        let (row_iv, row_sq) = bounds::row(a, b, i);
        if bounds::excludes(row_sq, best_d) {
            continue;
        }
        for (j, sb_j) in sb.iter().enumerate() {
            if bounds::axis_excludes(lo_b.get(j) - hi_a, best_d)
                || bounds::sphere_excludes(&sa[i], sb_j, best_d)
                || seed == Some((i, j))
            {
                continue;
            }
            let (col_iv, col_sq) = cols.get(a, b, j);
            if bounds::excludes(col_sq, best_d)
                || bounds::excludes(row_iv.distance_squared(&b.ssv_intervals()[j]), best_d)
                || bounds::excludes(a.ssv_intervals()[i].distance_squared(col_iv), best_d)
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

#[cfg(test)]
mod tests;
