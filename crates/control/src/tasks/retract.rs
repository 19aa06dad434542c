//! `q (+) v step` on any model without allocation: quaternion free joints move on SE(3)
//! (constant body twist, as [`biped_dynamics::integrate`]), all other coordinates add.

use crate::error::IkError;
use crate::ik::linalg::{check_dim, check_finite};
use biped_dynamics::{JointModel, Model};
use nalgebra::DVector;

/// Writes `q (+) v step` of `model` into `out`.
pub(crate) fn retract_configuration(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
    step: f64,
    out: &mut DVector<f64>,
) -> Result<(), IkError> {
    check_dim("retract q", model.nq(), q.len())?;
    check_dim("retract v", model.nv(), v.len())?;
    check_dim("retract output", q.len(), out.len())?;
    out.copy_from(q);
    for b in model.bodies().iter().filter(|b| b.owns_coordinates()) {
        let (qi, vi) = (b.q_index(), b.v_index());
        match b.joint() {
            JointModel::FreeQuaternion => super::se3::integrate_free(q, v, qi, vi, step, out),
            jm => {
                for c in 0..jm.nv() {
                    out[qi + c] += v[vi + c] * step;
                }
            }
        }
    }
    check_finite("retract output", out.as_slice())
}
