//! The simulation loop of Fig. 2.1: sample sensors, run the controller, hold its commands,
//! integrate the plant over one control period, repeat; with an observer hook per cycle and
//! a serialisable [`Summary`].

mod checks;
mod signals;
mod summary;

/// CoM and centroidal momentum `h_G` (7.1) of a recorded frame: one forward-dynamics first
/// pass, no `A_G` (tests/sim_momentum.rs checks it against `A_G v`).
pub use biped_dynamics::{
    centroidal_momentum as centroidal_sample, CentroidalMomentum as CentroidalSample,
};
pub use signals::Signals;
pub use summary::{Check, DriveLimits, LimitedJoint, PassiveSummary, Summary};

use crate::controller::{Commands, Controller};
use crate::error::SimError;
use crate::ode::{Integrator, Method, Settings};
use crate::plant::Plant;
use crate::sensors::Sensors;
use biped_dynamics::center_of_mass;
use checks::{check_passive_rate, integ, LimitedCommands};
use nalgebra::DVector;
use std::time::Instant;

/// What the observer sees once per control cycle (after the controller ran, before the
/// integration of the period).
pub struct Frame<'a> {
    /// Time \[s].
    pub t: f64,
    /// State `z(t)`.
    pub z: &'a [f64],
    /// The plant (layout, outputs of `z(t)`; its workspace holds the forward-dynamics
    /// kinematics pass at `z(t)` from the sensors' sample).
    pub plant: &'a Plant,
    /// Sensor sample at `t`.
    pub sensors: &'a Sensors,
    /// Commands held from `t` on.
    pub commands: &'a Commands,
}

/// Plant + integrator + controller.
///
/// Build it from a [`Plant`], any [`Controller`] of the plant's drive mode and an initial
/// state ([`Plant::initial_state`]), then [`Self::run`] it for a duration, as often as you
/// like: each run continues from where the last one ended. The crate-level example measures
/// a pendulum's period with it; [`crate::scenario::build`] sets up a standing robot and
/// [`crate::controller::Controller`] shows a controller of one's own.
pub struct Simulation<C> {
    plant: Plant,
    controller: C,
    integrator: Integrator,
    z: Vec<f64>,
    t: f64,
    sensors: Sensors,
    commands: Commands,
    /// The commands as the plant holds them (within the drive limits).
    held: Commands,
    steps: u64,
    max_contact: f64,
    /// Control cycles of this run in which the drive limits cut a command, per actuator and
    /// in all ([`Plant::hold_commands`]).
    limited: LimitedCommands,
}

impl<C: Controller> Simulation<C> {
    /// Simulation from `z0` with `method`; fixed-step methods take one step per control period
    /// (`h` = period), Dopri5 uses default tolerances (rtol 1e-6, atol 1e-9).
    pub fn new(
        plant: Plant,
        controller: C,
        method: Method,
        z0: Vec<f64>,
    ) -> Result<Self, SimError> {
        let settings = Settings::fixed(controller.period());
        Self::with_settings(plant, controller, method, settings, z0)
    }

    /// Simulation with explicit integrator settings.
    pub fn with_settings(
        plant: Plant,
        controller: C,
        method: Method,
        settings: Settings,
        z0: Vec<f64>,
    ) -> Result<Self, SimError> {
        crate::error::positive("control period", controller.period(), false)?;
        if controller.mode() != plant.mode() {
            return Err(SimError::CommandKind {
                got: controller.mode(),
                expected: plant.mode(),
            });
        }
        let n = plant.layout().dim();
        if z0.len() != n {
            return Err(SimError::Length {
                what: "z0",
                got: z0.len(),
                expected: n,
            });
        }
        crate::error::finite("z0", &z0)?;
        check_passive_rate(&plant, method, &settings, controller.period())?;
        let integrator = Integrator::new(method, n, settings)
            .map_err(|e| SimError::Integrator(e.to_string()))?;
        let sensors = Sensors::new(&plant);
        let plant_actuators = plant.actuators().len();
        let commands = Commands::new(plant.mode(), plant_actuators);
        Ok(Self {
            plant,
            controller,
            integrator,
            z: z0,
            t: 0.0,
            sensors,
            held: commands.clone(),
            commands,
            steps: 0,
            max_contact: 0.0,
            limited: LimitedCommands {
                per_actuator: vec![0; plant_actuators],
                cycles: 0,
            },
        })
    }

    /// Current time.
    pub fn time(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn state(&self) -> &[f64] {
        &self.z
    }

    /// The plant.
    pub fn plant(&self) -> &Plant {
        &self.plant
    }

    /// The plant, mutable (e.g. for energy evaluations between runs).
    pub fn plant_mut(&mut self) -> &mut Plant {
        &mut self.plant
    }

    /// The controller.
    pub fn controller(&self) -> &C {
        &self.controller
    }

    /// The latest sensor sample.
    pub fn sensors(&self) -> &Sensors {
        &self.sensors
    }

    /// Height of the centre of mass at the current state.
    pub fn com(&mut self) -> Result<nalgebra::Vector3<f64>, SimError> {
        let l = self.plant.layout();
        let q = DVector::from_column_slice(&self.z[l.q()]);
        let (model, data) = self.plant.model_and_data();
        Ok(center_of_mass(model, data, &q, None)?.position)
    }

    /// Runs `duration` seconds (rounded to whole control periods), calling `observer` once per
    /// cycle and once at the end; returns the summary of this run.
    pub fn run(
        &mut self,
        duration: f64,
        observer: &mut dyn FnMut(&Frame) -> Result<(), SimError>,
    ) -> Result<Summary, SimError> {
        crate::error::positive("duration", duration, true)?;
        let period = self.controller.period();
        let cycles = (duration / period).round() as u64;
        let (t0, rhs0, steps0) = (self.t, self.plant.rhs_count(), self.steps);
        let com0 = self.com()?;
        self.limited.reset();
        let start = Instant::now();
        for k in 0..cycles {
            self.cycle(observer)?;
            let t1 = t0 + (k + 1) as f64 * period;
            let st = self
                .integrator
                .advance_split(&mut self.plant, self.t, t1, &mut self.z)
                .map_err(integ)?;
            self.steps += st.steps as u64;
            self.t = t1;
        }
        let wall = start.elapsed().as_secs_f64();
        self.sample()?;
        self.observe(observer)?;
        let com1 = self.com()?;
        Ok(Summary::new(
            self,
            (t0, wall),
            (rhs0, steps0, cycles),
            (com0, com1),
        ))
    }

    /// Sensors at the current state.
    fn sample(&mut self) -> Result<(), SimError> {
        self.sensors.update(&mut self.plant, self.t, &self.z)?;
        let fz: f64 = self
            .plant
            .last_outputs()
            .contact
            .feet
            .iter()
            .map(|f| f.force.z)
            .sum();
        self.max_contact = self.max_contact.max(fz);
        Ok(())
    }

    /// Observer call on the current state.
    fn observe(
        &self,
        observer: &mut dyn FnMut(&Frame) -> Result<(), SimError>,
    ) -> Result<(), SimError> {
        observer(&Frame {
            t: self.t,
            z: &self.z,
            plant: &self.plant,
            sensors: &self.sensors,
            commands: &self.held,
        })
    }

    /// One control cycle: sensors, controller, hold, observer.
    fn cycle(
        &mut self,
        observer: &mut dyn FnMut(&Frame) -> Result<(), SimError>,
    ) -> Result<(), SimError> {
        self.sample()?;
        self.controller
            .update(self.t, &self.sensors, &mut self.commands)?;
        self.plant.hold_commands(&self.commands, &self.z)?;
        self.held.values.copy_from_slice(self.plant.commands());
        self.limited.count(&self.commands.values, &self.held.values);
        self.observe(observer)
    }

    /// Largest total vertical contact force seen at the control samples.
    pub fn max_contact_force(&self) -> f64 {
        self.max_contact
    }

    /// Integrator steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The integration method.
    pub fn method(&self) -> Method {
        self.integrator.method()
    }
}
