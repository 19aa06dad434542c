//! Foot force control of the dynamic walk (the hybrid position/force control of Lola's walking
//! control that the thesis builds on, 4.5): the difference `dz = z_left - z_right` of the two
//! feet's heights follows the error of the difference of their vertical loads,
//! `T dz' = k (dF_measured - dF_planned) - dz`, `dF = F_left - F_right`, clamped to
//! `max_offset`; each foot moves by `+-dz / 2` along the world vertical, relative to the
//! pelvis, through its leg's joints (damped least squares on the sole's 6 x 6 leg Jacobian,
//! the foot's orientation kept).
//!
//! Stiff position-controlled legs on a stiff ground share the load of a double support by
//! sub-millimetre differences of their lengths, and a swing foot touching down earlier or
//! later than planned meets the ground with the full stiffness of the leg: the landing heel
//! bounces off while the rear toe launches the robot. With the force loop a foot that carries
//! more than planned (an early touch-down, the heel edge during the roll) yields upwards and
//! one that carries less reaches down.

use super::reference::JointReference;
use super::robot::DynamicRobot;
use super::robot_legs::{DynamicLeg, LEG_JOINTS};
use crate::tasks::Frame;
use crate::walk::error::{model_err, WalkError};
use crate::walk::evaluate::body;
use biped_dynamics::{Data, JacobianFrame, Jacobians, Model};
use biped_robots::lola::LolaModel;
use biped_sim::plant::Plant;
use biped_sim::sensors::Sensors;
use nalgebra::{DMatrix, DVector, Matrix6, Vector3, Vector6};

/// Gains of the [`ForceControl`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForceGains {
    /// Steady-state height difference per load-difference error \[m/N] (0: off).
    pub compliance: f64,
    /// Time constant of the height difference \[s].
    pub time_constant: f64,
    /// Largest height difference \[m].
    pub max_offset: f64,
}

impl Default for ForceGains {
    /// `k = 3e-6 m/N` (a weight's worth of load error, 600 N, moves the feet 1.8 mm apart),
    /// `T = 0.03 s`, 10 mm: on the default walk the feet then share the ground without the
    /// flight phases of the position-controlled legs (2e-5 m/N oscillates against the
    /// ground's stiffness and falls; 1e-6 to 4e-6 m/N all walk it).
    fn default() -> Self {
        Self {
            compliance: 3e-6,
            time_constant: 0.03,
            max_offset: 0.01,
        }
    }
}

/// Per side: the actuator index and the velocity index of each leg joint.
type Leg = [(usize, usize); LEG_JOINTS];

/// The foot force controller: model workspace for the leg Jacobians and the height difference.
#[derive(Debug, Clone)]
pub struct ForceControl {
    gains: ForceGains,
    model: Model,
    data: Data,
    jac: Jacobians,
    full: DMatrix<f64>,
    q: DVector<f64>,
    actuator_q: Vec<usize>,
    legs: [Leg; 2],
    soles: [Frame; 2],
    entries: [Vec<usize>; 2],
    dz: f64,
}

impl ForceControl {
    /// Force control for `lola` (its soles `l_sole`, `r_sole`, legs `l_*`, `r_*`) on `plant`
    /// (contact sides `left`, `right`; actuators in the order of `lola.limits`).
    pub fn new(lola: &LolaModel, plant: &Plant, gains: ForceGains) -> Result<Self, WalkError> {
        let m = &lola.model;
        let soles = [body(m, "l_sole")?, body(m, "r_sole")?].map(Frame::body);
        let legs = [DynamicLeg::lola("l"), DynamicLeg::lola("r")];
        Self::for_legs(m.clone(), plant, &legs, soles, gains)
    }

    /// Force control of `robot` on its `plant` ([`DynamicRobot::legs`], [`DynamicRobot::soles`]).
    pub fn for_robot(
        robot: &DynamicRobot,
        plant: &Plant,
        gains: ForceGains,
    ) -> Result<Self, WalkError> {
        let model = plant.model().clone();
        Self::for_legs(model, plant, &robot.legs, robot.soles, gains)
    }

    /// Force control moving the `[left, right]` sole frames `soles` of `model` (the plant's
    /// coordinates) through the joints of `legs` on `plant` (contact sides `left`, `right`).
    pub fn for_legs(
        model: Model,
        plant: &Plant,
        legs: &[DynamicLeg; 2],
        soles: [Frame; 2],
        gains: ForceGains,
    ) -> Result<Self, WalkError> {
        let actuators = plant.actuators();
        let actuator = |name: &String| {
            actuators
                .iter()
                .position(|a| &a.name == name)
                .map(|a| (a, actuators[a].joint_v))
                .ok_or_else(|| model_err(format!("no actuated joint `{name}`")))
        };
        let leg = |l: &DynamicLeg| -> Result<Leg, WalkError> {
            let mut out = [(0, 0); LEG_JOINTS];
            for (slot, j) in out.iter_mut().zip(&l.joints) {
                *slot = actuator(j)?;
            }
            Ok(out)
        };
        let contact = plant.contact();
        let entries = |name: &str| {
            let side = contact
                .side_index(name)
                .ok_or_else(|| model_err(format!("the plant has no contact side `{name}`")))?;
            Ok::<_, WalkError>(contact.side_entries(side).to_vec())
        };
        if soles.iter().any(|s| s.body >= model.nbodies()) {
            return Err(model_err("a sole frame's body is not in the model"));
        }
        Ok(Self {
            gains,
            data: Data::new(&model),
            jac: Jacobians::new(&model),
            full: DMatrix::zeros(6, model.nv()),
            q: model.neutral(),
            actuator_q: actuators.iter().map(|a| a.joint_q).collect(),
            legs: [leg(&legs[0])?, leg(&legs[1])?],
            soles,
            entries: [entries("left")?, entries("right")?],
            dz: 0.0,
            model,
        })
    }

    /// The current height difference `z_left - z_right` \[m].
    pub fn offset(&self) -> f64 {
        self.dz
    }

    /// One control period `dt`: updates the height difference from the measured loads of
    /// `s` and the planned ones of sample `k` of `r`, and adds the leg joint offsets that
    /// realise it to `target` (actuator order).
    pub fn apply(
        &mut self,
        s: &Sensors,
        r: &JointReference,
        k: usize,
        dt: f64,
        target: &mut [f64],
    ) -> Result<(), WalkError> {
        let g = self.gains;
        if g.compliance <= 0.0 {
            return Ok(());
        }
        let load = |e: &[usize]| -> f64 {
            e.iter()
                .filter_map(|&i| s.foot_wrenches.get(i))
                .map(|w| w.lin.norm())
                .sum()
        };
        let measured = load(&self.entries[0]) - load(&self.entries[1]);
        let [pl, pr] = r.fz.get(k).copied().unwrap_or([0.0, 0.0]);
        let error = measured - (pl - pr);
        let rate = (g.compliance * error - self.dz) / g.time_constant.max(dt);
        self.dz = (self.dz + dt * rate).clamp(-g.max_offset, g.max_offset);
        self.place(&s.joint_positions)?;
        let up = match &s.imu {
            Some(imu) => imu.orientation.inverse() * Vector3::z(),
            None => Vector3::z(),
        };
        for (side, sign) in [(0, 0.5), (1, -0.5)] {
            let dq = self.leg_offsets(side, up * (sign * self.dz))?;
            for (&(a, _), d) in self.legs[side].iter().zip(dq.iter()) {
                target[a] += d;
            }
        }
        Ok(())
    }

    /// Kinematics at the joint angles `angles` (actuator order) with the pelvis at the
    /// origin (axes aligned).
    fn place(&mut self, angles: &[f64]) -> Result<(), WalkError> {
        for (&qi, &x) in self.actuator_q.iter().zip(angles) {
            self.q[qi] = x;
        }
        self.jac
            .compute(&self.model, &mut self.data, &self.q)
            .map_err(model_err)
    }

    /// The offsets of every actuated joint (actuator order; zero but for side `side`'s leg)
    /// that move its sole by `dp` (pelvis axes) at the joint angles `angles`, orientation
    /// kept ([`Self::apply`]'s step, for tests and scripts).
    pub fn leg_offsets_at(
        &mut self,
        angles: &[f64],
        side: usize,
        dp: Vector3<f64>,
    ) -> Result<Vec<f64>, WalkError> {
        if side > 1 || angles.len() != self.actuator_q.len() {
            return Err(model_err("side must be 0 or 1, angles one per actuator"));
        }
        self.place(angles)?;
        let dq = self.leg_offsets(side, dp)?;
        let mut out = vec![0.0; angles.len()];
        for (&(a, _), d) in self.legs[side].iter().zip(dq.iter()) {
            out[a] = *d;
        }
        Ok(out)
    }

    /// Leg joint offsets that move side `side`'s sole by `dp` (pelvis axes), orientation kept:
    /// `dq = J^T (J J^T + lambda^2 I)^-1 [0; dp]` with the sole's leg Jacobian `J`.
    fn leg_offsets(&mut self, side: usize, dp: Vector3<f64>) -> Result<Vector6<f64>, WalkError> {
        let sole = self.soles[side];
        let point = sole.offset.translation.vector;
        self.jac
            .frame_jacobian(
                sole.body,
                &point,
                JacobianFrame::WorldAligned,
                &mut self.full,
            )
            .map_err(model_err)?;
        let mut j = Matrix6::zeros();
        for (c, &(_, v)) in self.legs[side].iter().enumerate() {
            j.set_column(c, &self.full.column(v));
        }
        let x = Vector6::new(0.0, 0.0, 0.0, dp.x, dp.y, dp.z);
        let a = j * j.transpose() + Matrix6::identity() * 1e-4;
        let y = a
            .cholesky()
            .ok_or_else(|| model_err("leg Jacobian not factorisable"))?
            .solve(&x);
        Ok(j.transpose() * y)
    }
}
