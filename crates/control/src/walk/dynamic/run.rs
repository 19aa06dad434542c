//! [`run_dynamic_walk`]: the kinematic walk tracked in the contact simulation, with its time
//! series and pass criteria.

use super::feedforward::Feedforward;
use super::force::ForceControl;
use super::margins::simulated_margins;
use super::reference::{build_robot_reference, JointReference};
use super::robot::{DynamicRobot, PlantSource};
use super::slip::{SideContact, SideSample};
use super::stabiliser::Stabiliser;
use super::tracking::TrackingController;
use super::{DynamicWalkParams, DynamicWalkSeries, DynamicWalkSummary};
use crate::pattern::WalkingPattern;
use crate::walk::error::{model_err, WalkError};
use crate::walk::{WalkJoint, WalkRobot};
use biped_dynamics::Model;
use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::plant::{urdf_plant, Plant, PlantConfig};
use biped_sim::simulation::{Frame, Simulation};
use biped_sim::{Method as Integrator, SimError};
use nalgebra::DVector;
use std::time::Instant;

/// Result of [`run_dynamic_walk`].
#[derive(Debug, Clone)]
pub struct DynamicWalkRun {
    /// Time series, one row per control cycle.
    pub series: DynamicWalkSeries,
    /// Summary and verdict.
    pub summary: DynamicWalkSummary,
    /// The simulated plant's model (of [`DynamicWalkSeries::q`]).
    pub model: Model,
}

/// Runs the kinematic walk of `p`, then tracks it with [`TrackingController`] on the Lola
/// Type 2 plant (torque mode, RK4 at the 1 ms control period) until the walk plus
/// `p.hold_time` is over or the robot falls.
pub fn run_dynamic_walk(p: &DynamicWalkParams) -> Result<DynamicWalkRun, WalkError> {
    run_dynamic_walk_robot(&DynamicRobot::lola(LolaType::Type2)?, p)
}

/// [`run_dynamic_walk`] for any [`DynamicRobot`]: its plant, its kinematic walk as the
/// reference, the feedforward, stabiliser and force control on its feet and legs.
pub fn run_dynamic_walk_robot(
    robot: &DynamicRobot,
    p: &DynamicWalkParams,
) -> Result<DynamicWalkRun, WalkError> {
    p.validate()?;
    let mut plant = robot_plant(robot, p)?;
    let walk = &robot.walk;
    let pattern =
        WalkingPattern::generate(&walk.pattern_params(p.steps, p.step_length, p.step_time))?;
    let joints = actuated_joints(&plant, walk)?;
    let ff = Feedforward::for_bodies(plant.model().clone(), robot.feet, robot.toes)?;
    let reference = build_robot_reference(walk, &joints, ff, &pattern, &p.reference_options())?;
    let q0 = start_on_ground(&plant, &reference.q0)?;
    let z0 = plant
        .initial_state(&q0, &DVector::zeros(plant.layout().nv))
        .map_err(model_err)?;
    let names: Vec<String> = plant.actuators().iter().map(|a| a.name.clone()).collect();
    let mut ctrl = TrackingController::new(
        &mut plant,
        reference.clone(),
        &q0,
        (p.bandwidth, p.damping),
        p.feedforward,
        None,
    )
    .map_err(model_err)?;
    if let Some(g) = p.stabiliser {
        let s = Stabiliser::for_legs(&names, &robot.legs, g).map_err(model_err)?;
        ctrl = ctrl.with_stabiliser(s);
    }
    if let Some(g) = p.force {
        ctrl = ctrl.with_force_control(ForceControl::for_robot(robot, &plant, g)?);
    }
    ctrl.scale_gains(p.gain_scale);
    let mut sim = Simulation::new(plant, ctrl, Integrator::Rk4, z0).map_err(model_err)?;
    let duration = (reference.len() - 1) as f64 * reference.dt + p.hold_time;
    simulate(&mut sim, (&reference, walk), p, duration)
}

/// The plant of `robot` with the end stops and ground friction of `p`.
pub fn robot_plant(robot: &DynamicRobot, p: &DynamicWalkParams) -> Result<Plant, WalkError> {
    let mut config = PlantConfig {
        contact: robot.contact,
        ..PlantConfig::default()
    };
    config.passive.end_stops = p.end_stops;
    config.contact.friction = p.friction;
    match &robot.source {
        PlantSource::Lola(variant) => Ok(lola_plant(*variant, config).map_err(model_err)?.plant),
        PlantSource::Urdf {
            path,
            feet,
            armature,
        } => urdf_plant(path, feet, armature, config).map_err(model_err),
    }
}

/// The plant's actuated joints in actuator order, with the ranges of `walk`'s joints (none:
/// unbounded); an actuator on other coordinates than `walk`'s joint of its name is an error.
fn actuated_joints(plant: &Plant, walk: &WalkRobot) -> Result<Vec<WalkJoint>, WalkError> {
    plant
        .actuators()
        .iter()
        .map(|a| match walk.joint(&a.name) {
            Some(j) if (j.q_index, j.v_index) == (a.joint_q, a.joint_v) => Ok(j.clone()),
            Some(_) => Err(model_err(format!(
                "actuator {} is on other coordinates than the walk's joint",
                a.name
            ))),
            None => Ok(WalkJoint {
                name: a.name.clone(),
                q_index: a.joint_q,
                v_index: a.joint_v,
                lower: f64::NEG_INFINITY,
                upper: f64::INFINITY,
            }),
        })
        .collect()
}

/// `q` shifted vertically so that the lowest sole point sits at the static penetration of
/// the contact law under the robot's weight shared by all points.
pub fn start_on_ground(plant: &Plant, q: &DVector<f64>) -> Result<DVector<f64>, WalkError> {
    let mut q = q.clone();
    let model = plant.model();
    let mass = model.mass();
    let c = plant.contact();
    let per_point = mass * model.gravity().norm() / c.npoints().max(1) as f64;
    let pen = c.params().static_penetration(per_point);
    let (qi, _) = plant
        .floating_base()
        .ok_or_else(|| model_err("plant without floating base"))?;
    let low = c.lowest_point(q.as_slice(), plant.layout().nv);
    q[qi + 2] += c.params().ground_height - pen - low;
    Ok(q)
}

/// Runs the loop in chunks of 50 ms, recording every cycle; stops at the end of the chunk in
/// which a fall is detected (so the series run up to 50 ms past `fell_at`), or where the
/// simulation diverged ([`SimError::is_divergence`]: a fall at the last finite sample).
fn simulate(
    sim: &mut Simulation<TrackingController>,
    (r, robot): (&JointReference, &WalkRobot),
    p: &DynamicWalkParams,
    duration: f64,
) -> Result<DynamicWalkRun, WalkError> {
    let cycles = (duration / r.dt).round() as usize + 1;
    let mut s = DynamicWalkSeries::with_capacity(cycles);
    let model = sim.plant().model().clone();
    s.q_names = model.q_names();
    s.q.reserve(cycles * s.q_names.len());
    let (qi, _) = sim
        .plant()
        .floating_base()
        .ok_or_else(|| model_err("plant without floating base"))?;
    let sides = SideContact::new(sim.plant().contact())?;
    let fall_height = sim.state()[qi + 2] - p.fall_drop;
    let (mut fell_at, mut diverged) = (None, false);
    let rhs0 = sim.plant().rhs_count();
    let start = Instant::now();
    let chunk = 0.05_f64;
    while sim.time() < duration - 1e-9 && fell_at.is_none() {
        let span = chunk.min(duration - sim.time());
        let mut obs = |f: &Frame| -> Result<(), SimError> {
            if s.t.last().is_some_and(|&t| f.t <= t + 1e-9) {
                return Ok(());
            }
            record(&mut s, f, r, qi, &sides);
            let (z, tilt) = (f.z[qi + 2], *s.tilt.last().unwrap_or(&0.0));
            if fell_at.is_none() && (z < fall_height || tilt > p.max_tilt) {
                fell_at = Some(f.t);
            }
            Ok(())
        };
        match sim.run(span, &mut obs) {
            Ok(_) => {}
            Err(e) if e.is_divergence() => {
                diverged = true;
                fell_at = fell_at.or(Some(s.t.last().copied().unwrap_or(sim.time())));
            }
            Err(e) => return Err(model_err(e)),
        }
    }
    let wall = start.elapsed().as_secs_f64();
    let rhs = sim.plant().rhs_count() - rhs0;
    let margins = simulated_margins(robot, &s)?;
    let summary = DynamicWalkSummary::evaluate(&s, r, p, (wall, rhs), (fell_at, diverged), margins);
    Ok(DynamicWalkRun {
        series: s,
        summary,
        model,
    })
}

/// Appends one cycle of signals.
fn record(s: &mut DynamicWalkSeries, f: &Frame, r: &JointReference, qi: usize, c: &SideContact) {
    let z = f.z;
    let k = r.index(f.t);
    s.t.push(f.t);
    s.base.push([z[qi], z[qi + 1], z[qi + 2]]);
    s.planned_base_x.push(r.base[k].x);
    let (x, y) = (z[qi + 3], z[qi + 4]);
    let n2 = z[qi + 3..qi + 7]
        .iter()
        .map(|c| c * c)
        .sum::<f64>()
        .max(1e-300);
    s.tilt
        .push((1.0 - 2.0 * (x * x + y * y) / n2).clamp(-1.0, 1.0).acos());
    let [left, right] = c.sample(f.plant, f.z);
    let both = |g: fn(&SideSample) -> f64| [g(&left), g(&right)];
    s.foot_fz.push(both(|w| w.fz));
    s.tau_z.push(both(|w| w.tau_z));
    s.toe_fz.push(both(|w| w.toe_fz));
    s.heel_lift.push(both(|w| w.heel_lift));
    s.friction_usage.push(both(|w| w.friction_usage));
    s.slip_speed.push(both(|w| w.slip_speed));
    s.points_in_contact.push([left.points, right.points]);
    s.q.extend_from_slice(&z[..s.q_names.len()]);
    let q = r.row(&r.q, k);
    let err = q
        .iter()
        .zip(&f.sensors.joint_positions)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
    s.tracking_error.push(err);
}
