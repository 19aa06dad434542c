//! [`LolaTasks`]: stacked task errors and Jacobians of Table 4.2 for the Type 2 model,
//! evaluated into preallocated buffers (one centroidal pass for the CoG, one Jacobian pass
//! for all bodies, no allocation per call).
//!
//! Rows per task (geometric Jacobians, Appendix C; `R_p` = planning frame, `A_t` = torso):
//! - foot / arm CoG position: `x = R_p^T (p - c)`, `J = R_p^T (J_p - J_C)`;
//! - foot orientation: `R_rel = A_t^T A_f`, error `log(R_d R_rel^T)` in torso axes,
//!   `J = A_t^T (J_w,foot - J_w,torso)` (since `dR_rel/dt = [A_t^T (w_f - w_t)]x R_rel`);
//! - upper body: error `log(A_d A_t^T)`, `J = J_w,torso`; CoG: `J = J_C`;
//! - joint tasks: `J = e_i^T`.
//!
//! The foot TCP is the origin of the `*_sole` marker body, or of the `*_toe` segment while
//! the heel is lifted (`LolaTargets::foot_frame`, [`FootFrame::Toe`]); an arm CoG is the CoG of the
//! subtree of its `*_shoulder` body (links and the rotors mounted in the arm).
//! Inactive tasks (activation weight 0) are left out of the stack; blended tasks get the
//! row softness of [`crate::ik::blend`].

use super::frames::{arm_bodies, WalkTaskFrames, JOINT_TASKS};
use super::rows::{com_jacobian_from_ag, put_rows};
use super::targets::{FootFrame, LolaTargets, TaskId};
use super::task::Frame;
use crate::error::IkError;
use crate::ik::blend::Activation;
use crate::ik::orientation::orientation_error;
use crate::ik::TaskMap;
use biped_dynamics::{Centroidal, Data, JacobianFrame, Jacobians, Model};
use biped_robots::lola::LolaModel;
use nalgebra::{DMatrix, DVector, Matrix3, Rotation3, Vector3};

/// Kinematic quantities measured at one configuration.
#[derive(Debug, Clone, Copy)]
struct Measured {
    cog: Vector3<f64>,
    foot_pos: [Vector3<f64>; 2],
    foot_rot: [Matrix3<f64>; 2],
    torso_rot: Matrix3<f64>,
    arm_cog: [Vector3<f64>; 2],
}

/// Lola's switchable task set (Table 4.2) over the Type 2 model; implements [`TaskMap`].
#[derive(Debug, Clone)]
pub struct LolaTasks {
    model: Model,
    data: Data,
    jac: Jacobians,
    cen: Centroidal,
    torso: usize,
    soles: [Frame; 2],
    toes: Option<[Frame; 2]>,
    arms: [Vec<(usize, Vector3<f64>, f64)>; 2],
    arm_mass: [f64; 2],
    joint_q: [Option<usize>; 7],
    joint_v: [usize; 7],
    /// Task targets `x_d` and feed-forward velocities.
    pub targets: LolaTargets,
    /// Activation ramp of every task, in [`TaskId::ALL`] order.
    pub activation: [Activation; 15],
    jc: DMatrix<f64>,
    j3: DMatrix<f64>,
    jarm: DMatrix<f64>,
    j6: DMatrix<f64>,
    j6t: DMatrix<f64>,
    soft: Vec<f64>,
    ff: DVector<f64>,
}

impl LolaTasks {
    /// Task set for `lola` (Type 2 expected), all tasks on, blend ramps of `ramp_time` seconds.
    pub fn new(lola: &LolaModel, ramp_time: f64) -> Result<Self, IkError> {
        Self::with_frames(&lola.model, &WalkTaskFrames::lola(lola)?, ramp_time)
    }

    /// Task set on `model` with the bodies and joints of `frames`, all tasks on (the joint
    /// tasks of unused slots stay off), blend ramps of `ramp_time` seconds.
    pub fn with_frames(
        model: &Model,
        frames: &WalkTaskFrames,
        ramp_time: f64,
    ) -> Result<Self, IkError> {
        let model = model.clone();
        frames.check(&model)?;
        let arms = frames.arm_roots.map(|root| arm_bodies(&model, root));
        let arm_mass = [0, 1].map(|s| arms[s].iter().map(|a| a.2).sum());
        let joint_q = frames.joints.map(|j| j.map(|(q, _)| q));
        let joint_v = frames.joints.map(|j| j.map_or(0, |(_, v)| v));
        let mut activation = [Activation::new(true, ramp_time); 15];
        for (k, j) in frames.joints.iter().enumerate() {
            if j.is_none() {
                activation[JOINT_TASKS[k].index()] = Activation::new(false, ramp_time);
            }
        }
        let nv = model.nv();
        Ok(Self {
            data: Data::new(&model),
            jac: Jacobians::new(&model),
            cen: Centroidal::new(&model),
            torso: frames.torso,
            soles: frames.soles,
            toes: frames.toes,
            arms,
            arm_mass,
            joint_q,
            joint_v,
            targets: LolaTargets::default(),
            activation,
            jc: DMatrix::zeros(3, nv),
            j3: DMatrix::zeros(3, nv),
            jarm: DMatrix::zeros(3, nv),
            j6: DMatrix::zeros(6, nv),
            j6t: DMatrix::zeros(6, nv),
            soft: vec![0.0; TaskId::TOTAL_ROWS],
            ff: DVector::zeros(TaskId::TOTAL_ROWS),
            model,
        })
    }

    /// The multibody model.
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// Kinematics of the last evaluation: joint data (poses) and all body Jacobian columns.
    pub fn kinematics(&self) -> (&Data, &Jacobians) {
        (&self.data, &self.jac)
    }

    /// Centroidal quantities (CoM, `A_G`, hence `J_L` (7.2)) of the last evaluation.
    pub fn centroidal(&self) -> &Centroidal {
        &self.cen
    }

    /// Requests switching task `id` on or off (ramped by [`Self::advance`]).
    pub fn switch(&mut self, id: TaskId, on: bool) {
        let on = on && self.available(id);
        self.activation[id.index()].switch(on);
    }

    /// False for the joint task of an unused slot (the robot has no such joint).
    pub fn available(&self, id: TaskId) -> bool {
        id.joint_slot().is_none_or(|k| self.joint_q[k].is_some())
    }

    /// Switches task `id` on or off immediately (no ramp).
    pub fn set_active_now(&mut self, id: TaskId, on: bool) {
        let on = on && self.available(id);
        let a = &mut self.activation[id.index()];
        a.switch(on);
        a.level = a.target;
    }

    /// Advances all activation ramps by `dt`.
    pub fn advance(&mut self, dt: f64) {
        self.activation.iter_mut().for_each(|a| a.advance(dt));
    }

    /// Sets every target to its current value at `q` (zero task error), velocities to zero.
    pub fn set_targets_from(&mut self, q: &DVector<f64>) -> Result<(), IkError> {
        let m = self.measure(q)?;
        let rpt = planning_rotation(self.targets.planning_yaw).transpose();
        let t = &mut self.targets;
        for s in 0..2 {
            t.foot_position[s] = rpt * (m.foot_pos[s] - m.cog);
            t.foot_orientation[s] = m.torso_rot.transpose() * m.foot_rot[s];
            t.arm_cog[s] = rpt * (m.arm_cog[s] - m.cog);
        }
        t.cog = m.cog;
        t.upper_body = m.torso_rot;
        for (k, i) in self.joint_q.iter().enumerate() {
            t.joints[k] = i.map_or(0.0, |i| q[i]);
        }
        t.velocity.fill(0.0);
        Ok(())
    }

    /// TCP frame of foot slot `s` (0 = right, 1 = left) for its target frame (the sole
    /// frame on feet without toes).
    fn foot_frame(&self, s: usize) -> &Frame {
        match (self.targets.foot_frame[s], &self.toes) {
            (FootFrame::Toe, Some(toes)) => &toes[s],
            _ => &self.soles[s],
        }
    }

    /// CoG, foot and torso poses, arm CoGs at `q`; runs one kinematics pass for both.
    fn measure(&mut self, q: &DVector<f64>) -> Result<Measured, IkError> {
        let kin = |e: biped_dynamics::JacobianError| IkError::Kinematics(e.to_string());
        self.jac
            .compute(&self.model, &mut self.data, q)
            .map_err(kin)?;
        // one FK pass: the centroidal matrix reuses the poses and columns just computed
        self.cen
            .compute_matrix_with(&self.model, &self.data, &self.jac)
            .map_err(kin)?;
        com_jacobian_from_ag(self.cen.ag().map_err(kin)?, self.cen.mass(), &mut self.jc);
        let pose = |b: usize| self.data.world_rot[b];
        let mut arm_cog = [Vector3::zeros(); 2];
        for ((cog, arm), mass) in arm_cog.iter_mut().zip(&self.arms).zip(self.arm_mass) {
            for &(b, com, m) in arm {
                *cog += (self.data.world_pos[b] + self.data.world_rot[b] * com) * m;
            }
            *cog /= mass;
        }
        let feet = [*self.foot_frame(0), *self.foot_frame(1)];
        let at =
            |f: &Frame| self.data.world_pos[f.body] + pose(f.body) * f.offset.translation.vector;
        let rot = |f: &Frame| pose(f.body) * f.offset.rotation.to_rotation_matrix().into_inner();
        Ok(Measured {
            cog: self.cen.com(),
            foot_pos: [at(&feet[0]), at(&feet[1])],
            foot_rot: [rot(&feet[0]), rot(&feet[1])],
            torso_rot: pose(self.torso),
            arm_cog,
        })
    }

    /// Error and Jacobian rows of task `id` at row `r`.
    fn write_task(
        &mut self,
        id: TaskId,
        m: &Measured,
        q: &DVector<f64>,
        r: usize,
        err: &mut DVector<f64>,
        out: &mut DMatrix<f64>,
    ) -> Result<(), IkError> {
        let kin = |e: biped_dynamics::JacobianError| IkError::Kinematics(e.to_string());
        let rpt = planning_rotation(self.targets.planning_yaw).transpose();
        let e = match id {
            TaskId::RightFootPosition | TaskId::LeftFootPosition => {
                let s = (id == TaskId::LeftFootPosition) as usize;
                let f = *self.foot_frame(s);
                let offset = f.offset.translation.vector;
                self.jac
                    .point_jacobian(f.body, &offset, &mut self.j3)
                    .map_err(kin)?;
                put_rows(out, r, &rpt, &self.j3, 0, Some(&self.jc), 0);
                self.targets.foot_position[s] - rpt * (m.foot_pos[s] - m.cog)
            }
            TaskId::RightFootOrientation | TaskId::LeftFootOrientation => {
                let s = (id == TaskId::LeftFootOrientation) as usize;
                let (sole, frame) = (self.foot_frame(s).body, JacobianFrame::WorldAligned);
                self.jac
                    .body_jacobian(sole, frame, &mut self.j6)
                    .map_err(kin)?;
                let at = m.torso_rot.transpose();
                put_rows(out, r, &at, &self.j6, 0, Some(&self.j6t), 0);
                orientation_error(&self.targets.foot_orientation[s], &(at * m.foot_rot[s]))
            }
            TaskId::CoG => {
                put_rows(out, r, &Matrix3::identity(), &self.jc, 0, None, 0);
                self.targets.cog - m.cog
            }
            TaskId::UpperBodyOrientation => {
                put_rows(out, r, &Matrix3::identity(), &self.j6t, 0, None, 0);
                orientation_error(&self.targets.upper_body, &m.torso_rot)
            }
            TaskId::RightArmCoG | TaskId::LeftArmCoG => {
                let s = (id == TaskId::LeftArmCoG) as usize;
                self.arm_jacobian(s)?;
                put_rows(out, r, &rpt, &self.jarm, 0, Some(&self.jc), 0);
                self.targets.arm_cog[s] - rpt * (m.arm_cog[s] - m.cog)
            }
            _ => {
                let k = id.joint_slot().unwrap_or(0);
                out.row_mut(r).fill(0.0);
                out[(r, self.joint_v[k])] = 1.0;
                let qi = self.joint_q[k].unwrap_or(0);
                err[r] = self.targets.joints[k] - q[qi];
                return Ok(());
            }
        };
        err.fixed_rows_mut::<3>(r).copy_from(&e);
        Ok(())
    }

    /// Arm CoG Jacobian `sum m_b J_p(b, com_b) / m_arm` into `jarm`.
    fn arm_jacobian(&mut self, s: usize) -> Result<(), IkError> {
        let kin = |e: biped_dynamics::JacobianError| IkError::Kinematics(e.to_string());
        self.jarm.fill(0.0);
        for &(b, com, mass) in &self.arms[s] {
            self.jac
                .point_jacobian(b, &com, &mut self.j3)
                .map_err(kin)?;
            let f = mass / self.arm_mass[s];
            for (a, b) in self.jarm.iter_mut().zip(self.j3.iter()) {
                *a += f * b;
            }
        }
        Ok(())
    }
}

impl TaskMap for LolaTasks {
    fn nq(&self) -> usize {
        self.model.nq()
    }

    fn nv(&self) -> usize {
        self.model.nv()
    }

    fn max_rows(&self) -> usize {
        TaskId::TOTAL_ROWS
    }

    /// Stacks the active tasks in [`TaskId::ALL`] order (Table 4.2).
    fn error_and_jacobian(
        &mut self,
        q: &DVector<f64>,
        err: &mut DVector<f64>,
        jac: &mut DMatrix<f64>,
    ) -> Result<usize, IkError> {
        let (rows, nv) = (TaskId::TOTAL_ROWS, self.model.nv());
        if err.len() < rows || jac.nrows() < rows || jac.ncols() != nv {
            return Err(IkError::Dimension {
                what: "task buffers (rows)",
                expected: rows,
                got: err.len().min(jac.nrows()),
            });
        }
        let m = self.measure(q)?;
        let kin = |e: biped_dynamics::JacobianError| IkError::Kinematics(e.to_string());
        self.jac
            .body_jacobian(self.torso, JacobianFrame::WorldAligned, &mut self.j6t)
            .map_err(kin)?;
        let mut r = 0;
        for id in TaskId::ALL {
            let a = self.activation[id.index()];
            if !a.is_active() {
                continue;
            }
            self.write_task(id, &m, q, r, err, jac)?;
            let (d, off) = (id.dim(), id.full_offset());
            for i in 0..d {
                self.soft[r + i] = a.softness();
                self.ff[r + i] = self.targets.velocity[off + i];
            }
            r += d;
        }
        Ok(r)
    }

    fn feedforward(&self, out: &mut DVector<f64>) {
        out.copy_from(&self.ff);
    }

    fn softness(&self) -> Option<&[f64]> {
        Some(&self.soft)
    }

    /// `q (+) v step` with quaternion free joints integrated on SE(3) (constant body twist, as
    /// [`biped_dynamics::integrate`]), written into `out` without allocation.
    fn retract(
        &self,
        q: &DVector<f64>,
        v: &DVector<f64>,
        step: f64,
        out: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        super::retract::retract_configuration(&self.model, q, v, step, out)
    }
}

/// Rotation of the planning frame: yaw about the inertial vertical.
fn planning_rotation(yaw: f64) -> Matrix3<f64> {
    Rotation3::from_axis_angle(&Vector3::z_axis(), yaw).into_inner()
}
