//! Preallocated buffers and small helpers shared by all integration methods.

use super::error::{IntegrateError, Quantity};
use super::settings::StepStats;
use super::OdeSystem;

/// Position block length and position-rate function of a split system, for symplectic Euler.
pub(crate) type Split<S> = Option<(usize, fn(&S, &[f64], &mut [f64]))>;

/// Buffers of length `n`, allocated once by [`super::Integrator::new`].
#[derive(Debug, Clone)]
pub(crate) struct Work {
    /// Stage derivatives `k1..k7` (RK4 uses four, Euler one).
    pub k: [Vec<f64>; 7],
    /// Stage state.
    pub stage: Vec<f64>,
    /// Candidate state at the end of a step.
    pub next: Vec<f64>,
    /// Dense-output value handed to the sink.
    pub out: Vec<f64>,
}

impl Work {
    /// Zeroed buffers for dimension `n`.
    pub fn new(n: usize) -> Self {
        let v = || vec![0.0; n];
        Work {
            k: std::array::from_fn(|_| v()),
            stage: v(),
            next: v(),
            out: v(),
        }
    }
}

/// Sorted output times and the sink receiving `(t, z(t))`; `next` indexes the first pending.
pub(crate) struct Outputs<'a, F> {
    pub times: &'a [f64],
    pub next: usize,
    pub sink: F,
}

impl<F: FnMut(f64, &[f64])> Outputs<'_, F> {
    /// Next pending output time, if any is `<= t`.
    pub fn due(&self, t: f64) -> Option<f64> {
        self.times.get(self.next).copied().filter(|&to| to <= t)
    }
}

/// Evaluates `out = f(t, z)`, counts it, and rejects a non-finite result.
pub(crate) fn eval<S: OdeSystem>(
    sys: &mut S,
    t: f64,
    z: &[f64],
    out: &mut [f64],
    stats: &mut StepStats,
) -> Result<(), IntegrateError<S::Error>> {
    stats.rhs_evals += 1;
    sys.rhs(t, z, out).map_err(IntegrateError::System)?;
    finite(out, t, Quantity::Derivative)
}

/// `Err(NonFinite)` unless every entry of `x` is finite.
pub(crate) fn finite<E: std::error::Error>(
    x: &[f64],
    t: f64,
    what: Quantity,
) -> Result<(), IntegrateError<E>> {
    if all_finite(x) {
        Ok(())
    } else {
        Err(IntegrateError::NonFinite { t, what })
    }
}

/// True if every entry of `x` is finite: a branch-free fold (vectorised), not a short-circuit
/// scan, since the answer is almost always yes.
#[inline]
pub(crate) fn all_finite(x: &[f64]) -> bool {
    x.iter().fold(true, |ok, v| ok & v.is_finite())
}

/// Projects the accepted state `z` and reports whether the projection changed it.
pub(crate) fn project<S: OdeSystem>(sys: &S, z: &mut [f64], before: &[f64]) -> bool {
    sys.project(z);
    z.iter()
        .zip(before)
        .any(|(a, b)| a.to_bits() != b.to_bits())
}
