//! Input validation shared by the public entry points (errors, never panics).

use crate::model::joint::Joint;
use crate::spatial::Wrench;
use crate::{Data, DynamicsError, Model};
use nalgebra::DVector;

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

/// [`any_non_finite`] over the six components of each wrench.
#[inline]
fn any_non_finite_wrench(fs: &[Wrench]) -> bool {
    let bits = |v: &nalgebra::Vector3<f64>| {
        non_finite_bit(v.x) | non_finite_bit(v.y) | non_finite_bit(v.z)
    };
    fs.iter()
        .fold(0, |acc, f| acc | bits(&f.ang) | bits(&f.lin))
        != 0
}

/// Length and finiteness of `q`, and non-zero free-joint quaternions.
pub(crate) fn configuration(model: &Model, q: &DVector<f64>) -> Result<(), DynamicsError> {
    vector("q", q, model.nq())?;
    for b in &model.bodies {
        if matches!(b.joint, Joint::Quaternion) {
            let n2 = q.rows(b.q_index + 3, 4).norm_squared();
            if n2.is_nan() || n2 <= 1e-24 {
                return Err(DynamicsError::ZeroQuaternion {
                    q_index: b.q_index + 3,
                });
            }
        }
    }
    Ok(())
}

/// One finite wrench per body.
pub(crate) fn wrenches(model: &Model, fext: Option<&[Wrench]>) -> Result<(), DynamicsError> {
    let Some(fext) = fext else { return Ok(()) };
    if fext.len() != model.nbodies() {
        return Err(mismatch("fext", model.nbodies(), fext.len()));
    }
    if !any_non_finite_wrench(fext) {
        return Ok(());
    }
    let index = fext.iter().position(|f| !f.is_finite()).unwrap_or(0);
    Err(DynamicsError::NonFinite {
        argument: "fext",
        index,
    })
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
        /// The bit scans agree with `f64::is_finite` for every position of a bad entry.
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
            let fs: Vec<Wrench> = xs
                .chunks_exact(6)
                .map(|c| Wrench::from_vector(&nalgebra::Vector6::from_column_slice(c)))
                .collect();
            let expect = fs.iter().any(|f| !f.is_finite());
            prop_assert_eq!(any_non_finite_wrench(&fs), expect);
        }
    }
}
