//! Scenarios: `drop` (falls from 5 cm with joints held by PD control), `stand`
//! (stands under joint position control and comes to rest) and `sway` (shifts its pelvis and
//! CoM between the feet by hip and ankle adduction trajectories). Each builds the initial
//! state and the controller for a plant and carries its pass criteria.
//!
//! Initial pose: the named joint angles of [`ScenarioOptions::pose`] on the neutral
//! configuration, then the base height chosen so that the lowest contact point sits at the
//! static penetration of the contact law under the robot's weight (`stand`, `sway`) or
//! `drop_height` above the ground (`drop`).

mod criteria;
mod pose;

pub use criteria::{Criteria, Tracker, REST_CHECK};
pub use pose::{lola_pose, lola_sway_joints, SwayJoints};

use crate::controller::{Controller, JointPd};
use crate::error::SimError;
use crate::ode::{Method, Settings};
use crate::plant::Plant;
use crate::simulation::{Frame, Simulation, Summary};
use nalgebra::DVector;
use std::f64::consts::PI;

/// Which scenario.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScenarioKind {
    /// Fall from `drop_height` onto the ground, joints held by PD control.
    Drop,
    /// Stand under joint position control and come to rest.
    Stand,
    /// Shift the CoM between the feet by joint trajectories.
    Sway,
}

impl std::str::FromStr for ScenarioKind {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.to_ascii_lowercase().as_str() {
            "drop" => Ok(Self::Drop),
            "stand" => Ok(Self::Stand),
            "sway" => Ok(Self::Sway),
            _ => Err(format!("unknown scenario `{s}` (drop, stand, sway)")),
        }
    }
}

/// Scenario options (all have defaults).
#[derive(Debug, Clone, PartialEq)]
pub struct ScenarioOptions {
    /// Control period \[s] (default 1 ms).
    pub period: f64,
    /// Duration \[s] (default: drop 4, stand 3, sway 2 sway periods + 1 s).
    pub duration: Option<f64>,
    /// PD bandwidth `w` \[rad/s] of [`JointPd::scaled`] (default 40).
    pub bandwidth: f64,
    /// PD damping ratio (default 1).
    pub damping: f64,
    /// Drop height of the lowest contact point \[m] (default 0.05).
    pub drop_height: f64,
    /// Initial joint angles by joint name (others neutral).
    pub pose: Vec<(String, f64)>,
    /// Joints of the sway motion (required for `sway`).
    pub sway_joints: Option<SwayJoints>,
    /// Sway amplitude of the leg lean angle \[rad] (default 0.06).
    pub sway_amplitude: f64,
    /// Sway period \[s] (default 2).
    pub sway_period: f64,
    /// IMU damping through the ankles ([`JointPd::with_stance_damping`], gyroscope low-passed
    /// at the bandwidth; default on).
    pub stance_damping: bool,
}

impl Default for ScenarioOptions {
    fn default() -> Self {
        Self {
            period: 1e-3,
            duration: None,
            bandwidth: 40.0,
            damping: 1.0,
            drop_height: 0.05,
            pose: Vec::new(),
            sway_joints: None,
            sway_amplitude: 0.06,
            sway_period: 2.0,
            stance_damping: true,
        }
    }
}

impl ScenarioOptions {
    /// Defaults with Lola's bent-knee pose and sway joints.
    pub fn lola() -> Self {
        Self {
            pose: lola_pose(0.4),
            sway_joints: Some(lola_sway_joints()),
            ..Self::default()
        }
    }
}

/// A ready-to-run scenario: initial state, controller, duration and criteria.
#[derive(Debug)]
pub struct Scenario {
    /// Which scenario.
    pub kind: ScenarioKind,
    /// Initial configuration.
    pub q0: DVector<f64>,
    /// Initial state `z0`.
    pub z0: Vec<f64>,
    /// Joint PD controller (torque output).
    pub controller: JointPd,
    /// Duration \[s].
    pub duration: f64,
    /// Pass criteria.
    pub criteria: Criteria,
}

/// Builds `kind` for `plant` (torque mode) with `options`.
///
/// # Example
///
/// The Lola-like biped (Type 2) standing for a fifth of a second: the soles carry its weight
/// (total mass from the model's centre of mass, times `g`) and the base does not sink.
///
/// ```
/// use biped_dynamics::{center_of_mass, Data};
/// use biped_robots::lola::LolaType;
/// use biped_sim::plant::PlantConfig;
/// use biped_robots::plant::lola_plant;
/// use biped_sim::scenario::{self, ScenarioKind, ScenarioOptions};
/// use biped_sim::Method;
///
/// let mut lp = lola_plant(LolaType::Type2, PlantConfig::default())?;
/// let model = &lp.lola.model;
/// let mass = center_of_mass(model, &mut Data::new(model), &model.neutral(), None)?.mass;
///
/// let mut stand = scenario::build(ScenarioKind::Stand, &mut lp.plant, &ScenarioOptions::lola())?;
/// stand.duration = 0.2;
/// let base_z = stand.q0[2];
/// let (summary, sim) = stand.run(lp.plant, Method::Rk4, &mut |_| Ok(()))?;
/// assert_eq!(summary.control_cycles, 200);
/// assert!((summary.final_contact_force - mass * 9.81).abs() < 0.01 * mass * 9.81);
/// assert!((sim.state()[2] - base_z).abs() < 2e-3);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn build(
    kind: ScenarioKind,
    plant: &mut Plant,
    options: &ScenarioOptions,
) -> Result<Scenario, SimError> {
    let o = options;
    let mut q0 = pose::configuration(plant, &o.pose)?;
    let lift = if kind == ScenarioKind::Drop {
        o.drop_height
    } else {
        -pose::static_penetration(plant)
    };
    pose::place_on_ground(plant, &mut q0, lift)?;
    let z0 = plant.initial_state(&q0, &DVector::zeros(plant.layout().nv))?;
    let mut controller = JointPd::scaled(plant, &q0, o.period, o.bandwidth, o.damping)?;
    if o.stance_damping {
        controller = controller.with_stance_damping(plant, &q0, o.bandwidth)?;
    }
    let base = pose::base_height(plant, &q0);
    let (duration, criteria) = match kind {
        ScenarioKind::Drop => (4.0, Criteria::drop(base)),
        ScenarioKind::Stand => (3.0, Criteria::stand(base)),
        ScenarioKind::Sway => {
            let joints = o
                .sway_joints
                .as_ref()
                .ok_or_else(|| SimError::InvalidParameter {
                    what: "sway_joints".into(),
                    reason: "the sway scenario needs hip and ankle adduction joint names".into(),
                })?;
            crate::error::positive("sway_amplitude", o.sway_amplitude, false)?;
            pose::sway_within_stops(plant, &q0, joints, o.sway_amplitude)?;
            let traj = sway_trajectory(
                plant,
                joints,
                controller.target().to_vec(),
                o.sway_amplitude,
                o.sway_period,
            )?;
            controller = controller.with_trajectory(traj);
            let lean = pose::leg_length(plant, &q0, joints)? * o.sway_amplitude.sin();
            (2.0 * o.sway_period + 1.0, Criteria::sway(base, 0.5 * lean))
        }
    };
    Ok(Scenario {
        kind,
        q0,
        z0,
        controller,
        duration: o.duration.unwrap_or(duration),
        criteria,
    })
}

/// `phi(t) = A sin(2 pi t / T) s(t)` on both hip adductions and `-phi` on both ankle
/// adductions (parallel legs: pelvis and feet stay level), `s` a smooth ramp over the first
/// period.
fn sway_trajectory(
    plant: &Plant,
    joints: &SwayJoints,
    base: Vec<f64>,
    amplitude: f64,
    period: f64,
) -> Result<crate::controller::Trajectory, SimError> {
    crate::error::positive("sway_period", period, false)?;
    let find = |name: &String| {
        plant
            .actuators()
            .iter()
            .position(|a| &a.name == name)
            .ok_or_else(|| SimError::Unknown {
                kind: "sway joint",
                name: name.clone(),
            })
    };
    let hips = [find(&joints.hips[0])?, find(&joints.hips[1])?];
    let ankles = [find(&joints.ankles[0])?, find(&joints.ankles[1])?];
    Ok(Box::new(move |t, target: &mut [f64]| {
        let x = (t / period).min(1.0);
        let ramp = x * x * (3.0 - 2.0 * x);
        let phi = amplitude * (2.0 * PI * t / period).sin() * ramp;
        target.copy_from_slice(&base);
        for &h in &hips {
            target[h] += phi;
        }
        for &a in &ankles {
            target[a] -= phi;
        }
    }))
}

impl Scenario {
    /// Runs the scenario on `plant` with `method`, one integrator step per control period
    /// for fixed-step methods; `observer` sees every cycle. Fills the summary's checks.
    pub fn run(
        self,
        plant: Plant,
        method: Method,
        observer: &mut dyn FnMut(&Frame) -> Result<(), SimError>,
    ) -> Result<(Summary, Simulation<JointPd>), SimError> {
        let settings = Settings::fixed(self.controller.period());
        self.run_with(plant, method, settings, observer)
    }

    /// Like [`Self::run`] with explicit integrator settings (e.g. `h` = 0.1 ms for Type 3,
    /// whose stiff elastic gears need steps below the control period).
    pub fn run_with(
        self,
        plant: Plant,
        method: Method,
        settings: Settings,
        observer: &mut dyn FnMut(&Frame) -> Result<(), SimError>,
    ) -> Result<(Summary, Simulation<JointPd>), SimError> {
        self.run_wrapped(plant, Ok, method, settings, observer)
    }

    /// Like [`Self::run_with`] with the scenario's PD wrapped by `wrap` into another
    /// controller, e.g. for current or voltage mode:
    /// `|pd| Cascade::new(pd, CurrentPi::new(&plant, 1e-4, kp, ki)?, n)` (then `settings.h`
    /// must resolve the electrical time constant, see [`crate::drive`]).
    pub fn run_wrapped<C: Controller>(
        self,
        plant: Plant,
        wrap: impl FnOnce(JointPd) -> Result<C, SimError>,
        method: Method,
        settings: Settings,
        observer: &mut dyn FnMut(&Frame) -> Result<(), SimError>,
    ) -> Result<(Summary, Simulation<C>), SimError> {
        let base = plant.floating_base();
        let controller = wrap(self.controller)?;
        let mut sim = Simulation::with_settings(plant, controller, method, settings, self.z0)?;
        let mut tracker = Tracker::new(base.map(|(qi, _)| qi));
        let mut obs = |f: &Frame| {
            tracker.observe(f);
            observer(f)
        };
        let mut summary = sim.run(self.duration, &mut obs)?;
        self.criteria.evaluate(&mut summary, &tracker);
        Ok((summary, sim))
    }

    /// Control period of the scenario's controller.
    pub fn period(&self) -> f64 {
        self.controller.period()
    }
}
