//! Drive models (the drive dynamics of Table 2.3): DC/brushless motor electrics
//! `L di/dt = u - R i - k_e omega`, torque `k_t i`, gear friction (viscous + smoothed Coulomb)
//! with a load-dependent efficiency loss, and the transmission from motor to joints
//! ([`actuator`]).
//!
//! All drive quantities are on the **motor side** (motor speed `omega_m`, motor torque
//! `tau_m`); the transmission maps them to generalized forces by virtual work,
//! `Q = n(q)^T tau_m` with the motor-rate row `omega_m = n(q) v`. For a Harmonic Drive
//! `n = N` (the ratio), for the knee and ankle roller screws `n(q)` is the screw ratio times
//! the nut-travel Jacobian (3.5), (3.32), read from the rotor part's mechanism.
//!
//! Modes and stability at the control period:
//! - [`DriveMode::Torque`]: ideal joint torque; no electrical states.
//! - [`DriveMode::Current`]: ideal current loop (`i = i_cmd`, clamped to `max_current`); no
//!   electrical states, so RK4 at h = 1 ms is not limited by the electrical time constant.
//! - [`DriveMode::Voltage`]: the currents are states. Their eigenvalue `-R/L` (default
//!   `L/R = 0.4 ms`) needs `h R / L < 2.78` for RK4 and much less for accuracy: use
//!   h <= 0.1 ms or a fast inner current loop ([`crate::controller::Cascade`]).
//!
//! Friction `tau_f = d omega + (tau_c + (1 - eta) |tau_m|) tanh(omega / omega_eps)`: the
//! efficiency `eta` of the gear / roller screw is modelled as a Coulomb loss proportional to
//! the transmitted motor torque. Its slope at rest `tau_c / omega_eps` reflected to the joint
//! (`n^2` times) must stay well inside the step's stability region; the default
//! `omega_eps = 1 rad/s` (motor side) gives `h lambda ~ 0.3` on Lola's hip at h = 1 ms.

pub mod actuator;
pub mod tanh;

pub use actuator::{Actuator, Transmission};

use crate::error::{positive, SimError};
use serde::{Deserialize, Serialize};

/// How the actuators are commanded (and whether the currents are states).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum DriveMode {
    /// Joint torque commands \[N m] (ideal torque-controlled drives).
    Torque,
    /// Motor current commands \[A] with an ideal current loop.
    Current,
    /// Motor voltage commands \[V]; the motor currents are integrated states.
    Voltage,
}

impl std::str::FromStr for DriveMode {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.to_ascii_lowercase().as_str() {
            "torque" => Ok(Self::Torque),
            "current" => Ok(Self::Current),
            "voltage" => Ok(Self::Voltage),
            _ => Err(format!(
                "unknown drive mode `{s}` (torque, current, voltage)"
            )),
        }
    }
}

/// Electrical and electromechanical constants of one motor.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MotorParams {
    /// Winding resistance `R` \[Ohm].
    pub resistance: f64,
    /// Winding inductance `L` \[H].
    pub inductance: f64,
    /// Torque constant `k_t` \[N m / A].
    pub torque_constant: f64,
    /// Back-EMF constant `k_e` \[V s / rad].
    pub back_emf: f64,
    /// Current limit \[A] (commands and states are clamped to it in the torque).
    pub max_current: f64,
    /// Supply voltage limit \[V] (voltage commands are clamped to it).
    pub max_voltage: f64,
}

impl Default for MotorParams {
    /// A plausible 200 W brushless motor: `L/R = 0.4 ms`, `k_t = k_e = 0.05`.
    fn default() -> Self {
        Self {
            resistance: 0.5,
            inductance: 2.0e-4,
            torque_constant: 0.05,
            back_emf: 0.05,
            max_current: 20.0,
            max_voltage: 48.0,
        }
    }
}

impl MotorParams {
    /// Checks that every constant is finite and positive.
    pub fn validate(&self) -> Result<(), SimError> {
        positive("motor.resistance", self.resistance, false)?;
        positive("motor.inductance", self.inductance, false)?;
        positive("motor.torque_constant", self.torque_constant, false)?;
        positive("motor.back_emf", self.back_emf, true)?;
        positive("motor.max_current", self.max_current, false)?;
        positive("motor.max_voltage", self.max_voltage, false)
    }

    /// Current rate `di/dt = (u - R i - k_e omega) / L`.
    #[inline]
    pub fn current_rate(&self, u: f64, i: f64, omega: f64) -> f64 {
        (u - self.resistance * i - self.back_emf * omega) / self.inductance
    }

    /// Motor torque `k_t i` with `i` clamped to the current limit.
    #[inline]
    pub fn torque(&self, i: f64) -> f64 {
        self.torque_constant * i.clamp(-self.max_current, self.max_current)
    }

    /// Stall torque `k_t u / R` at voltage `u` (steady state at `omega = 0`).
    pub fn stall_torque(&self, u: f64) -> f64 {
        self.torque_constant * u / self.resistance
    }

    /// No-load speed `u / k_e` at voltage `u` (steady state at zero torque).
    pub fn no_load_speed(&self, u: f64) -> f64 {
        u / self.back_emf
    }
}

/// Gear friction on the motor side.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FrictionParams {
    /// Viscous coefficient `d` \[N m s / rad].
    pub viscous: f64,
    /// Coulomb torque `tau_c` \[N m].
    pub coulomb: f64,
    /// Smoothing speed `omega_eps` of `tanh(omega / omega_eps)` \[rad/s].
    pub smoothing: f64,
    /// Efficiency `eta` in (0, 1] of the gear or screw (1 = lossless).
    pub efficiency: f64,
}

impl Default for FrictionParams {
    /// Small motor-side friction: 1e-5 N m s/rad, 5 mN m Coulomb, 90 % efficiency.
    fn default() -> Self {
        Self {
            viscous: 1.0e-5,
            coulomb: 5.0e-3,
            smoothing: 1.0,
            efficiency: 0.9,
        }
    }
}

impl FrictionParams {
    /// A lossless drive.
    pub fn none() -> Self {
        Self {
            viscous: 0.0,
            coulomb: 0.0,
            smoothing: 1.0,
            efficiency: 1.0,
        }
    }

    /// Checks ranges (`eta` in (0, 1], the rest finite and `>= 0`, `omega_eps > 0`).
    pub fn validate(&self) -> Result<(), SimError> {
        positive("friction.viscous", self.viscous, true)?;
        positive("friction.coulomb", self.coulomb, true)?;
        positive("friction.smoothing", self.smoothing, false)?;
        if !(self.efficiency > 0.0 && self.efficiency <= 1.0) {
            return Err(SimError::InvalidParameter {
                what: "friction.efficiency".into(),
                reason: format!("must be in (0, 1], got {}", self.efficiency),
            });
        }
        Ok(())
    }

    /// Friction torque opposing the motor speed `omega` while transmitting `tau_m`.
    pub fn torque(&self, omega: f64, tau_m: f64) -> f64 {
        let law = FrictionLaw::from(self);
        law.torque(omega, law.level(tau_m))
    }
}

/// [`FrictionParams`] prepared for repeated evaluation: the loss factor `1 - eta` and the
/// reciprocal smoothing speed `1 / omega_eps` (no division on the right-hand side's dependency
/// chain). Built from the parameters (the plant builds one per actuator with the plant and never
/// changes its actuators afterwards), so it cannot disagree with them.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FrictionLaw {
    /// Viscous coefficient `d`.
    viscous: f64,
    /// Coulomb torque `tau_c`.
    coulomb: f64,
    /// Efficiency loss `1 - eta`.
    loss: f64,
    /// `1 / omega_eps`.
    inv_smoothing: f64,
}

impl From<&FrictionParams> for FrictionLaw {
    fn from(p: &FrictionParams) -> Self {
        Self {
            viscous: p.viscous,
            coulomb: p.coulomb,
            loss: 1.0 - p.efficiency,
            inv_smoothing: 1.0 / p.smoothing,
        }
    }
}

impl FrictionLaw {
    /// Coulomb level `tau_c + (1 - eta) |tau_m|` while transmitting the motor torque `tau_m`.
    #[inline]
    pub fn level(&self, tau_m: f64) -> f64 {
        self.coulomb + self.loss * tau_m.abs()
    }

    /// Friction torque `d omega + level tanh(omega / omega_eps)` opposing the motor speed
    /// `omega` at the Coulomb level `level` ([`Self::level`]).
    #[inline]
    pub fn torque(&self, omega: f64, level: f64) -> f64 {
        self.viscous * omega + level * tanh::tanh(omega * self.inv_smoothing)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The prepared law equals the friction formula of the module docs (with the division
        /// by `omega_eps`) up to rounding, over valid parameters, speeds and torques.
        #[test]
        fn prepared_law_matches_the_formula(
            viscous in 0.0f64..1.0,
            coulomb in 0.0f64..1.0,
            smoothing in 1e-3f64..10.0,
            efficiency in 1e-3f64..=1.0,
            omega in -100.0f64..100.0,
            tau_m in -50.0f64..50.0,
        ) {
            let p = FrictionParams { viscous, coulomb, smoothing, efficiency };
            prop_assert!(p.validate().is_ok());
            let formula = viscous * omega
                + (coulomb + (1.0 - efficiency) * tau_m.abs()) * (omega / smoothing).tanh();
            let law = FrictionLaw::from(&p);
            let scale = viscous * omega.abs() + coulomb + tau_m.abs();
            for got in [p.torque(omega, tau_m), law.torque(omega, law.level(tau_m))] {
                prop_assert!((got - formula).abs() <= 1e-14 * scale, "{got} vs {formula}");
            }
        }
    }
}
