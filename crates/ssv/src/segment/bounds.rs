//! Cheap lower bounds on SSV-pair distances that let the closest-pair search skip exact
//! distance calls without changing its result:
//!
//! * box-frame intervals: in the frame of segment B's OBB, the axis-aligned bounds of SSV `i`
//!   of A (transformed per query) and of SSV `j` of B (constant, precomputed) are separated
//!   by per-axis gaps `g_k`, and `d(i, j) >= sqrt(sum g_k^2)`. The same against B's whole
//!   box bounds a whole row `i`. Symmetrically, B's SSVs in A's box frame bound whole
//!   columns `j` and, against A's precomputed intervals, each pair a second time; the larger
//!   of the two pair bounds is used;
//! * bounding spheres: `d(i, j) >= |c_i - c_j| - R_i - R_j` (signed, valid when overlapping).
//!
//! Interval bounds are non-negative, so they only prune while they are positive (a zero
//! bound says nothing about how deep two volumes interpenetrate).

use super::{BoundingSphere, Segment};
use crate::obb::LocalInterval;
use nalgebra::Vector3;

/// Slack on every bound so that rounding can never prune the true closest pair.
const SLACK: f64 = 1e-12;
/// Columns whose box-frame intervals are kept; beyond this every column of B is scanned
/// with sphere and row bounds only.
const MAX_COLUMNS: usize = 16;

/// Whether a non-negative squared lower bound excludes a distance below `best`.
#[inline(always)]
pub(super) fn excludes(lower_sq: f64, best: f64) -> bool {
    let t = best + SLACK;
    if t <= 0.0 {
        lower_sq > 0.0
    } else {
        lower_sq >= t * t
    }
}

/// Whether the sphere bound excludes a distance below `best` (no square root).
#[inline(always)]
pub(super) fn sphere_excludes(s: &BoundingSphere, t: &BoundingSphere, best: f64) -> bool {
    let reach = best + s.radius + t.radius + SLACK;
    reach <= 0.0 || (t.center - s.center).norm_squared() >= reach * reach
}

/// The interval that bounds nothing (used past [`MAX_COLUMNS`]).
#[inline(always)]
fn unbounded() -> LocalInterval {
    LocalInterval {
        lo: Vector3::repeat(f64::NEG_INFINITY),
        hi: Vector3::repeat(f64::INFINITY),
    }
}

/// The SSVs of B in A's box frame: their intervals and squared gaps to A's box.
pub(super) struct Columns {
    interval: [LocalInterval; MAX_COLUMNS],
    bound_sq: [f64; MAX_COLUMNS],
    len: usize,
}

impl Columns {
    /// The column bounds of `b` against `a`'s box.
    #[inline]
    pub fn new(a: &Segment, b: &Segment) -> Self {
        let ssvs = b.world_ssvs();
        let box_a = a.world_obb();
        let own = box_a.own_interval();
        let mut cols = Self {
            interval: [unbounded(); MAX_COLUMNS],
            bound_sq: [0.0; MAX_COLUMNS],
            len: ssvs.len(),
        };
        if ssvs.len() <= MAX_COLUMNS {
            for ((iv, sq), s) in cols.interval.iter_mut().zip(&mut cols.bound_sq).zip(ssvs) {
                *iv = box_a.local_interval(s);
                *sq = iv.distance_squared(&own);
            }
        }
        cols
    }

    /// Number of columns (SSVs of B).
    #[inline(always)]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Squared lower bound of column `j` against A's whole box (0 when untracked).
    #[inline(always)]
    pub fn bound_sq(&self, j: usize) -> f64 {
        match self.bound_sq.get(j) {
            Some(&b) if self.len <= MAX_COLUMNS => b,
            _ => 0.0,
        }
    }

    /// Whether every column is excluded from beating `cutoff`.
    #[inline]
    pub fn all_excluded(&self, cutoff: f64) -> bool {
        self.len <= MAX_COLUMNS
            && self.bound_sq[..self.len]
                .iter()
                .all(|&b| excludes(b, cutoff))
    }

    /// Squared interval bound of pair (i, j) in A's box frame (0 when untracked).
    #[inline(always)]
    fn pair_sq(&self, a: &Segment, i: usize, j: usize) -> f64 {
        match self.interval.get(j) {
            Some(iv) if self.len <= MAX_COLUMNS => a.ssv_intervals()[i].distance_squared(iv),
            _ => 0.0,
        }
    }
}

/// Row bound: SSV `i` of A in B's box frame and its squared gap to B's box.
#[inline(always)]
pub(super) fn row(a: &Segment, b: &Segment, i: usize) -> (LocalInterval, f64) {
    let box_b = b.world_obb();
    let iv = box_b.local_interval(&a.world_ssvs()[i]);
    let lb = iv.distance_squared(&box_b.own_interval());
    (iv, lb)
}

/// Squared interval bound of pair (i, j): the larger of the bounds in B's and A's box frames.
#[inline(always)]
pub(super) fn pair_sq(
    a: &Segment,
    b: &Segment,
    cols: &Columns,
    i: usize,
    row: &LocalInterval,
    j: usize,
) -> f64 {
    let in_b = row.distance_squared(&b.ssv_intervals()[j]);
    in_b.max(cols.pair_sq(a, i, j))
}

/// Whether pair (i, j) is excluded from beating `best`, given row `i`'s interval.
#[inline(always)]
pub(super) fn pair_excludes(
    a: &Segment,
    b: &Segment,
    cols: &Columns,
    i: usize,
    row: &LocalInterval,
    j: usize,
    best: f64,
) -> bool {
    sphere_excludes(&a.world_spheres()[i], &b.world_spheres()[j], best)
        || excludes(pair_sq(a, b, cols, i, row, j), best)
}

/// A promising first pair for an unbounded search: the smallest interval bound, ties (zero
/// bounds) broken by the sphere bound.
pub(super) fn seed(a: &Segment, b: &Segment, cols: &Columns) -> Option<(usize, usize)> {
    let mut best: Option<(usize, usize, f64, f64)> = None;
    for i in 0..a.len() {
        let (iv, _) = row(a, b, i);
        for j in 0..cols.len() {
            let box_sq = pair_sq(a, b, cols, i, &iv, j);
            let key = if box_sq > 0.0 {
                f64::INFINITY
            } else {
                a.world_spheres()[i].distance_lower_bound(&b.world_spheres()[j])
            };
            if improves(&best, box_sq, key) {
                best = Some((i, j, box_sq, key));
            }
        }
    }
    best.map(|(i, j, _, _)| (i, j))
}

/// Lexicographic order of seed candidates: interval bound, then sphere bound.
#[inline]
fn improves(best: &Option<(usize, usize, f64, f64)>, box_sq: f64, key: f64) -> bool {
    match best {
        None => true,
        Some((_, _, b, k)) => box_sq < *b || (box_sq == *b && key < *k),
    }
}
