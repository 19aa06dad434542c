//! Lola-like test models (needs `mod loop_support;` beside it): branched revolute chains on a floating base whose links carry
//! Harmonic Drive rotors (3.1)-(3.2) mounted on the link's carrier (the parent), as in the
//! Lola drive trains; most rotors axisymmetric (the spin-invariant fast path), some not; some
//! links carry massless fixed frames (sole-like leaves).
#![allow(dead_code)]

use crate::loop_support::{random_axis, random_inertia, random_pose, rng};
use biped_dynamics::mechanism::harmonic_drive::{HarmonicDriveParams, HarmonicDriveRotor};
use biped_dynamics::model::Mechanism;
use biped_dynamics::{BodySpec, JointModel, Model, ModelBuilder, RigidInertia};
use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use rand::rngs::StdRng;
use rand::Rng;

/// Rotor inertia: axisymmetric about its z axis with the CoM on it, or (one in four) generic.
fn rotor_inertia(rng: &mut StdRng) -> RigidInertia {
    let (a, b): (f64, f64) = (rng.random_range(1e-5..5e-5), rng.random_range(1e-5..5e-5));
    let com = Vector3::new(0.0, 0.0, rng.random_range(-0.02..0.02));
    if rng.random_range(0..4) == 0 {
        let ic = Matrix3::from_diagonal(&Vector3::new(a, 1.3 * a, b.clamp(0.5 * a, 2.0 * a)));
        let com = com + Vector3::new(3e-3, -2e-3, 0.0);
        return RigidInertia::new(0.2, com, ic).unwrap();
    }
    let ic = Matrix3::from_diagonal(&Vector3::new(a, a, b.min(2.0 * a)));
    RigidInertia::new(rng.random_range(0.05..0.4), com, ic).unwrap()
}

/// Harmonic Drive rotor with random ratio, mounting pose and offset.
fn random_rotor(rng: &mut StdRng) -> HarmonicDriveRotor {
    let sign = if rng.random_bool(0.5) { 1.0 } else { -1.0 };
    HarmonicDriveRotor::new(HarmonicDriveParams {
        ratio: sign * rng.random_range(30.0..160.0),
        orientation: UnitQuaternion::from_euler_angles(
            rng.random_range(-3.0..3.0),
            rng.random_range(-1.5..1.5),
            rng.random_range(-3.0..3.0),
        ),
        position: Vector3::new(rng.random(), rng.random(), rng.random()) * 0.2,
        offset: rng.random_range(-3.0..3.0),
    })
    .unwrap()
}

/// Floating base with `n` revolute links in a random tree, each with a Harmonic Drive rotor
/// on the link's parent driven by the link's coordinate (a 1-DoF sub-system per link).
pub fn harmonic_drive_chain(seed: u64, n: usize) -> Model {
    let mut rng = rng(seed);
    let mut b = ModelBuilder::new();
    let spec = |name: String, parent, joint, placement, inertia| BodySpec {
        joint_name: format!("{name}_joint"),
        name,
        parent,
        joint,
        placement,
        inertia,
    };
    let base = b
        .add_body(spec(
            "base".into(),
            None,
            JointModel::FreeQuaternion,
            random_pose(&mut rng),
            random_inertia(&mut rng),
        ))
        .unwrap();
    let mut links = vec![base];
    for k in 0..n {
        let parent = links[rng.random_range(0..links.len())];
        let joint = JointModel::Revolute {
            axis: random_axis(&mut rng),
        };
        let (pose, inertia) = (random_pose(&mut rng), random_inertia(&mut rng));
        let link = b
            .add_body(spec(format!("link{k}"), Some(parent), joint, pose, inertia))
            .unwrap();
        let joint = JointModel::Coupled {
            mechanism: Mechanism::HarmonicDrive(random_rotor(&mut rng)),
            inputs: vec![link],
        };
        let (pose, inertia) = (random_pose(&mut rng), rotor_inertia(&mut rng));
        b.add_body(spec(
            format!("rotor{k}"),
            Some(parent),
            joint,
            pose,
            inertia,
        ))
        .unwrap();
        if rng.random_range(0..3) == 0 {
            // A massless tool/sole frame on the link (a leaf; wrenches may act on it).
            let (pose, zero) = (random_pose(&mut rng), RigidInertia::zero());
            let joint = JointModel::Fixed;
            b.add_body(spec(format!("frame{k}"), Some(link), joint, pose, zero))
                .unwrap();
        }
        links.push(link);
    }
    b.build().unwrap()
}

/// Bodies that are not Harmonic Drive rotors.
pub fn link_bodies(model: &Model) -> Vec<usize> {
    let is_rotor = |j: &JointModel| {
        matches!(
            j,
            JointModel::Coupled {
                mechanism: Mechanism::HarmonicDrive(_),
                ..
            }
        )
    };
    (0..model.nbodies())
        .filter(|&i| !is_rotor(model.bodies()[i].joint()))
        .collect()
}
