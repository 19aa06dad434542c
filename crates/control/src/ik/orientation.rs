//! Orientation error by the equivalent angle-axis representation and Euler Z-X-Z angles
//! (thesis Appendix C, (C.1)-(C.6)).
//!
//! Convention: with the current orientation `A` and the desired `A_d` (columns = frame axes in
//! the reference frame), the error is `Delta x_rot = gamma e_e = log(A_d A^T)` (C.1), expressed
//! in the reference frame. It matches the geometric Jacobian (C.8): `dA/dt = [omega]x A`, so
//! for a small rotation `A_d = exp([dx]x) A` the error is `dx` and the closed loop (C.11)
//! drives `omega = K dx` straight at the target. `log` is taken through nalgebra's rotation
//! logarithm (angle in `[0, pi]`); at `gamma = pi` the axis sign is arbitrary (either is valid).
//!
//! Typo resolved: (C.6) as printed contains `psi`, so it cannot invert `T(phi, theta)` of
//! (C.5); it resembles the inverse for the body-frame `A^T omega` with the rows reversed and
//! `omega_y` negated. [`euler_zxz_rates`] therefore inverts (C.5) itself
//! (tests/ik_orientation.rs derives and checks the body-frame inverse).

use nalgebra::{Matrix3, Vector3};

/// Orientation error `gamma e_e = log(A_d A^T)` (C.1) in the reference frame.
pub fn orientation_error(desired: &Matrix3<f64>, current: &Matrix3<f64>) -> Vector3<f64> {
    rotation_log(&(desired * current.transpose()))
}

/// Rotation logarithm `gamma e` of a rotation matrix (Appendix C), accurate near 0 and pi:
/// the shared implementation [`biped_robots::calibration::so3_log`].
pub fn rotation_log(r: &Matrix3<f64>) -> Vector3<f64> {
    biped_robots::calibration::so3_log(r)
}

/// Rotation matrix `A_Id` of Euler Z-X-Z angles `(phi, theta, psi)` (C.3).
pub fn euler_zxz_matrix(phi: f64, theta: f64, psi: f64) -> Matrix3<f64> {
    let (sf, cf) = phi.sin_cos();
    let (st, ct) = theta.sin_cos();
    let (sp, cp) = psi.sin_cos();
    Matrix3::new(
        cf * cp - sf * ct * sp,
        -cf * sp - sf * ct * cp,
        sf * st,
        sf * cp + cf * ct * sp,
        -sf * sp + cf * ct * cp,
        -cf * st,
        st * sp,
        st * cp,
        ct,
    )
}

/// Euler Z-X-Z angles `(phi, theta, psi)` recovered from a rotation matrix (C.4a)-(C.4c).
pub fn euler_zxz_angles(a: &Matrix3<f64>) -> (f64, f64, f64) {
    let (a31, a32) = (a[(2, 0)], a[(2, 1)]);
    let psi = if a31 == 0.0 && a32 == 0.0 {
        0.0
    } else {
        a31.atan2(a32)
    };
    let (sp, cp) = psi.sin_cos();
    let theta = (a31 * sp + a32 * cp).atan2(a[(2, 2)]);
    let phi = (a[(1, 0)] * cp - a[(1, 1)] * sp).atan2(a[(0, 0)] * cp - a[(0, 1)] * sp);
    (phi, theta, psi)
}

/// Matrix `T(x_rot)` mapping Euler Z-X-Z rates to the angular velocity, `omega = T xdot` (C.5).
pub fn euler_zxz_rate_matrix(phi: f64, theta: f64) -> Matrix3<f64> {
    let (sf, cf) = phi.sin_cos();
    let (st, ct) = theta.sin_cos();
    Matrix3::new(0.0, cf, sf * st, 0.0, sf, -cf * st, 1.0, 0.0, ct)
}

/// Euler Z-X-Z rates from an angular velocity (C.6); `None` at the singularity `sin theta = 0`.
pub fn euler_zxz_rates(phi: f64, theta: f64, omega: &Vector3<f64>) -> Option<Vector3<f64>> {
    euler_zxz_rate_matrix(phi, theta)
        .try_inverse()
        .map(|t| t * omega)
        .filter(|r| r.iter().all(|x| x.is_finite()))
}
