//! Recursive Newton-Euler inverse dynamics: `tau = J^T (M a - f)` of (2.53) evaluated recursively.

use crate::kinematics::{add_projected_force, propagate_accelerations};
use crate::{Data, Model};
use nalgebra::DVector;

/// Backward half of RNEA after the first forward recursion: accelerations for `qdd` (`None` =
/// zero), net forces `M_i a_i - f_i`, projected with `J_i^T` into `out` (2.53-2.56).
pub(crate) fn rnea_from_kinematics(
    model: &Model,
    data: &mut Data,
    qdd: Option<&DVector<f64>>,
    out_bias: bool,
) {
    propagate_accelerations(model, data, qdd);
    for (i, body) in model.bodies.iter().enumerate() {
        data.fnet[i] = body.inertia.apply(&data.acc[i]) - data.force[i];
    }
    let mut out = if out_bias {
        std::mem::take(&mut data.nle)
    } else {
        std::mem::take(&mut data.tau)
    };
    out.as_mut_slice().fill(0.0);
    for i in (0..model.nbodies()).rev() {
        let body = &model.bodies[i];
        let f = data.fnet[i];
        add_projected_force(data, i, body, &f, &mut out);
        if let Some(p) = body.parent {
            data.fnet[p] += data.x[i].tr_apply_force(&f);
        }
    }
    if out_bias {
        data.nle = out;
    } else {
        data.tau = out;
    }
}
