//! Plants of URDF models with a floating base, and the parts other robots' plants are built
//! from ([`actuator`], [`rotor_of`]; the Lola-like biped's is `biped_robots::plant`).

use super::armature::{with_rotors, Armature};
use super::{Plant, PlantConfig};
use crate::contact::{sole_rectangle, FootSpec};
use crate::drive::{Actuator, Transmission};
use crate::error::SimError;
use crate::passive::JointSpec;
use biped_dynamics::model::Mechanism;
use biped_dynamics::urdf::{self, UrdfOptions};
use biped_dynamics::{BodyId, JointModel, Model};
use nalgebra::{Point3, Vector3};
use std::path::Path;

pub(crate) fn unknown(kind: &'static str, name: &str) -> SimError {
    SimError::Unknown {
        kind,
        name: name.to_string(),
    }
}

/// An actuator of joint `name` (coordinates `q`, `v`) through `t` with the motor and friction
/// of `c`; its nominal ratio from the motor row at neutral.
pub fn actuator(
    m: &Model,
    c: &PlantConfig,
    name: String,
    q: usize,
    v: usize,
    t: Transmission,
) -> Result<Actuator, SimError> {
    let mut a = Actuator {
        name,
        joint_q: q,
        joint_v: v,
        transmission: t,
        motor: c.motor,
        friction: c.friction,
        nominal_ratio: 1.0,
        effort: f64::INFINITY,
        velocity: f64::INFINITY,
    };
    let q0 = m.neutral();
    a.nominal_ratio = match (t, a.motor_row(m, q0.as_slice())?) {
        (Transmission::Elastic { ratio, .. }, _) => ratio.abs(),
        (_, Some(row)) => row
            .entries()
            .find(|(i, _)| *i == v)
            .map_or(1.0, |(_, c)| c.abs()),
        (_, None) => 1.0,
    };
    if a.nominal_ratio.is_nan() || a.nominal_ratio <= 0.0 {
        a.nominal_ratio = 1.0;
    }
    Ok(a)
}

/// The transmission from the motor rotor driving joint body `joint`: a coupled part whose name
/// contains "rotor" and whose inputs contain `joint` (a Harmonic Drive: its gear; of a
/// multi-input group, the `k`-th rotor drives input `k`); direct without one.
pub fn rotor_of(m: &Model, joint: BodyId) -> Result<Transmission, SimError> {
    let mut group = Vec::new();
    let mut slot = None;
    for (id, b) in m.bodies().iter().enumerate() {
        let JointModel::Coupled { mechanism, inputs } = b.joint() else {
            continue;
        };
        if !b.name().contains("rotor") || !inputs.contains(&joint) {
            continue;
        }
        if let Mechanism::HarmonicDrive(r) = mechanism {
            return Ok(Transmission::Gear {
                ratio: r.params().ratio,
            });
        }
        slot = inputs.iter().position(|&i| i == joint);
        group.push(id);
    }
    match slot.and_then(|k| group.get(k)) {
        Some(&rotor) => Actuator::rotor_transmission(m, rotor),
        None => Ok(Transmission::Direct),
    }
}

/// Feet of a URDF model: link names and the sole rectangle in each link's frame.
#[derive(Debug, Clone, PartialEq)]
pub struct UrdfFeet {
    /// `(signal name, URDF link)` of each foot.
    pub links: Vec<(String, String)>,
    /// Sole rectangle centre in the link frame \[m] (default `(0, 0, -0.05)`).
    pub center: Vector3<f64>,
    /// Sole length along the link's x \[m] (default 0.20).
    pub length: f64,
    /// Sole width along the link's y \[m] (default 0.10).
    pub width: f64,
}

impl UrdfFeet {
    /// Two feet with the default sole rectangle (0.20 m x 0.10 m, 5 cm below the link frame).
    pub fn new(left: &str, right: &str) -> Self {
        Self {
            links: vec![("left".into(), left.into()), ("right".into(), right.into())],
            center: Vector3::new(0.0, 0.0, -0.05),
            length: 0.20,
            width: 0.10,
        }
    }
}

/// Gear ratio given to every URDF joint's motor and rotor (URDF has no drive data).
pub const URDF_GEAR_RATIO: f64 = 100.0;

/// Plant of a URDF model with a floating base: every revolute/prismatic joint is actuated
/// through a rigid gear of [`URDF_GEAR_RATIO`]; `feet` name the sole links; `armature` gives
/// the reflected rotor inertia `N^2 J` of the joints it names, added as geared rotor bodies
/// (thesis 3.1, see [`Armature`]; URDF has no rotor data, so without it the drives carry none).
/// The URDF's joint ranges, `<dynamics>` damping and friction become the plant's passive layer
/// ([`Plant::with_passive`], switched by `config.passive`) and each `effort` the actuator's
/// torque limit (and its motor's current limit `effort / (N k_t)`).
///
/// The motor-side friction reflected through the gear (`N^2 tau_c / omega_eps` at rest:
/// 50 N m s/rad with the defaults) would act on light links (a G1 ankle-roll subtree has
/// ~4e-4 kg m^2 without rotors) with rates far beyond any explicit step: the drives of URDF
/// plants are lossless ([`crate::drive::FrictionParams::none`]), whatever `config.friction` says.
pub fn urdf_plant(
    path: &Path,
    feet: &UrdfFeet,
    armature: &[Armature],
    config: PlantConfig,
) -> Result<Plant, SimError> {
    let opts = UrdfOptions {
        floating: true,
        reject_mimic: false,
    };
    let u = urdf::load_file(path, &opts).map_err(|e| SimError::InvalidParameter {
        what: "urdf".into(),
        reason: e.to_string(),
    })?;
    let model = with_rotors(&u.model, armature, URDF_GEAR_RATIO)?;
    let m = &model;
    let config = PlantConfig {
        friction: crate::drive::FrictionParams::none(),
        ..config
    };
    let mut actuators = Vec::new();
    for b in m.bodies() {
        if matches!(
            b.joint(),
            JointModel::Revolute { .. } | JointModel::Prismatic { .. }
        ) {
            let t = Transmission::Gear {
                ratio: URDF_GEAR_RATIO,
            };
            let mut a = actuator(
                m,
                &config,
                b.joint_name().to_string(),
                b.q_index(),
                b.v_index(),
                t,
            )?;
            let props = u.joints.iter().find(|j| j.name == a.name);
            if let Some(effort) = props.and_then(|j| j.effort) {
                limit_effort(&mut a, effort);
            }
            if let Some(velocity) = props.and_then(|j| j.velocity) {
                a.velocity = velocity;
            }
            actuators.push(a);
        }
    }
    let passive = urdf_joint_specs(m, &u.joints);
    let mut specs = Vec::new();
    for (name, link) in &feet.links {
        let lf = u
            .links
            .iter()
            .find(|l| &l.link == link)
            .ok_or_else(|| unknown("foot link", link))?;
        let body = lf
            .body
            .and_then(|b| m.body(b))
            .ok_or_else(|| unknown("foot body of link", link))?;
        let to_body = |p: Vector3<f64>| (lf.pose * Point3::from(p)).coords;
        let local = sole_rectangle(feet.center, feet.length, feet.width);
        specs.push(FootSpec {
            name: name.clone(),
            body: body.name().to_string(),
            points: local.into_iter().map(to_body).collect(),
            reference: to_body(feet.center),
            part_of: None,
        });
    }
    Plant::new(m.clone(), actuators, &specs, Vec::new(), config)?.with_passive(&passive)
}

/// Caps actuator `a` at the joint torque `effort`: torque commands directly, current commands
/// through the motor's current limit `effort / (N k_t)`.
fn limit_effort(a: &mut Actuator, effort: f64) {
    a.effort = effort;
    a.motor.max_current = effort / (a.nominal_ratio * a.motor.torque_constant);
}

/// The passive joint specs (range, damping, friction) of the URDF's movable joints.
fn urdf_joint_specs(m: &Model, joints: &[urdf::JointProps]) -> Vec<JointSpec> {
    joints
        .iter()
        .filter_map(|j| {
            let b = m.body(j.body)?;
            Some(JointSpec {
                name: j.name.clone(),
                q: b.q_index(),
                v: b.v_index(),
                range: j.range,
                damping: j.damping,
                friction: j.friction,
            })
        })
        .collect()
}
