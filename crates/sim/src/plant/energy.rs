//! Energy bookkeeping of the plant (for conservation tests and monitoring).

use super::Plant;
use crate::error::SimError;
use biped_dynamics::{center_of_mass, mass_matrix};
use serde::Serialize;

/// Energy of a plant state \[J].
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Energy {
    /// Kinetic energy `v^T M(q) v / 2`.
    pub kinetic: f64,
    /// Gravitational potential `-m g . r_C`.
    pub gravity: f64,
    /// Elastic-gear potential `sum k theta^2 / 2` (Type 3).
    pub gears: f64,
    /// Contact springs: normal `k delta^(e+1) / (e+1)` and bristles `k_t |s|^2 / 2`.
    pub contact: f64,
}

impl Energy {
    /// Sum of all parts.
    pub fn total(&self) -> f64 {
        self.kinetic + self.gravity + self.gears + self.contact
    }
}

impl Plant {
    /// Energy at `z` (allocates nothing; runs kinematics into the workspace).
    pub fn energy(&mut self, z: &[f64]) -> Result<Energy, SimError> {
        self.load_state(z)?;
        let m = mass_matrix(&self.model, &mut self.data, &self.q)?;
        let kinetic = 0.5 * (m * &self.v).dot(&self.v);
        let com = center_of_mass(&self.model, &mut self.data, &self.q, None)?;
        let gravity = -com.mass * self.model.gravity().dot(&com.position);
        let k = self.config.gear_stiffness;
        let gears = self
            .gears
            .iter()
            .map(|g| {
                let theta = self.q[g.motor_q] / g.ratio - self.q[g.link_q];
                0.5 * k * theta * theta
            })
            .sum();
        let contact = self.contact.potential(
            self.q.as_slice(),
            self.v.as_slice(),
            &z[self.layout.contact()],
        );
        Ok(Energy {
            kinetic,
            gravity,
            gears,
            contact,
        })
    }
}
