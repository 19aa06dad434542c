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
    match w.iter().position(|x| !x.is_finite()) {
        Some(index) => Err(DynamicsError::NonFinite { argument, index }),
        None => Ok(()),
    }
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
    match fext.iter().position(|f| !f.is_finite()) {
        Some(index) => Err(DynamicsError::NonFinite {
            argument: "fext",
            index,
        }),
        None => Ok(()),
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
