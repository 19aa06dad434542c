//! Allocation-free SE(3) step of a quaternion free joint for [`super::LolaTasks`]'s retract:
//! the same map as [`biped_dynamics::integrate`] (constant body twist `v = [nu; w]` over the
//! step, `q = [x, y, z, qx, qy, qz, qw]`), checked against it in the tests.

use biped_dynamics::configuration::left_jacobian;
use nalgebra::{DVector, Quaternion, UnitQuaternion, Vector3};

/// Writes the free-joint pose at `q[qi..qi+7]` moved by the body twist `v[vi..vi+6] * step`
/// into `out[qi..qi+7]`.
pub(crate) fn integrate_free(
    q: &DVector<f64>,
    v: &DVector<f64>,
    qi: usize,
    vi: usize,
    step: f64,
    out: &mut DVector<f64>,
) {
    let quat = Quaternion::new(q[qi + 6], q[qi + 3], q[qi + 4], q[qi + 5]);
    let rot = UnitQuaternion::new_normalize(quat);
    let t = Vector3::new(q[qi], q[qi + 1], q[qi + 2]);
    let nu = Vector3::new(v[vi], v[vi + 1], v[vi + 2]) * step;
    let w = Vector3::new(v[vi + 3], v[vi + 4], v[vi + 5]) * step;
    let t_new = t + rot * (left_jacobian(&w) * nu);
    let r_new = rot * UnitQuaternion::from_scaled_axis(w);
    let c = r_new.quaternion().coords;
    for k in 0..3 {
        out[qi + k] = t_new[k];
    }
    for k in 0..4 {
        out[qi + 3 + k] = c[k];
    }
}
