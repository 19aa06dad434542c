//! Motor rotors added to an existing model as Harmonic Drive rotor bodies (thesis 3.1-3.2):
//! the drive inertia a URDF does not describe (the "armature" `N^2 J` of other simulators)
//! enters the multibody model as a body of its own, so its gyroscopic coupling with the parent
//! is kept, and the O(n) solve takes it as a spin-invariant axial member (`subsystem::axial`).

use super::{BodyId, BodySpec, JointModel, Mechanism, Model, ModelBuilder};
use crate::mechanism::harmonic_drive::{HarmonicDriveParams, HarmonicDriveRotor};
use crate::spatial::RigidInertia;
use crate::ModelError;
use nalgebra::{Isometry3, Matrix3, UnitQuaternion, Vector3};

/// One motor rotor, mounted on the parent of joint body `joint` coaxially with its joint axis
/// at the joint origin, turning `ratio` times the joint angle.
#[derive(Clone, Debug, PartialEq)]
pub struct RotorSpec {
    /// Body whose revolute joint drives the rotor.
    pub joint: BodyId,
    /// Gear ratio `N` (rotor turns per joint turn).
    pub ratio: f64,
    /// Rotor inertia in the rotor frame, whose z axis is the joint axis (the spin axis).
    pub inertia: RigidInertia,
}

impl RotorSpec {
    /// A massless rotor of polar moment `armature / ratio^2` about its z (the joint axis;
    /// transverse moments half of it, a thin disc), so that it adds `armature` (kg m^2) to the joint's
    /// diagonal of the mass matrix; errors for a joint that is not revolute, a zero or
    /// non-finite ratio and a negative or non-finite armature.
    pub fn from_armature(
        model: &Model,
        joint: BodyId,
        ratio: f64,
        armature: f64,
    ) -> Result<Self, ModelError> {
        revolute_axis(model, joint)?;
        if !ratio.is_finite() || ratio == 0.0 {
            return Err(ModelError::InvalidGearRatio {
                body: format!("{}_rotor", model.bodies[joint].name),
                ratio,
            });
        }
        // A negative or non-finite armature is rejected by `RigidInertia::new`.
        let polar = armature / (ratio * ratio);
        let rot = Matrix3::from_diagonal(&Vector3::new(0.5, 0.5, 1.0)) * polar;
        let inertia = RigidInertia::new(0.0, Vector3::zeros(), rot)?;
        Ok(Self {
            joint,
            ratio,
            inertia,
        })
    }
}

/// The joint axis of revolute body `joint`, or why it cannot carry a rotor.
fn revolute_axis(
    model: &Model,
    joint: BodyId,
) -> Result<nalgebra::Unit<nalgebra::Vector3<f64>>, ModelError> {
    let body = model.bodies.get(joint).ok_or(ModelError::BadDriver {
        body: format!("rotor of body {joint}"),
        driver: joint,
        reason: "no such body",
    })?;
    match body.joint_model {
        JointModel::Revolute { axis } => Ok(axis),
        _ => Err(ModelError::BadDriver {
            body: format!("{}_rotor", body.name),
            driver: joint,
            reason: "a rotor needs a revolute joint",
        }),
    }
}

impl Model {
    /// This model with one Harmonic Drive rotor body per spec (thesis 3.1-3.2), named
    /// `<joint body>_rotor` and appended after the existing bodies, so that body ids and the
    /// coordinates `q`, `v` are unchanged; the rotors form sub-systems with their joints (2.9).
    pub fn with_geared_rotors(&self, rotors: &[RotorSpec]) -> Result<Model, ModelError> {
        let mut b = ModelBuilder::new();
        b.set_gravity(self.gravity);
        for body in &self.bodies {
            b.add_body(BodySpec {
                name: body.name.clone(),
                joint_name: body.joint_name.clone(),
                parent: body.parent,
                joint: body.joint_model.clone(),
                placement: body.placement,
                inertia: body.inertia,
            })?;
        }
        for r in rotors {
            let axis = revolute_axis(self, r.joint)?;
            let body = &self.bodies[r.joint];
            let name = format!("{}_rotor", body.name);
            // Rotor z along the joint axis, at the joint origin, in the parent frame (3.2).
            let to_axis =
                UnitQuaternion::rotation_between(&Vector3::z(), &axis).unwrap_or_else(|| {
                    UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
                });
            let rotor = HarmonicDriveRotor::new(HarmonicDriveParams {
                ratio: r.ratio,
                orientation: body.placement.rotation * to_axis,
                position: body.placement.translation.vector,
                offset: 0.0,
            })
            .map_err(|_| ModelError::InvalidGearRatio {
                body: name.clone(),
                ratio: r.ratio,
            })?;
            b.add_body(BodySpec {
                joint_name: format!("{}_rotor", body.joint_name),
                name,
                parent: body.parent,
                joint: JointModel::Coupled {
                    mechanism: Mechanism::HarmonicDrive(rotor),
                    inputs: vec![r.joint],
                },
                placement: Isometry3::identity(),
                inertia: r.inertia,
            })?;
        }
        b.build()
    }
}
