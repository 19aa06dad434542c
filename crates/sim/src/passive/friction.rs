//! Joint-side friction of a robot description: viscous damping plus smoothed Coulomb friction.

use crate::drive::tanh::tanh;

/// Friction of one joint: `tau = -(d qdot + f tanh(qdot / eps))`.
#[derive(Debug, Clone, PartialEq)]
pub struct JointFriction {
    /// Joint name.
    pub name: String,
    /// Joint coordinate in `v`.
    pub v: usize,
    /// Viscous coefficient `d` \[N m s/rad or N s/m].
    pub viscous: f64,
    /// Coulomb torque or force `f` \[N m or N].
    pub coulomb: f64,
    /// Smoothing speed `eps` of the Coulomb term \[rad/s or m/s].
    pub smoothing: f64,
}

impl JointFriction {
    /// Friction torque at joint rate `qdot` (opposes the motion).
    #[inline]
    pub fn torque(&self, qdot: f64) -> f64 {
        -(self.viscous * qdot + self.coulomb * tanh(qdot / self.smoothing))
    }

    /// Slope `d + f / eps` of the friction law at rest (its steepest point).
    pub fn slope(&self) -> f64 {
        self.viscous + self.coulomb / self.smoothing
    }
}
