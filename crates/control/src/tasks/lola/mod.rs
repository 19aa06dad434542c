//! [`LolaTasks`]: the switchable, blended task set of Table 4.2 as one configuration of the
//! generic [`TaskStack`] (one centroidal pass for the CoG, one Jacobian pass for all bodies,
//! no allocation per call).
//!
//! Tasks (`R_p` = planning frame, `A_t` = torso; the rows of [`crate::tasks::task`]):
//! - foot position: an [`Offset`] of the foot TCP from the CoG in `R_p`;
//! - foot orientation: a [`RelativeOrientation`] of the foot TCP to the torso;
//! - upper body: an [`Orientation`] of the torso; CoG: a [`Com`] task;
//! - arm CoG: an [`Offset`] of the arm's [`SubtreeCom`] from the CoG in `R_p` (links and the
//!   rotors mounted in the arm);
//! - joint tasks: [`Joint`].
//!
//! The foot TCP is the origin of the `*_sole` marker body, or of the `*_toe` segment while
//! the heel is lifted (`LolaTargets::foot_frame`, [`Toe`]). Before each evaluation the
//! targets, activation ramps and feed-forward velocities are copied into the stack: inactive
//! tasks (activation weight 0) are left out, blended tasks get the row softness of
//! [`crate::ik::blend`] (joint tasks while blended become the stack's folded unit rows).
//!
//! [`Offset`]: crate::tasks::TaskKind::Offset
//! [`RelativeOrientation`]: crate::tasks::TaskKind::RelativeOrientation
//! [`Orientation`]: crate::tasks::TaskKind::Orientation
//! [`Com`]: crate::tasks::TaskKind::Com
//! [`Joint`]: crate::tasks::TaskKind::Joint
//! [`SubtreeCom`]: crate::tasks::Point::SubtreeCom
//! [`Toe`]: crate::tasks::FootFrame::Toe

mod config;

use super::frames::WalkTaskFrames;
use super::stack::{TaskHandle, TaskStack};
use super::targets::{LolaTargets, TaskId};
use super::task::{Frame, Task};
use crate::error::IkError;
use crate::ik::blend::Activation;
use crate::ik::TaskMap;
use biped_dynamics::{Centroidal, Data, Jacobians, Model};
use biped_robots::lola::LolaModel;
use config::{foot_frame, initial_kind, planning_rotation, set_target};
use nalgebra::{DMatrix, DVector, Vector3};

/// Lola's switchable task set (Table 4.2) over the Type 2 model; implements [`TaskMap`].
#[derive(Debug, Clone)]
pub struct LolaTasks {
    stack: TaskStack,
    /// Stack handle of every task in [`TaskId::ALL`] order (`None`: an unused joint slot).
    handles: [Option<TaskHandle>; 15],
    torso: usize,
    soles: [Frame; 2],
    toes: Option<[Frame; 2]>,
    joint_q: [Option<usize>; 7],
    /// Task targets `x_d` and feed-forward velocities.
    pub targets: LolaTargets,
    /// Activation ramp of every task, in [`TaskId::ALL`] order.
    pub activation: [Activation; 15],
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
        frames.check(model)?;
        let mut stack = TaskStack::new(model);
        let mut handles = [None; 15];
        let mut activation = [Activation::new(true, ramp_time); 15];
        for id in TaskId::ALL {
            match initial_kind(id, frames) {
                Some(kind) => handles[id.index()] = Some(stack.push(Task::hard(kind))?),
                None => activation[id.index()] = Activation::new(false, ramp_time),
            }
        }
        Ok(Self {
            stack,
            handles,
            torso: frames.torso,
            soles: frames.soles,
            toes: frames.toes,
            joint_q: frames.joints.map(|j| j.map(|(q, _)| q)),
            targets: LolaTargets::default(),
            activation,
        })
    }

    /// The multibody model.
    pub fn model(&self) -> &Model {
        self.stack.model()
    }

    /// The generic task stack this set configures.
    pub fn stack(&self) -> &TaskStack {
        &self.stack
    }

    /// Kinematics of the last evaluation: joint data (poses) and all body Jacobian columns.
    pub fn kinematics(&self) -> (&Data, &Jacobians) {
        self.stack.kinematics()
    }

    /// Centroidal quantities (CoM, `A_G`, hence `J_L` (7.2)) of the last evaluation.
    pub fn centroidal(&self) -> &Centroidal {
        self.stack.centroidal()
    }

    /// Requests switching task `id` on or off (ramped by [`Self::advance`]).
    pub fn switch(&mut self, id: TaskId, on: bool) {
        let on = on && self.available(id);
        self.activation[id.index()].switch(on);
    }

    /// False for the joint task of an unused slot (the robot has no such joint).
    pub fn available(&self, id: TaskId) -> bool {
        self.handles[id.index()].is_some()
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
        self.targets.velocity.fill(0.0);
        let all_on = self.activation;
        self.activation
            .iter_mut()
            .for_each(|a| *a = Activation::new(true, 0.0));
        let (rows, nv) = (self.max_rows(), self.nv());
        let (mut err, mut jac) = (DVector::zeros(rows), DMatrix::zeros(rows, nv));
        let result = self.error_and_jacobian(q, &mut err, &mut jac);
        self.activation = all_on;
        result?;
        // the stack now holds the measured values as `target - error`, in `TaskId::ALL` order
        let mut r = 0;
        for id in TaskId::ALL {
            if self.handles[id.index()].is_some() {
                self.take_measured(id, &err.rows(r, id.dim()), q);
                r += id.dim();
            }
        }
        Ok(())
    }

    /// Target of task `id` from its error rows `e` at the current targets (`x = x_d - e`).
    fn take_measured(&mut self, id: TaskId, e: &nalgebra::DVectorView<'_, f64>, q: &DVector<f64>) {
        let t = &mut self.targets;
        let x = |d: &Vector3<f64>| d - Vector3::new(e[0], e[1], e[2]);
        let (data, _) = self.stack.kinematics();
        let rot = |f: &Frame| {
            data.world_rot[f.body] * f.offset.rotation.to_rotation_matrix().into_inner()
        };
        let torso = data.world_rot[self.torso];
        match id {
            TaskId::RightFootPosition | TaskId::LeftFootPosition => {
                let s = (id == TaskId::LeftFootPosition) as usize;
                t.foot_position[s] = x(&t.foot_position[s]);
            }
            TaskId::RightFootOrientation | TaskId::LeftFootOrientation => {
                let s = (id == TaskId::LeftFootOrientation) as usize;
                let f = foot_frame((&self.soles, &self.toes), s, t.foot_frame[s]);
                t.foot_orientation[s] = torso.transpose() * rot(&f);
            }
            TaskId::CoG => t.cog = x(&t.cog),
            TaskId::UpperBodyOrientation => t.upper_body = torso,
            TaskId::RightArmCoG | TaskId::LeftArmCoG => {
                let s = (id == TaskId::LeftArmCoG) as usize;
                t.arm_cog[s] = x(&t.arm_cog[s]);
            }
            _ => {
                let k = id.joint_slot().unwrap_or(0);
                t.joints[k] = self.joint_q[k].map_or(0.0, |i| q[i]);
            }
        }
    }

    /// Copies targets, frames, activation and feed-forward velocities into the stack.
    fn configure(&mut self) {
        let axes = planning_rotation(self.targets.planning_yaw);
        for id in TaskId::ALL {
            let Some(h) = self.handles[id.index()] else {
                continue;
            };
            let a = self.activation[id.index()];
            let (t, frames) = (&self.targets, (&self.soles, &self.toes));
            let Some(task) = self.stack.task_mut(h) else {
                continue;
            };
            task.active = a.is_active();
            let c = a.softness();
            task.weight = (c > 0.0).then(|| 1.0 / c);
            let off = id.full_offset();
            for i in 0..id.dim() {
                task.velocity[i] = t.velocity[off + i];
            }
            set_target(id, &mut task.kind, t, frames, &axes);
        }
    }
}

impl TaskMap for LolaTasks {
    fn nq(&self) -> usize {
        self.stack.nq()
    }

    fn nv(&self) -> usize {
        self.stack.nv()
    }

    fn max_rows(&self) -> usize {
        self.stack.max_rows()
    }

    /// Stacks the active tasks in [`TaskId::ALL`] order (Table 4.2), blended joint tasks last.
    fn error_and_jacobian(
        &mut self,
        q: &DVector<f64>,
        err: &mut DVector<f64>,
        jac: &mut DMatrix<f64>,
    ) -> Result<usize, IkError> {
        self.configure();
        self.stack.error_and_jacobian(q, err, jac)
    }

    fn feedforward(&self, out: &mut DVector<f64>) {
        self.stack.feedforward(out)
    }

    fn softness(&self) -> Option<&[f64]> {
        self.stack.softness()
    }

    fn unit_rows(&self) -> &[usize] {
        self.stack.unit_rows()
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
        self.stack.retract(q, v, step, out)
    }
}
