//! The controller in the loop (Fig. 2.1): a [`Controller`] samples the
//! [`Sensors`] every control period and writes actuator [`Commands`]; the plant holds them
//! (zero-order hold) while the integrator advances to the next sample. Cascaded loops run an
//! inner controller at an integer multiple of the outer rate ([`Cascade`]).

mod cascade;
mod hooked;
mod pd;
mod stance;

pub use cascade::{Cascade, CurrentPi, InnerController};
pub use hooked::{Hook, Hooked};
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
///
/// Implement it for a controller of your own; [`crate::simulation::Simulation`] calls
/// [`Controller::update`] once per [`Controller::period`] with the latest sensor sample and
/// holds the commands it writes until the next call.
///
/// # Example
///
/// A PD controller on a pendulum with one ideal torque actuator. Without gravity
/// compensation it settles where the spring balances gravity, `k_p (q_ref - q) = m g l sin q`,
/// which the test solves by Newton's method.
///
/// ```
/// use biped_dynamics::{BodySpec, JointModel, ModelBuilder, RigidInertia};
/// use biped_sim::controller::{Commands, Controller};
/// use biped_sim::drive::{Actuator, DriveMode, FrictionParams, MotorParams, Transmission};
/// use biped_sim::plant::{Plant, PlantConfig};
/// use biped_sim::sensors::Sensors;
/// use biped_sim::simulation::Simulation;
/// use biped_sim::{Method, SimError};
/// use nalgebra::{DVector, Isometry3, Matrix3, Vector3};
///
/// struct Pd { q_ref: f64, kp: f64, kd: f64 }
/// impl Controller for Pd {
///     fn period(&self) -> f64 { 1e-3 }
///     fn mode(&self) -> DriveMode { DriveMode::Torque }
///     fn update(&mut self, _t: f64, s: &Sensors, c: &mut Commands) -> Result<(), SimError> {
///         c.values[0] = self.kp * (self.q_ref - s.joint_positions[0]) - self.kd * s.joint_velocities[0];
///         Ok(())
///     }
/// }
///
/// let (m, l, g) = (1.0, 0.5, 9.81);
/// let bob = RigidInertia::new(m, Vector3::new(0.0, 0.0, -l), Matrix3::zeros())?;
/// let hinge = JointModel::Revolute { axis: Vector3::y_axis() };
/// let mut builder = ModelBuilder::new();
/// builder.add_body(BodySpec::named("rod", None, hinge, Isometry3::identity(), bob))?;
/// let motor = Actuator {
///     name: "rod".into(),
///     joint_q: 0,
///     joint_v: 0,
///     transmission: Transmission::Direct,
///     motor: MotorParams::default(),
///     friction: FrictionParams::none(),
///     nominal_ratio: 1.0,
///     effort: f64::INFINITY,
///     velocity: f64::INFINITY,
/// };
/// let plant = Plant::new(builder.build()?, vec![motor], &[], vec![], PlantConfig::default())?;
/// let z0 = plant.initial_state(&DVector::zeros(1), &DVector::zeros(1))?;
/// let pd = Pd { q_ref: 0.5, kp: 20.0, kd: 4.0 };
/// let mut sim = Simulation::new(plant, pd, Method::Rk4, z0)?;
/// sim.run(4.0, &mut |_| Ok(()))?;
///
/// let mut q: f64 = 0.5; // Newton on kp (q_ref - q) - m g l sin q = 0
/// for _ in 0..20 {
///     q -= (20.0 * (0.5 - q) - m * g * l * q.sin()) / (-20.0 - m * g * l * q.cos());
/// }
/// assert!((sim.state()[0] - q).abs() < 1e-6, "{} vs {q}", sim.state()[0]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
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
