//! Cheap lower bounds on SSV-pair distances that let the closest-pair search skip exact
//! distance calls without changing its result:
//!
//! * box-frame intervals: in the frame of segment B's OBB, the axis-aligned bounds of SSV `i`
//!   of A (transformed per query) and of SSV `j` of B (constant, precomputed) are separated
//!   by per-axis gaps `g_k`, and `d(i, j) >= sqrt(sum g_k^2)`. The same against B's whole
//!   box bounds a whole row `i`; B's SSVs against A's box bound whole columns `j`;
//! * bounding spheres: `d(i, j) >= |c_i - c_j| - R_i - R_j` (signed, valid when overlapping).
//!
//! Interval bounds are non-negative, so they only prune while they are positive (a zero
//! bound says nothing about how deep two volumes interpenetrate).

use super::{BoundingSphere, Segment};
use crate::obb::LocalInterval;

/// Slack on every bound so that rounding can never prune the true closest pair.
const SLACK: f64 = 1e-12;
/// Columns tracked individually; beyond this every column of B is scanned.
const MAX_COLUMNS: usize = 64;

/// Whether a non-negative squared lower bound excludes a distance below `best`.
#[inline]
pub(super) fn excludes(lower_sq: f64, best: f64) -> bool {
    let t = best + SLACK;
    if t <= 0.0 {
        lower_sq > 0.0
    } else {
        lower_sq >= t * t
    }
}

/// Whether the sphere bound excludes a distance below `best` (no square root).
#[inline]
pub(super) fn sphere_excludes(s: &BoundingSphere, t: &BoundingSphere, best: f64) -> bool {
    let reach = best + s.radius + t.radius + SLACK;
    reach <= 0.0 || (t.center - s.center).norm_squared() >= reach * reach
}

/// The columns (SSVs of B) not excluded by A's box for a given cutoff, with their bounds.
pub(super) struct Columns {
    index: [u16; MAX_COLUMNS],
    bound_sq: [f64; MAX_COLUMNS],
    len: usize,
    /// Set when B has more than `MAX_COLUMNS` SSVs: scan `0..all` without column bounds.
    all: usize,
}

impl Columns {
    /// Columns of `b` whose bound against `a`'s box does not exclude `cutoff`.
    #[inline]
    pub fn new(a: &Segment, b: &Segment, cutoff: f64) -> Self {
        let mut cols = Self {
            index: [0; MAX_COLUMNS],
            bound_sq: [0.0; MAX_COLUMNS],
            len: 0,
            all: 0,
        };
        let ssvs = b.world_ssvs();
        if ssvs.len() > MAX_COLUMNS {
            cols.all = ssvs.len();
            return cols;
        }
        let box_a = a.world_obb();
        let own = box_a.own_interval();
        for (j, s) in ssvs.iter().enumerate() {
            let lb = box_a.local_interval(s).distance_squared(&own);
            if !excludes(lb, cutoff) {
                cols.index[cols.len] = j as u16;
                cols.bound_sq[cols.len] = lb;
                cols.len += 1;
            }
        }
        cols
    }

    /// Whether no column survived.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0 && self.all == 0
    }

    /// Surviving columns as `(j, squared column bound)`.
    #[inline]
    pub fn iter(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        let listed = self.index[..self.len]
            .iter()
            .zip(&self.bound_sq[..self.len])
            .map(|(&j, &b)| (j as usize, b));
        listed.chain((0..self.all).map(|j| (j, 0.0)))
    }
}

/// Row bound: SSV `i` of A in B's box frame and its squared gap to B's box.
#[inline]
pub(super) fn row(a: &Segment, b: &Segment, i: usize) -> (LocalInterval, f64) {
    let box_b = b.world_obb();
    let iv = box_b.local_interval(&a.world_ssvs()[i]);
    let lb = iv.distance_squared(&box_b.own_interval());
    (iv, lb)
}

/// Whether pair (i, j) is excluded from beating `best`, given row `i`'s interval.
#[inline]
pub(super) fn pair_excludes(
    a: &Segment,
    b: &Segment,
    i: usize,
    row: &LocalInterval,
    j: usize,
    best: f64,
) -> bool {
    excludes(row.distance_squared(&b.ssv_intervals()[j]), best)
        || sphere_excludes(&a.world_spheres()[i], &b.world_spheres()[j], best)
}

/// A promising first pair for an unbounded search: the smallest interval bound, ties (zero
/// bounds) broken by the sphere bound.
pub(super) fn seed(a: &Segment, b: &Segment, cols: &Columns) -> Option<(usize, usize)> {
    let mut best: Option<(usize, usize, f64, f64)> = None;
    for i in 0..a.len() {
        let (iv, _) = row(a, b, i);
        for (j, _) in cols.iter() {
            let box_sq = iv.distance_squared(&b.ssv_intervals()[j]);
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
