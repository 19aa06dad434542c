//! Choosing the segment pairs of a fitted model by sampling configurations, as MoveIt's setup
//! assistant does: pairs of adjacent bodies are left out, and of the others those that never
//! come closer than the activation distance `d_a` in any sample (they cannot meet) and those
//! in contact in (almost) every sample (always touching: nothing to avoid).

use crate::model::{CollisionModel, ModelError};
use crate::segment::PairQuery;
use nalgebra::Isometry3;

/// Fraction of the samples in contact from which a pair counts as always touching.
pub const ALWAYS_IN_CONTACT: f64 = 0.95;

/// How often one candidate pair came close over the samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PairCount {
    /// First segment.
    pub a: usize,
    /// Second segment.
    pub b: usize,
    /// Samples in which the pair was closer than `d_a`.
    pub close: usize,
    /// Samples in which the pair was in contact (distance <= 0).
    pub contact: usize,
}

impl PairCount {
    /// Whether the pair is kept after `samples` samples: close at least once and in contact
    /// in fewer than [`ALWAYS_IN_CONTACT`] of them.
    pub fn kept(&self, samples: usize) -> bool {
        self.close > 0 && (self.contact as f64) < ALWAYS_IN_CONTACT * samples as f64
    }
}

/// Every pair of segments `a < b` on different bodies that are not `adjacent` (bodies by
/// index, e.g. parent and child).
pub fn candidates(
    segment_bodies: &[usize],
    adjacent: impl Fn(usize, usize) -> bool,
) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    for (a, &ba) in segment_bodies.iter().enumerate() {
        for (b, &bb) in segment_bodies.iter().enumerate().skip(a + 1) {
            if ba != bb && !adjacent(ba, bb) && !adjacent(bb, ba) {
                out.push((a, b));
            }
        }
    }
    out
}

/// Counts, over `samples` configurations, how often each pair of `model` is closer than its
/// `d_a` and in contact; `poses` fills the body poses of sample `k` (one per body).
pub fn count<E: From<ModelError>>(
    model: &mut CollisionModel,
    samples: usize,
    mut poses: impl FnMut(usize, &mut [Isometry3<f64>]) -> Result<(), E>,
) -> Result<Vec<PairCount>, E> {
    model.set_pair_query(PairQuery::WithinActivation);
    let d_a = model.activation_distance();
    let mut counts: Vec<PairCount> = model
        .pairs()
        .iter()
        .map(|p| PairCount {
            a: p.a,
            b: p.b,
            close: 0,
            contact: 0,
        })
        .collect();
    let mut buffer = vec![Isometry3::identity(); model.bodies().len()];
    for k in 0..samples {
        poses(k, &mut buffer)?;
        model.update(&buffer)?;
        for (count, result) in counts.iter_mut().zip(model.results()) {
            if let Some(d) = result.distance() {
                count.close += usize::from(d < d_a);
                count.contact += usize::from(d <= 0.0);
            }
        }
    }
    Ok(counts)
}
