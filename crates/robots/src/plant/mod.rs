//! The plant of the Lola-like biped (Type 2 / Type 3) for the simulator of `biped_sim`.
//!
//! One actuator per actuated joint (25), end stops at the joint ranges of its parameter file
//! ([`biped_sim::passive`]; its drives carry the gear friction, so no joint friction).
//! Harmonic Drive joints get a rigid gear (Type 2) or their elastic motor coordinate (Type 3);
//! the knee gets its screw rotor; the two ankle joints get the two ankle screw rotors (rotor `k`
//! of a multi-input mechanism drives input `k`); the kinematic vergence joint is a direct
//! torque source. Feet and toes: see [`feet`].
//!
//! # Example
//!
//! ```
//! use biped_robots::lola::LolaType;
//! use biped_robots::plant::lola_plant;
//! use biped_sim::plant::PlantConfig;
//!
//! let lp = lola_plant(LolaType::Type2, PlantConfig::default())?;
//! assert_eq!(lp.plant.actuators().len(), lp.lola.limits.len());
//! # Ok::<(), biped_sim::SimError>(())
//! ```

pub mod feet;

use crate::lola::{self, LolaModel, LolaType};
use biped_sim::drive::Transmission;
use biped_sim::passive::JointSpec;
use biped_sim::plant::{actuator, rotor_of, Plant, PlantConfig};
use biped_sim::SimError;

/// A Lola plant together with the robot description it was built from.
#[derive(Debug, Clone)]
pub struct LolaPlant {
    /// The plant.
    pub plant: Plant,
    /// Joint ranges, elastic gears and the model.
    pub lola: LolaModel,
}

/// Builds the plant of the shipped Lola-like model.
pub fn lola_plant(variant: LolaType, config: PlantConfig) -> Result<LolaPlant, SimError> {
    let lola = lola::build(variant).map_err(|e| SimError::InvalidParameter {
        what: "lola model".into(),
        reason: e.to_string(),
    })?;
    let m = &lola.model;
    let mut actuators = Vec::with_capacity(lola.limits.len());
    for l in &lola.limits {
        let body = m.body_id(&l.name).ok_or_else(|| SimError::Unknown {
            kind: "joint body",
            name: l.name.clone(),
        })?;
        let gear = lola.gears.iter().find(|g| g.link_v == l.v_index);
        let transmission = match gear {
            Some(g) => Transmission::Elastic {
                motor_q: g.motor_q,
                motor_v: g.motor_v,
                ratio: g.ratio,
            },
            None => rotor_of(m, body)?,
        };
        actuators.push(actuator(
            m,
            &config,
            l.name.clone(),
            l.q_index,
            l.v_index,
            transmission,
        )?);
    }
    let feet = feet::contact_entries(m, config.toe_contacts)?;
    let stops: Vec<JointSpec> = lola
        .limits
        .iter()
        .map(|l| JointSpec {
            name: l.name.clone(),
            q: l.q_index,
            v: l.v_index,
            range: Some([l.lower, l.upper]),
            damping: 0.0,
            friction: 0.0,
        })
        .collect();
    let plant = Plant::new(m.clone(), actuators, &feet, lola.gears.clone(), config)?;
    let plant = plant.with_passive(&stops)?;
    Ok(LolaPlant { plant, lola })
}
