//! The task-adding methods of [`Ik`]: frame, relative frame, offset, CoM, posture, joint and
//! vertical momentum tasks by URDF link and joint names.

use super::Ik;
use crate::error::IkError;
use crate::tasks::{MomentumAxes, Point, Task, TaskHandle, TaskKind};
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

    /// The point named `name`: `"com"` (the centre of mass), `"subtree:LINK"` (the centre of
    /// mass of LINK's body and every body beyond it) or link `name`'s origin.
    pub fn point(&self, name: &str) -> Result<Point, IkError> {
        Ok(match (name, name.strip_prefix("subtree:")) {
            ("com", _) => Point::Com,
            (_, Some(link)) => Point::SubtreeCom(self.frame(link)?.body),
            _ => Point::Frame(self.frame(name)?),
        })
    }

    /// Hard task: the offset `axes^T (p - p_from)` of point `point` from point `from` (names
    /// as in [`Self::point`]) at `target`, in `axes` (columns: the axes in world coordinates,
    /// e.g. a frame yawed with the robot's heading).
    pub fn offset(
        &mut self,
        point: &str,
        from: &str,
        axes: Matrix3<f64>,
        target: Vector3<f64>,
    ) -> Result<TaskHandle, IkError> {
        let (point, from) = (self.point(point)?, self.point(from)?);
        self.add(Task::hard(TaskKind::Offset {
            point,
            from,
            axes,
            target,
        }))
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
