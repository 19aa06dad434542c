//! Cheap lower bounds on SSV-pair distances that let the closest-pair search skip exact
//! distance calls without changing its result:
//!
//! * box-frame intervals: in the frame of segment B's OBB, the axis-aligned bounds of SSV `i`
//!   of A (transformed per query) and of SSV `j` of B (constant, precomputed) are separated
//!   by per-axis gaps `g_k`, and `d(i, j) >= sqrt(sum g_k^2)`. The same against B's whole
//!   box bounds a whole row `i`. Symmetrically, B's SSVs in A's box frame bound whole
//!   columns `j` and, against A's precomputed intervals, each pair a second time (columns
//!   are transformed only when first needed);
//! * bounding spheres: `d(i, j) >= |c_i - c_j| - R_i - R_j` (signed, valid when overlapping);
//! * a separating axis n (the normal of the first evaluated pair, else the direction between
//!   the box centres): `d(i, j) >= min_{x in j} x . n - max_{x in i} x . n`, radii included
//!   (signed as well, since |q - p| >= (q - p) . n for any unit n). With the warm-start
//!   pair's normal this one subtraction per pair rejects most pairs.
//!
//! Interval bounds are non-negative, so they only prune while they are positive (a zero
//! bound says nothing about how deep two volumes interpenetrate).

use super::{BoundingSphere, Segment};
use crate::obb::LocalInterval;
use crate::primitives::Ssv;
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

/// The SSVs of B in A's box frame (their intervals and squared gaps to A's box), computed
/// on first use: only columns that meet a pair surviving the sphere bound are transformed.
pub(super) struct Columns {
    /// Column j's interval and squared gap once computed.
    col: [Option<(LocalInterval, f64)>; MAX_COLUMNS],
}

impl Columns {
    /// No column computed yet.
    #[inline(always)]
    pub fn new() -> Self {
        Self {
            col: [None; MAX_COLUMNS],
        }
    }

    /// Column `j`: B's SSV `j` in A's box frame and its squared gap to A's box (unbounded
    /// and 0 beyond [`MAX_COLUMNS`]).
    #[inline(always)]
    pub fn get(&mut self, a: &Segment, b: &Segment, j: usize) -> (&LocalInterval, f64) {
        match self.col.get_mut(j) {
            Some(slot) => {
                let (iv, sq) = slot.get_or_insert_with(|| {
                    let box_a = a.world_obb();
                    let iv = box_a.local_interval(&b.world_ssvs()[j]);
                    (iv, iv.distance_squared(&box_a.own_interval()))
                });
                (iv, *sq)
            }
            None => (&UNBOUNDED_REF.0, 0.0),
        }
    }
}

/// Holder of the interval that bounds nothing (columns beyond [`MAX_COLUMNS`]).
struct Unbounded(LocalInterval);
/// The unbounded interval (a `static` cannot call `Vector3::repeat`, so it is spelled out).
static UNBOUNDED_REF: Unbounded = Unbounded(LocalInterval {
    lo: Vector3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY),
    hi: Vector3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY),
});

/// Whether a signed lower bound excludes a distance below `best`.
#[inline(always)]
pub(super) fn axis_excludes(lower: f64, best: f64) -> bool {
    lower >= best + SLACK
}

/// The unit direction from A's box centre to B's (`None` if they coincide).
#[inline(always)]
pub(super) fn box_axis(a: &Segment, b: &Segment) -> Option<Vector3<f64>> {
    let d = b.world_obb().center - a.world_obb().center;
    let n2 = d.norm_squared();
    if n2 > 0.0 && n2.is_finite() {
        Some(d / n2.sqrt())
    } else {
        None
    }
}

/// `max x . n` over an SSV (radius included); +inf without an axis (bounds nothing).
#[inline(always)]
pub(super) fn axis_max(s: &Ssv, n: Option<&Vector3<f64>>) -> f64 {
    match n {
        Some(n) => {
            let m = s
                .vertices()
                .iter()
                .map(|v| v.coords.dot(n))
                .fold(f64::NEG_INFINITY, f64::max);
            m + s.radius()
        }
        None => f64::INFINITY,
    }
}

/// `min x . n` over each SSV of B (radius included), for the first [`MAX_COLUMNS`] SSVs;
/// -inf without an axis or beyond them, so that differences with [`axis_max`] never exclude.
pub(super) struct AxisSupport {
    lo: [f64; MAX_COLUMNS],
    min: f64,
}

impl AxisSupport {
    /// The supports of `ssvs` along `n`.
    #[inline(always)]
    pub fn new(ssvs: &[Ssv], n: Option<&Vector3<f64>>) -> Self {
        let mut sup = Self {
            lo: [f64::NEG_INFINITY; MAX_COLUMNS],
            min: f64::NEG_INFINITY,
        };
        if let Some(n) = n {
            if ssvs.len() <= MAX_COLUMNS {
                let mut min = f64::INFINITY;
                for (lo, s) in sup.lo.iter_mut().zip(ssvs) {
                    let m = s
                        .vertices()
                        .iter()
                        .map(|v| v.coords.dot(n))
                        .fold(f64::INFINITY, f64::min);
                    *lo = m - s.radius();
                    min = min.min(*lo);
                }
                sup.min = min;
            }
        }
        sup
    }

    /// Support of SSV `j` (-inf when untracked).
    #[inline(always)]
    pub fn get(&self, j: usize) -> f64 {
        self.lo.get(j).copied().unwrap_or(f64::NEG_INFINITY)
    }

    /// Smallest support over all SSVs.
    #[inline(always)]
    pub fn min(&self) -> f64 {
        self.min
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

/// Squared interval bound of pair (i, j) with row `i`'s interval: the larger of the bounds
/// in B's and A's box frames.
#[inline(always)]
pub(super) fn pair_sq(
    a: &Segment,
    b: &Segment,
    cols: &mut Columns,
    i: usize,
    row: &LocalInterval,
    j: usize,
) -> f64 {
    let in_b = row.distance_squared(&b.ssv_intervals()[j]);
    let (col, _) = cols.get(a, b, j);
    in_b.max(a.ssv_intervals()[i].distance_squared(col))
}

/// A promising first pair for an unbounded search: the smallest interval bound, ties (zero
/// bounds) broken by the sphere bound.
pub(super) fn seed(a: &Segment, b: &Segment, cols: &mut Columns) -> Option<(usize, usize)> {
    let mut best: Option<(usize, usize, f64, f64)> = None;
    for i in 0..a.len() {
        let (iv, _) = row(a, b, i);
        for j in 0..b.len() {
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
