//! The controller in the loop (Fig. 2.1, issue item 3): a [`Controller`] samples the
//! [`Sensors`] every control period and writes actuator [`Commands`]; the plant holds them
//! (zero-order hold) while the integrator advances to the next sample. Cascaded loops run an
//! inner controller at an integer multiple of the outer rate ([`Cascade`]).

mod cascade;
mod pd;
mod stance;

pub use cascade::{Cascade, CurrentPi, InnerController};
pub use pd::{JointPd, Trajectory};
pub use stance::{StanceAnkle, StanceDamping};

use crate::drive::DriveMode;
use crate::error::SimError;
use crate::sensors::Sensors;

/// Actuator commands, one value per actuator, of the kind given by `mode`.
#[derive(Debug, Clone, PartialEq)]
pub struct Commands {
    /// Kind of every value (torque \[N m], current \[A] or voltage \[V]).
    pub mode: DriveMode,
    /// One value per actuator, in the plant's actuator order.
    pub values: Vec<f64>,
}

impl Commands {
    /// `n` zero commands of kind `mode`.
    pub fn new(mode: DriveMode, n: usize) -> Self {
        Self {
            mode,
            values: vec![0.0; n],
        }
    }
}

/// A discrete-time controller in the loop.
pub trait Controller {
    /// Control period \[s] (the simulation integrates the plant over one period per cycle).
    fn period(&self) -> f64;

    /// Kind of command this controller writes.
    fn mode(&self) -> DriveMode;

    /// One control cycle at time `t`: reads `sensors`, writes `commands`.
    fn update(
        &mut self,
        t: f64,
        sensors: &Sensors,
        commands: &mut Commands,
    ) -> Result<(), SimError>;
}
