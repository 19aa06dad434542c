//! Configuration-space operations: `q (+) v dt` and its inverse, with quaternion free joints
//! integrated on SE(3) (constant body twist over the step).

use crate::check;
use crate::model::joint::Joint;
use crate::spatial::skew;
use crate::{DynamicsError, Model};
use nalgebra::{DVector, Matrix3, Quaternion, UnitQuaternion, Vector3};

/// Largest accepted deviation of a free-joint quaternion's norm from 1: every function taking a
/// `q` rejects a quaternion outside `[1 - tol, 1 + tol]` with
/// [`DynamicsError::QuaternionNorm`] (or [`DynamicsError::ZeroQuaternion`]) and uses the
/// normalised quaternion inside. The margin admits the drift of explicit integrator stages,
/// which leave the unit sphere by about `(h |omega|)^2 / 8` (below 1 % for steps that turn the
/// body by less than 0.28 rad); an unnormalised or mistyped quaternion (`[0, 0, 0, 2]`, or
/// components of 1e155 whose squares overflow) is an error, never silently rescaled.
pub const QUATERNION_NORM_TOLERANCE: f64 = 1e-2;

/// `q (+) v dt`: vector joints add `v dt`; quaternion free joints move with the constant body
/// twist `v` for time `dt` (SE(3) exponential), result quaternion normalised.
pub fn integrate(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
    dt: f64,
) -> Result<DVector<f64>, DynamicsError> {
    check::configuration(model, q)?;
    check::vector("v", v, model.nv())?;
    if !dt.is_finite() {
        return Err(DynamicsError::NonFinite {
            argument: "dt",
            index: 0,
        });
    }
    let mut out = q.clone();
    for b in model.bodies.iter().filter(|b| b.owns_coordinates) {
        let (qi, vi) = (b.q_index, b.v_index);
        match b.joint {
            Joint::Quaternion => {
                let (rot, t) = free_pose(q, qi);
                let nu = Vector3::new(v[vi], v[vi + 1], v[vi + 2]) * dt;
                let w = Vector3::new(v[vi + 3], v[vi + 4], v[vi + 5]) * dt;
                let t_new = t + rot * (left_jacobian(&w) * nu);
                let r_new = rot * UnitQuaternion::from_scaled_axis(w);
                write_free_pose(&mut out, qi, &r_new, &t_new);
            }
            _ => {
                for c in 0..b.joint_model.nv() {
                    out[qi + c] += v[vi + c] * dt;
                }
            }
        }
    }
    Ok(out)
}

/// A second state near `(q, v)` for timing loops: `q (+) 1e-3` along every coordinate and
/// `v + 1e-3`. Alternating the two makes each forward-dynamics call a fresh pass (a repeated
/// bitwise-equal `(q, v)` reuses the kinematics, see [`crate::forward_dynamics_kinematics`]).
pub fn nearby_state(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> Result<(DVector<f64>, DVector<f64>), DynamicsError> {
    check::vector("v", v, model.nv())?;
    let step = DVector::from_element(model.nv(), 1.0);
    Ok((integrate(model, q, &step, 1e-3)?, v.add_scalar(1e-3)))
}

/// `v` with `integrate(q0, v, 1) = q1` (the group logarithm for quaternion free joints).
pub fn difference(
    model: &Model,
    q0: &DVector<f64>,
    q1: &DVector<f64>,
) -> Result<DVector<f64>, DynamicsError> {
    check::configuration(model, q0)?;
    check::configuration(model, q1)?;
    let mut v = DVector::zeros(model.nv());
    for b in model.bodies.iter().filter(|b| b.owns_coordinates) {
        let (qi, vi) = (b.q_index, b.v_index);
        match b.joint {
            Joint::Quaternion => {
                let (r0, t0) = free_pose(q0, qi);
                let (r1, t1) = free_pose(q1, qi);
                let w = (r0.inverse() * r1).scaled_axis();
                let nu = left_jacobian_inverse(&w) * (r0.inverse() * (t1 - t0));
                v.rows_mut(vi, 3).copy_from(&nu);
                v.rows_mut(vi + 3, 3).copy_from(&w);
            }
            _ => {
                for c in 0..b.joint_model.nv() {
                    v[vi + c] = q1[qi + c] - q0[qi + c];
                }
            }
        }
    }
    Ok(v)
}

/// Rotation and translation of a quaternion free joint in `q`.
fn free_pose(q: &DVector<f64>, qi: usize) -> (UnitQuaternion<f64>, Vector3<f64>) {
    let quat = Quaternion::new(q[qi + 6], q[qi + 3], q[qi + 4], q[qi + 5]);
    (
        UnitQuaternion::new_normalize(quat),
        Vector3::new(q[qi], q[qi + 1], q[qi + 2]),
    )
}

/// Writes a free-joint pose into `q` as `[x, y, z, qx, qy, qz, qw]`.
fn write_free_pose(q: &mut DVector<f64>, qi: usize, r: &UnitQuaternion<f64>, t: &Vector3<f64>) {
    q.rows_mut(qi, 3).copy_from(t);
    let c = r.quaternion().coords; // [x, y, z, w]
    q.rows_mut(qi + 3, 4).copy_from(&c);
}

/// SO(3) left Jacobian `V(w) = E + (1 - cos t)/t^2 w~ + (t - sin t)/t^3 w~^2`, `t = |w|`
/// (maps a constant body twist's linear part to the translation of the SE(3) exponential).
pub fn left_jacobian(w: &Vector3<f64>) -> Matrix3<f64> {
    let t2 = w.norm_squared();
    let k = skew(w);
    let (a, b) = if t2 < 1e-8 {
        (0.5 - t2 / 24.0, 1.0 / 6.0 - t2 / 120.0)
    } else {
        let t = t2.sqrt();
        ((1.0 - t.cos()) / t2, (t - t.sin()) / (t2 * t))
    };
    Matrix3::identity() + k * a + k * k * b
}

/// Inverse of [`left_jacobian`]: `E - w~/2 + (1/t^2)(1 - t sin t / (2 (1 - cos t))) w~^2`.
fn left_jacobian_inverse(w: &Vector3<f64>) -> Matrix3<f64> {
    let t2 = w.norm_squared();
    let k = skew(w);
    let c = if t2 < 1e-8 {
        1.0 / 12.0 + t2 / 720.0
    } else {
        let t = t2.sqrt();
        (1.0 - t * t.sin() / (2.0 * (1.0 - t.cos()))) / t2
    };
    Matrix3::identity() - k * 0.5 + k * k * c
}
