//! Shared finite-difference checks for the mechanism tests (`mech_*.rs`).
#![allow(dead_code)]

use biped_dynamics::mechanism::{CoupledMotion, Coupling, MAX_COUPLED};
use nalgebra::{Isometry3, Vector3, Vector6};

/// Finite-difference step along `q + qd t`.
pub const H: f64 = 1e-5;

/// `q + qd t` for slices.
fn along(q: &[f64], qd: &[f64], t: f64) -> Vec<f64> {
    q.iter().zip(qd).map(|(a, b)| a + b * t).collect()
}

/// Relative twist `[omega; v]` (part frame) by central differences of the pose.
pub fn fd_twist(
    before: &Isometry3<f64>,
    now: &Isometry3<f64>,
    after: &Isometry3<f64>,
    h: f64,
) -> Vector6<f64> {
    let drot = before.rotation.inverse() * after.rotation;
    let w = drot.scaled_axis() / (2.0 * h);
    let w_now = now.rotation.inverse() * (before.rotation * w);
    // `drot` is the rotation over [t-h, t+h] in the frame at t-h; bring it to the frame at t.
    let v =
        now.rotation.inverse() * (after.translation.vector - before.translation.vector) / (2.0 * h);
    Vector6::new(w_now.x, w_now.y, w_now.z, v.x, v.y, v.z)
}

/// Richardson extrapolation `(4 D(H/2) - D(H)) / 3` of a central difference `D(h)`: O(H^4)
/// truncation, so fast rotor spins (hundreds of rad/s) stay within the tolerance.
fn richardson(d: impl Fn(f64) -> Vector6<f64>) -> Vector6<f64> {
    (d(H / 2.0) * 4.0 - d(H)) / 3.0
}

/// `J qd` from a motion.
pub fn j_times(m: &CoupledMotion, qd: &[f64]) -> Vector6<f64> {
    qd.iter().enumerate().map(|(j, x)| m.jacobian[j] * *x).sum()
}

/// Asserts `a ~ b` with tolerance `tol * (1 + |b|)` component-wise, with a label.
pub fn assert_close6(a: &Vector6<f64>, b: &Vector6<f64>, tol: f64, what: &str) {
    let scale = 1.0 + b.amax().max(a.amax());
    assert!(
        (a - b).amax() <= tol * scale,
        "{what}: {a:?} vs {b:?} (diff {:e})",
        (a - b).amax()
    );
}

/// Checks pose, Jacobian (each column and `J qd`) and bias of `c` against central differences
/// along `q + qd t`, and that unused Jacobian columns are zero.
pub fn check_coupling(c: &dyn Coupling, q: &[f64], qd: &[f64], tol: f64) {
    let n = c.n_inputs();
    let m = c.motion(q, qd).expect("motion");
    assert!(m.pose.translation.vector.iter().all(|x| x.is_finite()));
    for j in n..MAX_COUPLED {
        assert_eq!(m.jacobian[j], Vector6::zeros());
    }
    let zero = vec![0.0; n];
    let pose_at = |t: f64, dir: &[f64]| c.motion(&along(q, dir, t), &zero).unwrap().pose;
    // J qd and each column.
    let mut dirs: Vec<Vec<f64>> = (0..n)
        .map(|j| (0..n).map(|k| f64::from(u8::from(j == k))).collect())
        .collect();
    dirs.push(qd.to_vec());
    for dir in &dirs {
        let fd = richardson(|h| fd_twist(&pose_at(-h, dir), &m.pose, &pose_at(h, dir), h));
        assert_close6(&j_times(&m, dir), &fd, tol, "J qd vs FD of pose");
    }
    // bias = d/dt J(q + qd t) qd.
    let jq = |t: f64| j_times(&c.motion(&along(q, qd, t), qd).unwrap(), qd);
    let fd_bias = richardson(|h| (jq(h) - jq(-h)) / (2.0 * h));
    assert_close6(&m.bias, &fd_bias, tol, "bias vs FD of J qd");
    // bias must not depend on qdd, and J must not depend on qd.
    let m0 = c.motion(q, &zero).unwrap();
    for j in 0..n {
        assert_close6(
            &m0.jacobian[j],
            &m.jacobian[j],
            1e-14,
            "J independent of qd",
        );
    }
}

/// Rotation part of a pose applied to a vector (helper for geometry checks).
pub fn rot(p: &Isometry3<f64>, v: Vector3<f64>) -> Vector3<f64> {
    p.rotation * v
}
