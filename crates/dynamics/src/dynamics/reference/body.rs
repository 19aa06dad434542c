//! One rigid body in the thesis' notation: the spatial transform `C_i` (2.36), the mass matrix
//! `M_i` (2.22) and the force vector `f_i = f_g + f_ext - h_i` (2.56), as dense 6x6 matrices
//! and 6-vectors `[angular; linear]` in the body frame.

use crate::spatial::{RigidInertia, Wrench};
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

/// The cross-product matrix `a~` with `a~ b = a x b` (notation of (2.13)).
pub(super) fn skew(a: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -a.z, a.y, a.z, 0.0, -a.x, -a.y, a.x, 0.0)
}

/// `C_kp = [A_kp, 0; -A_kp r~_PO, A_kp]` (2.36), `r_PO` in parent coordinates.
pub(super) fn transform(rot_kp: &Matrix3<f64>, r_po: &Vector3<f64>) -> Matrix6<f64> {
    let mut c = Matrix6::zeros();
    c.fixed_view_mut::<3, 3>(0, 0).copy_from(rot_kp);
    c.fixed_view_mut::<3, 3>(3, 3).copy_from(rot_kp);
    c.fixed_view_mut::<3, 3>(3, 0)
        .copy_from(&(-rot_kp * skew(r_po)));
    c
}

/// `M = [I_O, m r~_OC; m r~_OC^T, m E]` (2.22), about the body-frame origin `O`.
pub(super) fn mass_matrix(inertia: &RigidInertia) -> Matrix6<f64> {
    let m = inertia.mass();
    let c = skew(&inertia.com());
    let i_o = inertia.inertia_about_com() - c * c * m; // I_O = -int r~ r~ dm (2.21)
    let mut out = Matrix6::zeros();
    out.fixed_view_mut::<3, 3>(0, 0).copy_from(&i_o);
    out.fixed_view_mut::<3, 3>(0, 3).copy_from(&(c * m));
    out.fixed_view_mut::<3, 3>(3, 0)
        .copy_from(&(c.transpose() * m));
    out.fixed_view_mut::<3, 3>(3, 3)
        .copy_from(&(Matrix3::identity() * m));
    out
}

/// `f_i = [m r~_OC g; m g] + [T + r~ F; F] - [w~ I_O w; m w~ w~ r_OC]` (2.56) for the body
/// angular velocity `w`, gravity `g` and external wrench, all in body coordinates.
pub(super) fn force(
    inertia: &RigidInertia,
    omega: &Vector3<f64>,
    gravity: &Vector3<f64>,
    external: Option<&Wrench>,
) -> Vector6<f64> {
    let m = inertia.mass();
    let r_oc = inertia.com();
    let i_o = mass_matrix(inertia).fixed_view::<3, 3>(0, 0).into_owned();
    let f_g = stack(&(r_oc.cross(gravity) * m), &(gravity * m));
    let h = stack(
        &omega.cross(&(i_o * omega)),
        &(omega.cross(&omega.cross(&r_oc)) * m),
    );
    let f_e = external.map_or(Vector6::zeros(), |w| stack(&w.ang, &w.lin));
    f_g + f_e - h
}

/// `[top; bottom]`.
pub(super) fn stack(top: &Vector3<f64>, bottom: &Vector3<f64>) -> Vector6<f64> {
    Vector6::new(top.x, top.y, top.z, bottom.x, bottom.y, bottom.z)
}

/// The angular (upper) part of a 6-vector.
pub(super) fn upper(x: &Vector6<f64>) -> Vector3<f64> {
    Vector3::new(x[0], x[1], x[2])
}

/// The linear (lower) part of a 6-vector.
pub(super) fn lower(x: &Vector6<f64>) -> Vector3<f64> {
    Vector3::new(x[3], x[4], x[5])
}
