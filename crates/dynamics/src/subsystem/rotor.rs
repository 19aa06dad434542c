//! Spin-invariant congruence of Harmonic Drive rotors for the O(n) backward pass (2.76).
//!
//! A rotor (3.1)-(3.2) attached directly to its sub-system's parent has `C-hat = C`, a rotation
//! by the spin angle about the z axis of a constant frame. When the rotor's inertia is
//! axisymmetric about that axis (CoM on the axis, `I_xx = I_yy`, no products of inertia), its
//! term `C^T M C` of (2.76) does not depend on the spin angle and is computed once per model.

use super::on::add_rigid_congruence;
use crate::mechanism::harmonic_drive::HarmonicDriveRotor;
use crate::model::coupling::Mechanism;
use crate::model::JointModel;
use crate::spatial::{ArticulatedInertia, RigidInertia, SpatialTransform};
use crate::Model;

/// Per body: the constant `C^T M C` of a spin-invariant rotor member (see the module doc),
/// `None` for every other body. `frames` are the rotors' constant frames (spin angle zero).
pub(crate) fn constant_congruences(
    model: &Model,
    frames: &[SpatialTransform],
) -> Vec<Option<ArticulatedInertia>> {
    let mut out = vec![None; model.nbodies()];
    for sub in &model.subsystems {
        for (mi, &j) in sub.members.iter().enumerate() {
            let body = &model.bodies[j];
            let is_rotor = matches!(
                &body.joint_model,
                JointModel::Coupled {
                    mechanism: Mechanism::HarmonicDrive(HarmonicDriveRotor { .. }),
                    ..
                }
            );
            if is_rotor && sub.rigid_member[mi] && body.parent == sub.parent {
                out[j] = spin_invariant(&body.inertia, &frames[j]);
            }
        }
    }
    out
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
        let off_axis = RigidInertia::new(0.15, Vector3::new(1e-3, 0.0, 0.0), ic).expect("valid");
        assert!(spin_invariant(&off_axis, &frame).is_none());
        let flat = Matrix3::from_diagonal(&Vector3::new(2e-5, 2.1e-5, 3e-5));
        let flat = RigidInertia::new(0.15, Vector3::zeros(), flat).expect("valid");
        assert!(spin_invariant(&flat, &frame).is_none());
    }
}
