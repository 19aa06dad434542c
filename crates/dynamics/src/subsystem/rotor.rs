//! Spin-invariant congruence of Harmonic Drive rotors for the O(n) backward pass (2.76).
//!
//! A rotor (3.1)-(3.2) attached directly to its sub-system's parent has `C-hat = C`, a rotation
//! by the spin angle about the z axis of a constant frame. When the rotor's inertia is
//! axisymmetric about that axis (CoM on the axis, `I_xx = I_yy`, no products of inertia), its
//! term `K = C^T M C` of (2.76) does not depend on the spin angle and is computed once per model.
//! So are its contributions to `B_S` and `M_S`: with the rotor column `J = [0, 0, N, 0, 0, 0]`
//! (3.1) and its parent-frame image `s = C^-1 J` (the spin axis, constant), `C^T M J = K s` and
//! `J^T M J = s^T K s`.
//!
//! Such a rotor's CoM is fixed in the parent frame and its inertia there is constant, so the
//! O(n) forward dynamics need no rotor kinematics at all (no spin angle, no rotor pose): its
//! velocity-product and gravity force `C^T (M b - f)` is formed in the parent frame from the
//! parent's angular velocity and gravity ([`parent_frame_bias`]). The kinematics of these
//! rotors are therefore skipped by [`crate::forward_dynamics_kinematics`] and completed only
//! where another algorithm needs them.

use super::on::add_rigid_congruence;
use crate::mechanism::harmonic_drive::HarmonicDriveRotor;
use crate::model::coupling::Mechanism;
use crate::model::JointModel;
use crate::spatial::{
    sym_congruence, ArticulatedInertia, Force, Motion, RigidInertia, SpatialTransform,
};
use crate::Model;
use nalgebra::{Matrix3, Vector3};

/// Spin-invariant quantities of one rotor member of a sub-system (see the module doc).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RotorConstant {
    /// `K = C^T M C` in the sub-system parent's frame.
    pub(crate) congruence: ArticulatedInertia,
    /// Column of the rotor's coordinate within the sub-system.
    pub(crate) column: usize,
    /// `C^T M J = K s`, the rotor's contribution to its row of `B_S`.
    pub(crate) ks: Force,
    /// `J^T M J = s^T K s`, the rotor's contribution to the diagonal of `M_S`.
    pub(crate) sks: f64,
    /// `s = C^-1 J`: the rotor column in the parent frame (`s.ang = N` times the spin axis).
    pub(crate) s: Motion,
    /// Rotor mass `m`.
    pub(crate) mass: f64,
    /// Rotor CoM in parent coordinates (on the spin axis, so constant).
    pub(crate) com: Vector3<f64>,
    /// Rotational inertia about the CoM in parent axes (constant by axisymmetry).
    pub(crate) inertia_com: Matrix3<f64>,
    /// Velocity index of the driving coordinate.
    pub(crate) v_index: usize,
}

/// `C^T (M b - f_g + h)` of a spin-invariant rotor in its parent's frame (moment about the
/// parent origin): the wrench that gives the rotor its motion at zero parent acceleration and
/// zero `qddot` against gravity, (2.56) with (2.37) moved to the parent. With the parent's
/// angular velocity `w_p` and gravity `g_p` (parent axes) and the rotor rate
/// `w_R = w_p + s.ang qd`: the CoM `c` is fixed in the parent, so `F = m (w_p x (w_p x c) - g_p)`;
/// the inertia `I_c` is constant in parent axes, so `dL/dt = w_p x (I_c w_R)` (the
/// `I_c (w_p x s qd)` terms of the rotor's angular acceleration and of the rotating
/// tensor cancel); the moment about the parent origin adds `c x F`.
#[inline]
pub(crate) fn parent_frame_bias(
    rc: &RotorConstant,
    w_p: &Vector3<f64>,
    g_p: &Vector3<f64>,
    qd: f64,
) -> Force {
    let w = w_p + rc.s.ang * qd;
    let f = (w_p.cross(&w_p.cross(&rc.com)) - g_p) * rc.mass;
    let n = w_p.cross(&(rc.inertia_com * w)) + rc.com.cross(&f);
    Force::new(n, f)
}

/// Per body: the constants of a spin-invariant rotor member (see the module doc), `None` for
/// every other body. `frames` are the rotors' constant frames (spin angle zero).
pub(crate) fn constant_congruences(
    model: &Model,
    frames: &[SpatialTransform],
) -> Vec<Option<RotorConstant>> {
    let mut out = vec![None; model.nbodies()];
    for sub in &model.subsystems {
        for (mi, &j) in sub.members.iter().enumerate() {
            let body = &model.bodies[j];
            let JointModel::Coupled {
                mechanism: Mechanism::HarmonicDrive(rotor),
                ..
            } = &body.joint_model
            else {
                continue;
            };
            let leaf = model.bodies.iter().all(|b| b.parent != Some(j));
            if !(leaf && sub.rigid_member[mi] && body.parent == sub.parent && body.v_set.len() == 1)
            {
                continue;
            }
            out[j] = spin_invariant(&body.inertia, &frames[j]).map(|congruence| {
                let s = frames[j].inv_apply_motion(&rotor_column(rotor));
                let ks = congruence.apply(&s);
                let frame = &frames[j];
                RotorConstant {
                    congruence,
                    column: sub.columns[mi][0],
                    ks,
                    sks: s.dot(&ks),
                    s,
                    mass: body.inertia.mass(),
                    com: frame.rot.tr_mul(&body.inertia.com()) + frame.trans,
                    inertia_com: sym_congruence(&body.inertia.inertia_about_com(), &frame.rot),
                    v_index: body.v_set.as_slice()[0],
                }
            });
        }
    }
    out
}

/// The rotor's Jacobian column `[0, 0, N, 0, 0, 0]` (3.1) in its own frame.
pub(crate) fn rotor_column(rotor: &HarmonicDriveRotor) -> Motion {
    Motion::new(
        Vector3::new(0.0, 0.0, rotor.params().ratio),
        Vector3::zeros(),
    )
}

/// `C^T M C` at spin angle zero if `M` is axisymmetric about the body z axis (to rounding).
pub(crate) fn spin_invariant(
    inertia: &RigidInertia,
    frame: &SpatialTransform,
) -> Option<ArticulatedInertia> {
    let (c, i) = (inertia.com(), inertia.inertia_about_com());
    let scale = i.amax();
    let axisymmetric = c.x == 0.0
        && c.y == 0.0
        && i[(0, 1)] == 0.0
        && i[(0, 2)] == 0.0
        && i[(1, 2)] == 0.0
        && (i[(0, 0)] - i[(1, 1)]).abs() <= 1e-14 * scale;
    axisymmetric.then(|| {
        let mut k = ArticulatedInertia::zero();
        add_rigid_congruence(inertia, frame, &mut k);
        k
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spatial::Axis;
    use nalgebra::{Isometry3, Matrix3, Vector3};

    /// The constant congruence equals the spun one at any angle; asymmetric rotors get none.
    #[test]
    fn spin_invariant_matches_spun_congruence() {
        let ic = Matrix3::from_diagonal(&Vector3::new(2e-5, 2e-5, 3e-5));
        let rotor = RigidInertia::new(0.15, Vector3::new(0.0, 0.0, 0.01), ic).expect("valid");
        let pose = Isometry3::new(Vector3::new(0.3, -0.1, 0.7), Vector3::new(0.9, -0.4, 1.2));
        let frame = SpatialTransform::from_pose(&pose);
        let k = spin_invariant(&rotor, &frame).expect("axisymmetric");
        for angle in [0.3, -2.0, 17.0, 1234.5] {
            let (s, c) = f64::sin_cos(angle);
            let x = SpatialTransform::new(Axis::Z.rot_tr_mul(s, c, &frame.rot), frame.trans);
            let dense = x.to_matrix().transpose() * rotor.to_matrix() * x.to_matrix();
            assert!((k.to_matrix() - dense).amax() < 1e-14);
        }
        // The constant B_S / M_S contributions against the dense C^T M J and J^T M J.
        let j = Motion::new(Vector3::new(0.0, 0.0, -80.0), Vector3::zeros());
        let sp = frame.inv_apply_motion(&j);
        let ks = k.apply(&sp).to_vector();
        let (s, c) = f64::sin_cos(2.3);
        let x = SpatialTransform::new(Axis::Z.rot_tr_mul(s, c, &frame.rot), frame.trans);
        let (m, jv) = (rotor.to_matrix(), j.to_vector());
        let dense = x.to_matrix().transpose() * m * jv;
        assert!((ks - dense).amax() < 1e-12 * dense.amax());
        let jmj = (jv.transpose() * m * jv)[0];
        assert!((sp.to_vector().dot(&ks) - jmj).abs() < 1e-12 * jmj);
        let off_axis = RigidInertia::new(0.15, Vector3::new(1e-3, 0.0, 0.0), ic).expect("valid");
        assert!(spin_invariant(&off_axis, &frame).is_none());
        let flat = Matrix3::from_diagonal(&Vector3::new(2e-5, 2.1e-5, 3e-5));
        let flat = RigidInertia::new(0.15, Vector3::zeros(), flat).expect("valid");
        assert!(spin_invariant(&flat, &frame).is_none());
    }
}
