//! The robot plant `zdot = f(z, u)` (2.2)-(2.4) assembled from the model layers of Table 2.3:
//! rigid multibody dynamics (O(n) forward dynamics with sub-systems), Type 3 elastic gears,
//! drive dynamics ([`crate::drive`]) and the contact layer ([`crate::contact`]). The input `u`
//! (the actuator commands) is held inside the plant and set by the control loop before each
//! control period (zero-order hold, Fig. 2.1).
//!
//! One right-hand side (`forces`): the kinematic phase of forward dynamics, contact forces
//! from its foot poses, drive and gear torques, the solve phase, `qdot` from `v`. Every buffer
//! is allocated in [`Plant::new`].

mod ankles;
mod armature;
mod build;
mod energy;
mod forces;
mod inertia;
pub mod kinematics;
pub mod layout;

pub use ankles::AnkleAxis;
pub use armature::Armature;
pub use build::{actuator, rotor_of, urdf_plant, UrdfFeet, URDF_GEAR_RATIO};
pub use energy::Energy;
pub use inertia::ActuatorInertia;
pub use layout::StateLayout;

use crate::contact::{ContactOutput, ContactParams, ContactSet, FootSpec};
use crate::controller::Commands;
use crate::drive::actuator::{DriveHold, DriveState, MotorRow};
use crate::drive::{Actuator, DriveMode, FrictionLaw, FrictionParams, MotorParams};
use crate::error::{finite, SimError};
use crate::ode::{OdeSystem, SplitSystem};
use crate::passive::{JointSpec, PassiveJoints, PassiveParams};
use biped_dynamics::ElasticGear;
use biped_dynamics::{Algorithm, Data, Model, Wrench};
use kinematics::QdotMap;
use nalgebra::DVector;
use serde::{Deserialize, Serialize};

/// Plant options.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PlantConfig {
    /// How the actuators are commanded.
    pub mode: DriveMode,
    /// Contact law and ground.
    pub contact: ContactParams,
    /// Elastic gear stiffness of Type 3 \[N m/rad] (link side).
    pub gear_stiffness: f64,
    /// Damping ratio `zeta` of each Type 3 gear: `d = 2 zeta sqrt(k J)` with the two-mass
    /// reduced inertia `J = J_link N^2 J_motor / (J_link + N^2 J_motor)` at the neutral pose
    /// (one value for gears on links from 0.2 kg toes to the 11 kg torso).
    pub gear_damping_ratio: f64,
    /// Motor constants given to every actuator by the robot builders.
    pub motor: MotorParams,
    /// Motor-side friction given to every actuator by the robot builders.
    pub friction: FrictionParams,
    /// End stops and joint friction built from the robot description ([`Plant::with_passive`]).
    #[serde(default)]
    pub passive: PassiveParams,
    /// Contact points on the toe segments of robots that have them (Lola: `l_toe` / `r_toe`,
    /// entries `left_toe` / `right_toe`, see `biped_robots::plant::lola_plant`); on by default. Off, a foot in
    /// toe-off stands on the front edge of its sole only.
    #[serde(default = "default_toe_contacts")]
    pub toe_contacts: bool,
    /// Forward-dynamics algorithm (O(n) by default).
    #[serde(skip, default = "default_algorithm")]
    pub algorithm: Algorithm,
}

fn default_algorithm() -> Algorithm {
    Algorithm::On
}

fn default_toe_contacts() -> bool {
    true
}

impl Default for PlantConfig {
    /// Torque mode, default contact, toe contacts, Type 3 gears of 2e4 N m/rad with 5 % damping.
    ///
    /// Stiffness note: on Lola's toe (link inertia ~2.5e-4 kg m^2) a 2e4 N m/rad gear has
    /// `omega = sqrt(k / J) ~ 9000 rad/s`, so Type 3 needs RK4 steps of <= 0.25 ms; Type 2
    /// (rigid gears) runs at the 1 ms control period.
    fn default() -> Self {
        Self {
            mode: DriveMode::Torque,
            contact: ContactParams::default(),
            gear_stiffness: 2.0e4,
            gear_damping_ratio: 0.05,
            motor: MotorParams::default(),
            friction: FrictionParams::default(),
            passive: PassiveParams::default(),
            toe_contacts: true,
            algorithm: Algorithm::On,
        }
    }
}

/// Everything the plant computes besides `zdot` at one state (overwritten by every call).
#[derive(Debug, Clone, Default)]
pub struct PlantOutputs {
    /// Contact forces, foot wrenches and foot poses.
    pub contact: ContactOutput,
    /// Motor-side state of each actuator.
    pub drives: Vec<DriveState>,
}

/// Robot plant: model, drives, contacts, state layout and the held command.
#[derive(Debug, Clone)]
pub struct Plant {
    model: Model,
    data: Data,
    config: PlantConfig,
    layout: StateLayout,
    actuators: Vec<Actuator>,
    gears: Vec<ElasticGear>,
    /// Damper of each gear \[N m s/rad] (link side).
    gear_damping: Vec<f64>,
    contact: ContactSet,
    qdot: QdotMap,
    commands: Vec<f64>,
    q: DVector<f64>,
    v: DVector<f64>,
    tau: DVector<f64>,
    fext: Vec<Wrench>,
    /// Motor-rate rows: constant ones from [`Plant::new`], roller-screw rows per evaluation.
    rows: Vec<Option<MotorRow>>,
    /// Each actuator's friction prepared once ([`FrictionLaw::from`]; the actuators never
    /// change after [`Plant::new`]).
    laws: Vec<FrictionLaw>,
    /// Each actuator's [`Actuator::hold`] of the held command, refreshed whenever the command
    /// changes (and per evaluation at the current state in voltage mode).
    holds: Vec<DriveHold>,
    /// The direct forces of `holds` in `v` coordinates: the start of every evaluation's `tau`.
    tau_held: Vec<f64>,
    out: PlantOutputs,
    scratch: Vec<f64>,
    /// Contact result of the last state pass for the next right-hand side at that state.
    contact_memo: forces::ContactMemo,
    /// End stops and joint friction ([`Self::with_passive`]; empty by default).
    passive: PassiveJoints,
    rhs_count: u64,
}

impl Plant {
    /// Assembles a plant; validates actuator indices, motor and friction parameters and feet.
    pub fn new(
        model: Model,
        actuators: Vec<Actuator>,
        feet: &[FootSpec],
        gears: Vec<ElasticGear>,
        config: PlantConfig,
    ) -> Result<Self, SimError> {
        for a in &actuators {
            a.motor.validate()?;
            a.friction.validate()?;
            if a.joint_q >= model.nq()
                || a.joint_v >= model.nv()
                || a.nominal_ratio.is_nan()
                || a.nominal_ratio <= 0.0
                || a.effort.is_nan()
                || a.effort <= 0.0
                || a.velocity.is_nan()
                || a.velocity <= 0.0
            {
                return Err(SimError::InvalidParameter {
                    what: format!("actuator `{}`", a.name),
                    reason:
                        "joint index out of range, nominal ratio, effort or velocity limit <= 0"
                            .into(),
                });
            }
        }
        crate::error::positive("gear_stiffness", config.gear_stiffness, true)?;
        crate::error::positive("gear_damping_ratio", config.gear_damping_ratio, true)?;
        let contact = ContactSet::new(&model, config.contact, feet)?;
        let ncurrent = if config.mode == DriveMode::Voltage {
            actuators.len()
        } else {
            0
        };
        let layout = StateLayout {
            nq: model.nq(),
            nv: model.nv(),
            ncontact: contact.nstates(),
            ncurrent,
        };
        let out = PlantOutputs {
            contact: contact.output(),
            drives: vec![DriveState::default(); actuators.len()],
        };
        let mut data = Data::new(&model);
        let gear_damping = inertia::gear_dampers(&model, &mut data, &gears, &config)?;
        let q0 = model.neutral();
        let rows = actuators
            .iter()
            .map(|a| a.motor_row(&model, q0.as_slice()))
            .collect::<Result<Vec<_>, _>>()?;
        if let Some(a) = actuators.iter().zip(&rows).find_map(|(a, row)| {
            let bad = row
                .iter()
                .flat_map(MotorRow::entries)
                .any(|(i, _)| i >= model.nv());
            bad.then_some(a)
        }) {
            return Err(SimError::InvalidParameter {
                what: format!("actuator `{}`", a.name),
                reason: "motor coordinate out of range".into(),
            });
        }
        let laws = actuators
            .iter()
            .map(|a| FrictionLaw::from(&a.friction))
            .collect();
        let mut plant = Self {
            data,
            gear_damping,
            qdot: QdotMap::new(&model),
            q: model.neutral(),
            v: DVector::zeros(model.nv()),
            tau: DVector::zeros(model.nv()),
            fext: vec![Wrench::zero(); model.nbodies()],
            rows,
            laws,
            holds: vec![DriveHold::default(); actuators.len()],
            tau_held: vec![0.0; model.nv()],
            commands: vec![0.0; actuators.len()],
            model,
            config,
            layout,
            actuators,
            gears,
            contact,
            out,
            scratch: vec![0.0; layout.dim()],
            contact_memo: forces::ContactMemo::default(),
            passive: PassiveJoints::default(),
            rhs_count: 0,
        };
        plant.hold_drives();
        Ok(plant)
    }

    /// Refreshes the drives' [`Actuator::hold`] of the held commands (zero currents in voltage
    /// mode: each evaluation redoes them at its state) and their direct forces `tau_held`.
    fn hold_drives(&mut self) {
        let mode = self.config.mode;
        self.tau_held.fill(0.0);
        let drives = self.actuators.iter().zip(&self.laws).zip(&self.rows);
        for ((h, &cmd), ((a, law), row)) in self.holds.iter_mut().zip(&self.commands).zip(drives) {
            *h = a.hold(law, mode, cmd, 0.0, row.is_some());
            self.tau_held[h.index] += h.direct;
        }
    }

    /// This plant with the end stops and joint friction of `specs`, built by
    /// [`PassiveJoints::new`] with `config.passive` and the joints' free inertias at the
    /// neutral configuration (replaces any earlier layer).
    pub fn with_passive(mut self, specs: &[JointSpec]) -> Result<Self, SimError> {
        let free = self.free_inertias(&self.model.neutral())?;
        self.passive = PassiveJoints::new(specs, |v| free[v], &self.config.passive)?;
        Ok(self)
    }

    /// End stops and joint friction.
    pub fn passive(&self) -> &PassiveJoints {
        &self.passive
    }

    /// The multibody model.
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// The options the plant was built with.
    pub fn config(&self) -> &PlantConfig {
        &self.config
    }

    /// Layout of `z`.
    pub fn layout(&self) -> StateLayout {
        self.layout
    }

    /// The actuators, in command order.
    pub fn actuators(&self) -> &[Actuator] {
        &self.actuators
    }

    /// Type 3 elastic gears (empty otherwise).
    pub fn gears(&self) -> &[ElasticGear] {
        &self.gears
    }

    /// The feet and contact law.
    pub fn contact(&self) -> &ContactSet {
        &self.contact
    }

    /// Drive mode (the kind of command the plant expects).
    pub fn mode(&self) -> DriveMode {
        self.config.mode
    }

    /// Number of right-hand-side evaluations so far.
    pub fn rhs_count(&self) -> u64 {
        self.rhs_count
    }

    /// The held command values.
    pub fn commands(&self) -> &[f64] {
        &self.commands
    }

    /// Holds `c` as the input until the next call (checks kind, length and finiteness).
    pub fn set_commands(&mut self, c: &Commands) -> Result<(), SimError> {
        self.store_commands(c)?;
        self.hold_drives();
        Ok(())
    }

    /// Checks kind, length and finiteness of `c` and copies its values into the held command
    /// (the drives' holds still to refresh).
    fn store_commands(&mut self, c: &Commands) -> Result<(), SimError> {
        if c.mode != self.config.mode {
            return Err(SimError::CommandKind {
                got: c.mode,
                expected: self.config.mode,
            });
        }
        if c.values.len() != self.commands.len() {
            return Err(SimError::Length {
                what: "commands",
                got: c.values.len(),
                expected: self.commands.len(),
            });
        }
        finite("commands", &c.values)?;
        self.commands.copy_from_slice(&c.values);
        Ok(())
    }

    /// [`Self::set_commands`] at the control sample `z`, as a drive's firmware limits its
    /// command from the measured speed each cycle: every command is held within its drive's
    /// limits ([`Actuator::limit`]), torque commands within the torque-speed envelope at the
    /// joint speed in `z` ([`Actuator::torque_envelope`]). The simulation holds its
    /// controller's commands this way; sampled per cycle, the line's slope `effort / omega_max`
    /// adds no stiffness to the integrated plant (a light joint without rotor inertia would
    /// need `h effort / (omega_max I) <= 2.785` for RK4 otherwise). [`Self::commands`] then
    /// holds the limited values.
    pub fn hold_commands(&mut self, c: &Commands, z: &[f64]) -> Result<(), SimError> {
        if z.len() != self.layout.dim() {
            return Err(SimError::Length {
                what: "z",
                got: z.len(),
                expected: self.layout.dim(),
            });
        }
        self.store_commands(c)?;
        let v = &z[self.layout.v()];
        let held = self.commands.iter_mut().zip(&self.rows);
        for (a, (cmd, row)) in self.actuators.iter().zip(held) {
            *cmd = a.limit(c.mode, *cmd, v[a.joint_v], row.is_some());
        }
        self.hold_drives();
        Ok(())
    }

    /// Initial state `z` from `(q, v)`: relaxed contact bristles, zero currents.
    pub fn initial_state(&self, q: &DVector<f64>, v: &DVector<f64>) -> Result<Vec<f64>, SimError> {
        let l = self.layout;
        if q.len() != l.nq || v.len() != l.nv {
            return Err(SimError::Length {
                what: "q or v",
                got: q.len() + v.len(),
                expected: l.nq + l.nv,
            });
        }
        finite("q", q.as_slice())?;
        finite("v", v.as_slice())?;
        let mut z = vec![0.0; l.dim()];
        z[l.q()].copy_from_slice(q.as_slice());
        z[l.v()].copy_from_slice(v.as_slice());
        self.qdot.normalize(&mut z[l.q()]);
        Ok(z)
    }

    /// Outputs of the last [`Self::outputs`], [`Self::state_outputs`] or right-hand side.
    pub fn last_outputs(&self) -> &PlantOutputs {
        &self.out
    }

    /// External body wrenches of the last evaluation (contact wrenches on the foot bodies, body
    /// frame, moment about the body origin; zero elsewhere).
    pub fn external_wrenches(&self) -> &[Wrench] {
        &self.fext
    }

    /// `(q index, v index)` of the floating base's quaternion joint, if any.
    pub fn floating_base(&self) -> Option<(usize, usize)> {
        self.qdot.floating_base()
    }

    /// The model and the workspace, for kinematics queries (CoM, Jacobians) at a state.
    pub fn model_and_data(&mut self) -> (&Model, &mut Data) {
        (&self.model, &mut self.data)
    }

    /// Workspace of the last dynamics or kinematics call (body poses etc.).
    pub fn data(&self) -> &Data {
        &self.data
    }
}

impl OdeSystem for Plant {
    type Error = SimError;

    fn dim(&self) -> usize {
        self.layout.dim()
    }

    fn rhs(&mut self, _t: f64, z: &[f64], zdot: &mut [f64]) -> Result<(), SimError> {
        self.eval(z, zdot)
    }

    fn project(&self, z: &mut [f64]) {
        self.qdot.normalize(&mut z[self.layout.q()]);
    }
}

impl SplitSystem for Plant {
    fn position_len(&self) -> usize {
        self.layout.nq
    }

    fn position_rate(&self, z: &[f64], xdot: &mut [f64]) {
        let l = self.layout;
        self.qdot.qdot(&z[l.q()], &z[l.v()], &mut xdot[..l.nq]);
    }
}
