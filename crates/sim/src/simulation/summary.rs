//! Result of one run, serialisable (the CLI's `summary.json`).

use super::Simulation;
use crate::controller::Controller;
use crate::drive::DriveMode;
use crate::passive::{PassiveJoints, PassiveRate};
use crate::plant::StateLayout;
use nalgebra::Vector3;
use serde::Serialize;

/// One pass criterion of a scenario.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Check {
    /// What is checked.
    pub name: String,
    /// Measured value.
    pub value: f64,
    /// Limit it is compared with.
    pub limit: f64,
    /// Whether the criterion holds.
    pub passed: bool,
}

/// Summary of a run.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// Integration method.
    pub method: String,
    /// Drive mode.
    pub drive_mode: DriveMode,
    /// Control period \[s].
    pub control_period: f64,
    /// Simulated time of this run \[s].
    pub sim_time: f64,
    /// Wall-clock time of the loop \[s] (sensors, controller, observer, integration).
    pub wall_time: f64,
    /// `sim_time / wall_time`.
    pub realtime_factor: f64,
    /// Control cycles.
    pub control_cycles: u64,
    /// Integrator steps.
    pub steps: u64,
    /// Right-hand-side evaluations (each one forward-dynamics call).
    pub rhs_evaluations: u64,
    /// State layout (Table 2.3 counts).
    pub layout: StateLayout,
    /// Total mass \[kg].
    pub mass: f64,
    /// Weight `m |g|` \[N].
    pub weight: f64,
    /// CoM at the start of the run \[m].
    pub initial_com: [f64; 3],
    /// CoM at the end \[m].
    pub final_com: [f64; 3],
    /// Largest total vertical contact force at the control samples \[N].
    pub max_contact_force: f64,
    /// Total vertical contact force at the end \[N].
    pub final_contact_force: f64,
    /// Largest `|v_i|` at the end over the link coordinates (base and joints; Type 3 motor
    /// coordinates, which turn `N` times faster, excluded).
    pub final_max_speed: f64,
    /// The link coordinate of [`Self::final_max_speed`]: its joint's name, with `[k]` for
    /// the `k`-th velocity of a multi-DoF joint (`root[3]` = a free base's x angular rate).
    pub final_fastest: Option<String>,
    /// Largest joint speed of the actuated joints at the end \[rad/s].
    pub final_max_joint_speed: f64,
    /// The plant's passive joint layer (end stops, joint friction).
    pub passive: PassiveSummary,
    /// How often the drive limits (effort, torque-speed line, current and voltage limits) cut
    /// the controller's commands.
    pub drive_limits: DriveLimits,
    /// Pass criteria (filled by a scenario).
    pub checks: Vec<Check>,
}

/// Commands cut by the drive limits over a run ([`crate::plant::Plant::hold_commands`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DriveLimits {
    /// Control cycles in which at least one command was cut.
    pub cycles: u64,
    /// The actuator cut in the most cycles (the first in actuator order among equals), `None`
    /// if no command was cut.
    pub most: Option<LimitedJoint>,
}

/// One actuator's count of cut commands.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LimitedJoint {
    /// Joint name.
    pub joint: String,
    /// Control cycles in which its command was cut.
    pub cycles: u64,
}

impl DriveLimits {
    /// The limits summary from the per-actuator counts (actuator order) and the total.
    pub(super) fn of(plant: &crate::plant::Plant, per_actuator: &[u64], cycles: u64) -> Self {
        let most = per_actuator
            .iter()
            .zip(plant.actuators())
            .filter(|(n, _)| **n > 0)
            .rev() // max_by_key keeps the last maximum: the first in actuator order.
            .max_by_key(|(n, _)| **n)
            .map(|(n, a)| LimitedJoint {
                joint: a.name.clone(),
                cycles: *n,
            });
        Self { cycles, most }
    }
}

/// Size and fastest law of the plant's passive joint layer ([`crate::passive`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PassiveSummary {
    /// Joints with end stops.
    pub end_stops: usize,
    /// Joints with damping or friction.
    pub friction_laws: usize,
    /// The fastest law, `None` for an empty layer.
    pub fastest: Option<PassiveRate>,
}

impl PassiveSummary {
    /// The summary of `p`.
    pub fn of(p: &PassiveJoints) -> Self {
        Self {
            end_stops: p.stops().len(),
            friction_laws: p.friction().len(),
            fastest: p.fastest().cloned(),
        }
    }
}

/// Largest `|v_i|` over the non-motor coordinates.
fn link_speed(plant: &crate::plant::Plant, v: &[f64]) -> (f64, Option<usize>) {
    let motor = |i: usize| plant.gears().iter().any(|g| g.motor_v == i);
    v.iter()
        .enumerate()
        .filter(|(i, _)| !motor(*i))
        .fold((0.0f64, None), |(m, at), (i, x)| match x.abs() > m {
            true => (x.abs(), Some(i)),
            false => (m, at),
        })
}

/// Name of velocity coordinate `i`: the joint owning it, `[k]` added for multi-DoF joints.
pub(crate) fn coordinate_name(model: &biped_dynamics::Model, i: usize) -> Option<String> {
    let j = (model.joints().iter()).find(|j| (j.v_index..j.v_index + j.nv).contains(&i))?;
    Some(match j.nv {
        1 => j.name.clone(),
        _ => format!("{}[{}]", j.name, i - j.v_index),
    })
}

impl Summary {
    /// Summary of the run that just ended on `sim`.
    pub(super) fn new<C: Controller>(
        sim: &Simulation<C>,
        (t0, wall): (f64, f64),
        (rhs0, steps0, cycles): (u64, u64, u64),
        (com0, com1): (Vector3<f64>, Vector3<f64>),
    ) -> Self {
        let plant = &sim.plant;
        let l = plant.layout();
        let mass = plant.model().mass();
        let sim_time = sim.t - t0;
        let abs_max = |x: &[f64]| x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let fastest = link_speed(plant, &sim.z[l.v()]);
        Self {
            method: sim.method().name().to_string(),
            drive_mode: plant.mode(),
            control_period: sim.controller.period(),
            sim_time,
            wall_time: wall,
            realtime_factor: if wall > 0.0 {
                sim_time / wall
            } else {
                f64::INFINITY
            },
            control_cycles: cycles,
            steps: sim.steps - steps0,
            rhs_evaluations: plant.rhs_count() - rhs0,
            layout: l,
            mass,
            weight: mass * plant.model().gravity().norm(),
            initial_com: com0.into(),
            final_com: com1.into(),
            max_contact_force: sim.max_contact,
            drive_limits: DriveLimits::of(plant, &sim.limited.per_actuator, sim.limited.cycles),
            final_contact_force: plant
                .last_outputs()
                .contact
                .feet
                .iter()
                .map(|f| f.force.z)
                .sum(),
            final_max_speed: fastest.0,
            final_fastest: fastest.1.and_then(|i| coordinate_name(plant.model(), i)),
            final_max_joint_speed: abs_max(&sim.sensors.joint_velocities),
            passive: PassiveSummary::of(plant.passive()),
            checks: Vec::new(),
        }
    }

    /// True if every check passed.
    pub fn passed(&self) -> bool {
        self.checks.iter().all(|c| c.passed)
    }
}

#[cfg(test)]
mod tests {
    use super::coordinate_name;
    use biped_dynamics::{BodySpec, JointModel, ModelBuilder, RigidInertia};
    use nalgebra::{Isometry3, Matrix3, Vector3};

    /// Free base `root` (6 velocities) carrying a revolute `hip`: names by velocity index.
    #[test]
    fn coordinates_are_named_by_their_joint() {
        let inertia = RigidInertia::new(1.0, Vector3::zeros(), Matrix3::identity()).expect("I");
        let mut b = ModelBuilder::new();
        let spec = |name: &str, parent, joint| BodySpec {
            name: name.into(),
            joint_name: name.into(),
            parent,
            joint,
            placement: Isometry3::identity(),
            inertia,
        };
        let root = b
            .add_body(spec("root", None, JointModel::FreeQuaternion))
            .expect("root");
        let axis = Vector3::y_axis();
        b.add_body(spec("hip", Some(root), JointModel::Revolute { axis }))
            .expect("hip");
        let model = b.build().expect("model");
        let names: Vec<_> = (0..8).map(|i| coordinate_name(&model, i)).collect();
        let want: Vec<_> = (0..6).map(|k| Some(format!("root[{k}]"))).collect();
        assert_eq!(names[..6], want[..]);
        assert_eq!(names[6].as_deref(), Some("hip"));
        assert_eq!(names[7], None, "past the last coordinate");
    }
}
