//! Input validation shared by the public entry points (errors, never panics).

use crate::configuration::QUATERNION_NORM_TOLERANCE;
use crate::model::joint::Joint;
use crate::spatial::Wrench;
use crate::{Body, Data, DynamicsError, Model};
use nalgebra::{DVector, Vector3};

/// The workspace must have been built for this model.
pub(crate) fn data(model: &Model, data: &Data) -> Result<(), DynamicsError> {
    if data.nbodies() != model.nbodies() {
        return Err(mismatch("data (bodies)", model.nbodies(), data.nbodies()));
    }
    if data.nv != model.nv() || data.nq != model.nq() {
        return Err(mismatch("data (coordinates)", model.nv(), data.nv));
    }
    Ok(())
}

/// Length and finiteness of a generalized vector.
pub(crate) fn vector(
    argument: &'static str,
    w: &DVector<f64>,
    expected: usize,
) -> Result<(), DynamicsError> {
    if w.len() != expected {
        return Err(mismatch(argument, expected, w.len()));
    }
    if !any_non_finite(w.as_slice()) {
        return Ok(());
    }
    let index = w.iter().position(|x| !x.is_finite()).unwrap_or(0);
    Err(DynamicsError::NonFinite { argument, index })
}

/// A computed result must be finite: [`DynamicsError::NonFiniteResult`] at its first bad entry.
#[inline]
pub(crate) fn result(quantity: &'static str, xs: &[f64]) -> Result<(), DynamicsError> {
    if !any_non_finite(xs) {
        return Ok(());
    }
    let index = xs.iter().position(|x| !x.is_finite()).unwrap_or(0);
    Err(DynamicsError::NonFiniteResult { quantity, index })
}

/// Exponent bits of an `f64`: all set exactly for infinities and NaNs.
const EXPONENT: u64 = 0x7ff0_0000_0000_0000;

/// 1 if `x` is infinite or NaN, else 0 (branch-free, so scans of it vectorise).
#[inline(always)]
fn non_finite_bit(x: f64) -> u64 {
    u64::from(x.to_bits() & EXPONENT == EXPONENT)
}

/// True if any entry is infinite or NaN: one branch-free OR-fold (the index of the first bad
/// entry is searched only when there is one).
#[inline]
pub(crate) fn any_non_finite(xs: &[f64]) -> bool {
    xs.iter().fold(0, |acc, &x| acc | non_finite_bit(x)) != 0
}

/// Index of the first wrench with an infinite or NaN component. Screened by the sum of all
/// components in six independent accumulators (one addition per component): a NaN or an
/// infinity makes every sum it enters non-finite, so a finite sum clears them all; a
/// non-finite sum (a bad entry, or finite entries overflowing) is settled by the exact scan.
#[inline]
fn first_non_finite_wrench(fs: &[Wrench]) -> Option<usize> {
    let (mut ang, mut lin) = (Vector3::zeros(), Vector3::zeros());
    for f in fs {
        ang += f.ang;
        lin += f.lin;
    }
    if ang.iter().chain(lin.iter()).all(|x| x.is_finite()) {
        return None;
    }
    fs.iter().position(|f| !f.is_finite())
}

/// A one-DoF pivot `D = J^T M-bar J` of the O(n) backward pass (2.67) must be positive and
/// finite, else [`DynamicsError::NotPositiveDefinite`] at velocity index `index`: one integer
/// comparison of the bits less one (positive finite doubles are exactly the patterns
/// `1..INFINITY`; zero wraps around, negatives and NaNs lie above), where the two float
/// comparisons compile to a classification of the value.
#[inline(always)]
pub(crate) fn positive_pivot(index: usize, d: f64) -> Result<(), DynamicsError> {
    if d.to_bits().wrapping_sub(1) < f64::INFINITY.to_bits() - 1 {
        return Ok(());
    }
    Err(DynamicsError::NotPositiveDefinite { index, pivot: d })
}

/// Squared-norm bounds `(1 -+ tol)^2` of an accepted free-joint quaternion.
const QUAT_NORM2_MIN: f64 = (1.0 - QUATERNION_NORM_TOLERANCE) * (1.0 - QUATERNION_NORM_TOLERANCE);
/// See [`QUAT_NORM2_MIN`].
const QUAT_NORM2_MAX: f64 = (1.0 + QUATERNION_NORM_TOLERANCE) * (1.0 + QUATERNION_NORM_TOLERANCE);

/// Length and finiteness of `q`, and free-joint quaternions of norm within
/// [`QUATERNION_NORM_TOLERANCE`] of 1. A squared norm in range cannot have overflowed or
/// underflowed (its entries are finite and at most ~1), so one comparison settles the valid case.
pub(crate) fn configuration(model: &Model, q: &DVector<f64>) -> Result<(), DynamicsError> {
    vector("q", q, model.nq())?;
    for b in &model.bodies {
        if matches!(b.joint, Joint::Quaternion) {
            let n2 = q.rows(b.q_index + 3, 4).norm_squared();
            if !(QUAT_NORM2_MIN..=QUAT_NORM2_MAX).contains(&n2) {
                return Err(quaternion_error(b, q));
            }
        }
    }
    Ok(())
}

/// The error of a free-joint quaternion outside the tolerance, with its norm computed without
/// overflow or underflow (a norm below 1e-12 is [`DynamicsError::ZeroQuaternion`]).
#[cold]
fn quaternion_error(b: &Body, q: &DVector<f64>) -> DynamicsError {
    let q_index = b.q_index + 3;
    let norm = scaled_norm(&q.as_slice()[q_index..q_index + 4]);
    if norm <= 1e-12 {
        return DynamicsError::ZeroQuaternion { q_index };
    }
    DynamicsError::QuaternionNorm {
        joint: b.joint_name.clone(),
        q_index,
        norm,
        tolerance: QUATERNION_NORM_TOLERANCE,
    }
}

/// Euclidean norm of finite entries without overflow or underflow: the entries are divided by
/// the largest magnitude before squaring, the sum of squares is then in `[1, len]`.
pub(crate) fn scaled_norm(xs: &[f64]) -> f64 {
    let m = xs.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if m == 0.0 || !m.is_finite() {
        return m;
    }
    m * xs.iter().map(|x| (x / m) * (x / m)).sum::<f64>().sqrt()
}

/// One finite wrench per body.
pub(crate) fn wrenches(model: &Model, fext: Option<&[Wrench]>) -> Result<(), DynamicsError> {
    let Some(fext) = fext else { return Ok(()) };
    if fext.len() != model.nbodies() {
        return Err(mismatch("fext", model.nbodies(), fext.len()));
    }
    match first_non_finite_wrench(fext) {
        None => Ok(()),
        Some(index) => Err(DynamicsError::NonFinite {
            argument: "fext",
            index,
        }),
    }
}

/// A dimension-mismatch error.
fn mismatch(argument: &'static str, expected: usize, got: usize) -> DynamicsError {
    DynamicsError::DimensionMismatch {
        argument,
        expected,
        got,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The bit scan agrees with `f64::is_finite` for every position of a bad entry.
        #[test]
        fn bit_scans_match_is_finite(
            xs in prop::collection::vec(-1e300f64..1e300, 0..40),
            at in 0usize..40,
            bad in prop::sample::select(vec![f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1.0]),
        ) {
            let mut xs = xs;
            if at < xs.len() {
                xs[at] = bad;
            }
            let expect = xs.iter().any(|x| !x.is_finite());
            prop_assert_eq!(any_non_finite(&xs), expect);
        }

        /// The summed wrench screen finds the first bad wrench exactly like `is_finite`, also
        /// when finite entries near the largest `f64` overflow the sums.
        #[test]
        fn wrench_screen_matches_is_finite(
            xs in prop::collection::vec(-1.0f64..1.0, 0..60),
            scale in prop::sample::select(vec![1.0, 1e300, f64::MAX]),
            at in 0usize..60,
            bad in prop::sample::select(vec![f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1.0]),
        ) {
            let mut xs: Vec<f64> = xs.iter().map(|x| x * scale).collect();
            if at < xs.len() {
                xs[at] = bad;
            }
            let fs: Vec<Wrench> = xs
                .chunks_exact(6)
                .map(|c| Wrench::from_vector(&nalgebra::Vector6::from_column_slice(c)))
                .collect();
            let expect = fs.iter().position(|f| !f.is_finite());
            prop_assert_eq!(first_non_finite_wrench(&fs), expect);
        }
    }

    /// The pivot test rejects exactly what `d <= 0 || !d.is_finite()` rejects.
    #[test]
    fn positive_pivot_matches_sign_and_finiteness() {
        let cases = [
            f64::NAN,
            -f64::NAN,
            f64::from_bits(0x7ff0_0000_0000_0001),
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.0,
            -0.0,
            -1e-300,
            f64::MIN_POSITIVE,
            5e-324,
            1.0,
            f64::MAX,
        ];
        for d in cases {
            let bad = d <= 0.0 || !d.is_finite();
            match positive_pivot(7, d) {
                Ok(()) => assert!(!bad, "{d} accepted"),
                Err(DynamicsError::NotPositiveDefinite { index: 7, pivot }) => {
                    assert!(bad, "{d} rejected");
                    assert_eq!(pivot.to_bits(), d.to_bits());
                }
                Err(e) => panic!("unexpected {e:?}"),
            }
        }
    }
}
