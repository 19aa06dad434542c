//! Lola-like biped model (thesis Fig. 1.1, Table 2.3): a floating base and 25 actuated joints
//! with their drives, after the parameter file `data/lola.toml` (plausible approximations, not
//! Lola's real data).
//!
//! - [`LolaType::Type2`]: rigid drives. Harmonic Drive rotors (3.1)-(3.2), the knee roller
//!   screw (3.3)-(3.21) and the ankle slider-cranks (3.22)-(3.37) are coupled parts, so their
//!   loops become sub-systems (2.9). 6 + 25 = 31 DoF (the thesis's 30 has no vergence DoF).
//! - [`LolaType::Type3`]: as Type 2, but the 16 Harmonic Drive joints of legs, pelvis and arms
//!   have elastic gears: the motor rotor is a body on its own revolute joint in the parent
//!   (the gear spring-damper is a force the simulation applies). 31 + 16 = 47 DoF (thesis 46).

mod assemble;
pub mod collision;
pub mod params;
mod sparsity;

pub use collision::{lola_collision_model, LolaCollision, LolaCollisionError};
pub use params::{LolaError, LolaParams};
pub use sparsity::{mass_matrix_nonzeros, sparsity, Sparsity};

use biped_dynamics::Model;
use nalgebra::{DVector, UnitQuaternion, Vector3};
use std::path::Path;

/// The parameter file shipped with the crate.
pub const LOLA_TOML: &str = include_str!("../../data/lola.toml");

/// Name of the shipped parameter file in messages.
pub const LOLA_TOML_NAME: &str = "crates/robots/data/lola.toml";

/// Model depth after Table 2.3.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LolaType {
    /// Rigid multibody model with rigidly coupled drives (30 mechanical DoF in the thesis).
    Type2,
    /// Type 2 plus elastic Harmonic Drive gears: 16 motor DoF (46 in the thesis).
    Type3,
}

impl std::str::FromStr for LolaType {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.to_ascii_lowercase().as_str() {
            "type2" | "2" => Ok(LolaType::Type2),
            "type3" | "3" => Ok(LolaType::Type3),
            _ => Err(format!("unknown Lola model type `{s}` (type2 or type3)")),
        }
    }
}

/// Range of one actuated link joint.
#[derive(Debug, Clone, PartialEq)]
pub struct JointLimit {
    /// Joint name.
    pub name: String,
    /// Index into `q`.
    pub q_index: usize,
    /// Index into `v`.
    pub v_index: usize,
    /// Lower bound \[rad].
    pub lower: f64,
    /// Upper bound \[rad].
    pub upper: f64,
}

/// An elastic Harmonic Drive gear of Type 3 (link joint and motor coordinates).
pub use biped_dynamics::ElasticGear;

/// A built Lola-like model with its joint ranges and elastic gears.
#[derive(Debug, Clone)]
pub struct LolaModel {
    /// The multibody model (root joint "root").
    pub model: Model,
    /// Model type.
    pub variant: LolaType,
    /// The 25 actuated link joints with their ranges.
    pub limits: Vec<JointLimit>,
    /// Type 3's elastic gears (empty for Type 2).
    pub gears: Vec<ElasticGear>,
}

/// Builds the Lola-like model of the shipped parameter file.
///
/// # Example
///
/// The neutral pose stands upright with the base frame at the origin; the soles lie below
/// it, left and right of the sagittal plane, mirror images of each other.
///
/// ```
/// use biped_dynamics::{update_placements, Data};
/// use biped_robots::lola::{build, LolaType};
///
/// let lola = build(LolaType::Type2)?;
/// let model = &lola.model;
/// let mut data = Data::new(model);
/// update_placements(model, &mut data, &model.neutral())?;
/// let left = data.world_pos[model.body_id("l_sole").unwrap()];
/// let right = data.world_pos[model.body_id("r_sole").unwrap()];
/// assert!(left.z < -0.5 && (left.z - right.z).abs() < 1e-12);
/// assert!(left.y > 0.0 && (left.y + right.y).abs() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn build(variant: LolaType) -> Result<LolaModel, LolaError> {
    build_from_str(LOLA_TOML, LOLA_TOML_NAME, variant)
}

/// Builds the model from a parameter file on disk.
pub fn load_file(path: &Path, variant: LolaType) -> Result<LolaModel, LolaError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|source| LolaError::Io {
        file: file.clone(),
        source,
    })?;
    build_from_str(&text, &file, variant)
}

/// Builds the model from parameter-file text; `file` names it in errors.
pub fn build_from_str(text: &str, file: &str, variant: LolaType) -> Result<LolaModel, LolaError> {
    let loc = params::Locator { file, text };
    let params = loc.parse()?;
    assemble::assemble(&params, &loc, variant)
}

impl LolaModel {
    /// A random state: base near the origin with a random orientation, link joints uniform in
    /// their ranges, motors at `N q_link` plus a small gear deflection; velocities in [-1, 1].
    /// `uniform(a, b)` draws from `[a, b)` (the caller's generator; no RNG dependency here).
    pub fn random_state(
        &self,
        uniform: &mut impl FnMut(f64, f64) -> f64,
    ) -> (DVector<f64>, DVector<f64>) {
        let m = &self.model;
        let mut q = m.neutral();
        let mut v = DVector::from_fn(m.nv(), |_, _| uniform(-1.0, 1.0));
        let axis = Vector3::new(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0));
        let rot = UnitQuaternion::from_scaled_axis(axis);
        for k in 0..3 {
            q[k] = uniform(-0.5, 0.5);
        }
        q.fixed_rows_mut::<4>(3).copy_from(&rot.coords);
        for l in &self.limits {
            q[l.q_index] = uniform(l.lower, l.upper);
        }
        for g in &self.gears {
            q[g.motor_q] = g.ratio * q[g.link_q] + uniform(-0.05, 0.05);
            v[g.motor_v] = g.ratio * v[g.link_v] + uniform(-1.0, 1.0);
        }
        (q, v)
    }

    /// Adds the elastic-gear forces of Type 3 to `tau`: with the deflection
    /// `theta = q_motor / N - q_link`, the gear torque `k theta + d theta_dot` drives the link
    /// and reacts on the motor divided by `N` (generalized forces of the potential
    /// `k theta^2 / 2` and of the damper). No-op for Type 2.
    pub fn add_gear_forces(
        &self,
        q: &DVector<f64>,
        v: &DVector<f64>,
        stiffness: f64,
        damping: f64,
        tau: &mut DVector<f64>,
    ) {
        for g in &self.gears {
            let theta = q[g.motor_q] / g.ratio - q[g.link_q];
            let rate = v[g.motor_v] / g.ratio - v[g.link_v];
            let torque = stiffness * theta + damping * rate;
            tau[g.link_v] += torque;
            tau[g.motor_v] -= torque / g.ratio;
        }
    }

    /// Potential energy `sum k theta^2 / 2` of the elastic gears at `q` (Type 3).
    pub fn gear_energy(&self, q: &DVector<f64>, stiffness: f64) -> f64 {
        self.gears
            .iter()
            .map(|g| {
                let theta = q[g.motor_q] / g.ratio - q[g.link_q];
                0.5 * stiffness * theta * theta
            })
            .sum()
    }
}
