//! The task-adding methods of [`Ik`]: frame, relative frame, CoM, posture, joint and vertical
//! momentum tasks by URDF link and joint names.

use super::Ik;
use crate::error::IkError;
use crate::tasks::{MomentumAxes, Task, TaskHandle, TaskKind};
use nalgebra::{DVector, Isometry3, Matrix3, Vector3};

impl Ik {
    /// Hard task: link `name`'s world pose at `target`.
    pub fn frame_pose(
        &mut self,
        name: &str,
        target: Isometry3<f64>,
    ) -> Result<TaskHandle, IkError> {
        let frame = self.frame(name)?;
        self.add(Task::hard(TaskKind::Pose { frame, target }))
    }

    /// Hard task: link `name`'s world origin at `target`.
    pub fn frame_position(
        &mut self,
        name: &str,
        target: Vector3<f64>,
    ) -> Result<TaskHandle, IkError> {
        let frame = self.frame(name)?;
        self.add(Task::hard(TaskKind::Position { frame, target }))
    }

    /// Hard task: link `name`'s world orientation at `target`.
    pub fn frame_orientation(
        &mut self,
        name: &str,
        target: Matrix3<f64>,
    ) -> Result<TaskHandle, IkError> {
        let frame = self.frame(name)?;
        self.add(Task::hard(TaskKind::Orientation { frame, target }))
    }

    /// Hard task: link `name`'s origin at `target` in the frame of link `reference`.
    pub fn relative_position(
        &mut self,
        name: &str,
        reference: &str,
        target: Vector3<f64>,
    ) -> Result<TaskHandle, IkError> {
        let (frame, reference) = (self.frame(name)?, self.frame(reference)?);
        let kind = TaskKind::RelativePosition {
            frame,
            reference,
            target,
        };
        self.add(Task::hard(kind))
    }

    /// Hard task: link `name`'s orientation relative to link `reference` at `target`.
    pub fn relative_orientation(
        &mut self,
        name: &str,
        reference: &str,
        target: Matrix3<f64>,
    ) -> Result<TaskHandle, IkError> {
        let (frame, reference) = (self.frame(name)?, self.frame(reference)?);
        let kind = TaskKind::RelativeOrientation {
            frame,
            reference,
            target,
        };
        self.add(Task::hard(kind))
    }

    /// Hard task: the centre of mass at `target`.
    pub fn com(&mut self, target: Vector3<f64>) -> Result<TaskHandle, IkError> {
        self.add(Task::hard(TaskKind::Com { target }))
    }

    /// Soft task of weight `w`: every joint with a range towards its entry in `q0`.
    pub fn posture(&mut self, q0: &DVector<f64>, w: f64) -> Result<TaskHandle, IkError> {
        let joints = self
            .limits
            .ranges()
            .iter()
            .map(|r| (r.q_index, r.v_index))
            .collect();
        let kind = TaskKind::Posture {
            joints,
            target: q0.clone(),
        };
        self.add(Task::soft(kind, w))
    }

    /// Hard task: URDF joint `name` at `target`.
    pub fn joint(&mut self, name: &str, target: f64) -> Result<TaskHandle, IkError> {
        let (q_index, v_index) = self.joint_index(name)?;
        self.add(Task::hard(TaskKind::Joint {
            q_index,
            v_index,
            target,
        }))
    }

    /// Hard task: the vertical angular momentum about the CoM `J_Lz v = lz` (7.3).
    pub fn vertical_momentum(&mut self, lz: f64) -> Result<TaskHandle, IkError> {
        self.add(Task::hard(TaskKind::AngularMomentum {
            axes: MomentumAxes::Vertical,
            target: Vector3::new(0.0, 0.0, lz),
        }))
    }

    /// Makes task `h` soft with weight `w` (`None`: hard).
    pub fn set_weight(&mut self, h: TaskHandle, w: Option<f64>) -> Result<(), IkError> {
        if w.is_some_and(|w| !(w > 0.0 && w.is_finite())) {
            return Err(IkError::InvalidParameter {
                name: "task weight",
                reason: "must be finite and > 0",
            });
        }
        self.task_mut(h)?.weight = w;
        Ok(())
    }
}
