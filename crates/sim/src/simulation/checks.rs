//! Checks and counts of the simulation loop: the drive-limit cut counter, integrator errors
//! mapped to simulation errors, and the step-size check against the passive joints' rates.

use crate::error::SimError;
use crate::ode::{IntegrateError, Method, Settings};
use crate::plant::Plant;

/// Counts of commands cut by the drive limits ([`Plant::hold_commands`]) over a run.
#[derive(Debug, Clone, Default)]
pub(super) struct LimitedCommands {
    /// Per actuator: cycles in which its command was cut.
    pub(super) per_actuator: Vec<u64>,
    /// Cycles in which at least one command was cut.
    pub(super) cycles: u64,
}

impl LimitedCommands {
    /// Zero counts (start of a run).
    pub(super) fn reset(&mut self) {
        self.per_actuator.fill(0);
        self.cycles = 0;
    }

    /// Counts the commands `held` that differ from the controller's `wanted`.
    pub(super) fn count(&mut self, wanted: &[f64], held: &[f64]) {
        let mut any = false;
        for ((n, w), h) in self.per_actuator.iter_mut().zip(wanted).zip(held) {
            if w != h {
                *n += 1;
                any = true;
            }
        }
        self.cycles += u64::from(any);
    }
}

/// Maps an integrator error, keeping the plant's own error; a non-finite state or step-size
/// underflow is a [`SimError::Divergence`].
pub(super) fn integ(e: IntegrateError<SimError>) -> SimError {
    match e {
        IntegrateError::System(e) => e,
        e @ (IntegrateError::NonFinite { .. } | IntegrateError::StepSizeUnderflow { .. }) => {
            SimError::Divergence(e.to_string())
        }
        other => SimError::Integrator(other.to_string()),
    }
}

/// Rejects a fixed step too long for the fastest law of the plant's passive joint layer
/// ([`crate::passive::PassiveJoints::fastest`]): `h rate` beyond the method's
/// [`Method::decay_stability_bound`] would blow up instead of damping.
pub(super) fn check_passive_rate(
    plant: &Plant,
    method: Method,
    settings: &Settings,
    period: f64,
) -> Result<(), SimError> {
    let (Some(fast), Some(bound)) = (plant.passive().fastest(), method.decay_stability_bound())
    else {
        return Ok(());
    };
    let h = period / (period / settings.h).ceil();
    if h * fast.rate <= bound {
        return Ok(());
    }
    Err(SimError::InvalidParameter {
        what: format!("joint `{}` {}", fast.joint, fast.law),
        reason: format!(
            "its rate {:.3e} 1/s on the joint's free inertia needs a {method} step below {:.3e} s \
             (step {h:.3e} s): add rotor inertia (armature), shorten the step or drop the law",
            fast.rate,
            bound / fast.rate
        ),
    })
}
