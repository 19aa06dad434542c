//! [`TaskStack`]: a list of generic [`Task`]s on any model, stacked into one [`TaskMap`] (one
//! kinematics pass, one centroidal pass when a CoM or momentum task needs it, no allocation per
//! evaluation).
//!
//! Rows: the tasks in insertion order, except the soft posture and joint tasks, whose unit rows
//! come last (in insertion order) and are reported by [`TaskMap::unit_rows`], so that the
//! solver folds them into the joint weight instead of stacking them.

mod check;
mod frames;
mod map;
mod offset;
mod unit;

use super::rows::put_rows;
use super::task::{MomentumAxes, Task, TaskKind};
use crate::error::IkError;
use biped_dynamics::{Centroidal, Data, JacobianError, Jacobians, Model};
use nalgebra::{DMatrix, DVector, Matrix3};
use offset::Subtree;

/// Index of a task in its [`TaskStack`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct TaskHandle(pub usize);

/// Generic tasks stacked in insertion order (soft joint-space tasks last); implements
/// [`crate::ik::TaskMap`].
#[derive(Debug, Clone)]
pub struct TaskStack {
    model: Model,
    data: Data,
    jac: Jacobians,
    cen: Centroidal,
    tasks: Vec<Task>,
    rows: usize,
    jc: DMatrix<f64>,
    jl: DMatrix<f64>,
    j3: DMatrix<f64>,
    j3r: DMatrix<f64>,
    j6: DMatrix<f64>,
    j6r: DMatrix<f64>,
    jt: DMatrix<f64>,
    subtrees: Vec<Subtree>,
    soft: Vec<f64>,
    ff: DVector<f64>,
    /// Columns of the trailing unit rows of the last evaluation.
    unit: Vec<usize>,
}

fn kin(e: JacobianError) -> IkError {
    IkError::Kinematics(e.to_string())
}

impl TaskStack {
    /// An empty stack on `model`.
    pub fn new(model: &Model) -> Self {
        let nv = model.nv();
        Self {
            data: Data::new(model),
            jac: Jacobians::new(model),
            cen: Centroidal::new(model),
            tasks: Vec::new(),
            rows: 0,
            jc: DMatrix::zeros(3, nv),
            jl: DMatrix::zeros(3, nv),
            j3: DMatrix::zeros(3, nv),
            j3r: DMatrix::zeros(3, nv),
            j6: DMatrix::zeros(6, nv),
            j6r: DMatrix::zeros(6, nv),
            jt: DMatrix::zeros(3, nv),
            subtrees: Vec::new(),
            soft: Vec::new(),
            ff: DVector::zeros(0),
            unit: Vec::new(),
            model: model.clone(),
        }
    }

    /// The model.
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// Kinematics of the last evaluation: body poses and Jacobian columns.
    pub fn kinematics(&self) -> (&Data, &Jacobians) {
        (&self.data, &self.jac)
    }

    /// Centroidal quantities of the last evaluation (only computed when a CoM or momentum task
    /// is in the stack).
    pub fn centroidal(&self) -> &Centroidal {
        &self.cen
    }

    /// The tasks, in stacking order.
    pub fn tasks(&self) -> &[Task] {
        &self.tasks
    }

    /// Task `h` (to read or change its target, weight or velocity).
    pub fn task_mut(&mut self, h: TaskHandle) -> Option<&mut Task> {
        self.tasks.get_mut(h.0)
    }

    /// Appends `task` after checking its indices and weight against the model.
    pub fn push(&mut self, task: Task) -> Result<TaskHandle, IkError> {
        self.check(&task)?;
        if let TaskKind::Offset { point, from, .. } = &task.kind {
            self.cache_subtrees(&[*point, *from])?;
        }
        self.rows += task.kind.dim();
        self.tasks.push(task);
        self.soft.resize(self.rows, 0.0);
        self.ff = DVector::zeros(self.rows);
        self.unit = Vec::with_capacity(self.rows);
        Ok(TaskHandle(self.tasks.len() - 1))
    }

    /// Error and Jacobian rows of task `k` from row `r`.
    fn write_task(
        &mut self,
        k: usize,
        q: &DVector<f64>,
        r: usize,
        err: &mut DVector<f64>,
        out: &mut DMatrix<f64>,
    ) -> Result<(), IkError> {
        let kind = &self.tasks[k].kind;
        match kind {
            TaskKind::Position { frame, target } => {
                let (frame, target) = (*frame, *target);
                self.write_position(&frame, &target, r, err, out)?;
            }
            TaskKind::Orientation { frame, target } => {
                let (frame, target) = (*frame, *target);
                self.write_orientation(&frame, &target, r, err, out)?;
            }
            TaskKind::Pose { frame, target } => {
                let (frame, target) = (*frame, *target);
                let rot = target.rotation.to_rotation_matrix().into_inner();
                self.write_position(&frame, &target.translation.vector, r, err, out)?;
                self.write_orientation(&frame, &rot, r + 3, err, out)?;
            }
            TaskKind::RelativePosition {
                frame,
                reference,
                target,
            } => {
                let (frame, reference, target) = (*frame, *reference, *target);
                self.write_relative_position(&frame, &reference, &target, r, err, out)?;
            }
            TaskKind::RelativeOrientation {
                frame,
                reference,
                target,
            } => {
                let (frame, reference, target) = (*frame, *reference, *target);
                self.write_relative_orientation(&frame, &reference, &target, r, err, out)?;
            }
            TaskKind::Offset {
                point,
                from,
                axes,
                target,
            } => {
                let (points, axes, target) = ((*point, *from), *axes, *target);
                self.write_offset((&points.0, &points.1), &axes, &target, r, err, out)?;
            }
            TaskKind::Com { target } => {
                put_rows(out, r, &Matrix3::identity(), &self.jc, 0, None, 0);
                err.fixed_rows_mut::<3>(r)
                    .copy_from(&(target - self.cen.com()));
            }
            TaskKind::Posture { joints, target } => {
                unit::write_posture(joints, target, q, r, err, out);
            }
            TaskKind::Joint {
                q_index,
                v_index,
                target,
            } => unit::write_joint((*q_index, *v_index), *target, q, r, err, out),
            TaskKind::AngularMomentum { axes, .. } => {
                let rows = match axes {
                    MomentumAxes::Vertical => 2..3,
                    MomentumAxes::All => 0..3,
                };
                for (i, row) in rows.enumerate() {
                    out.row_mut(r + i).copy_from(&self.jl.row(row));
                    err[r + i] = 0.0;
                }
            }
        }
        Ok(())
    }

    /// Feed-forward velocity and softness of task `k`'s rows from row `r`.
    fn write_velocity(&mut self, k: usize, r: usize) {
        let task = &self.tasks[k];
        let c = task.weight.map_or(0.0, |w| 1.0 / w);
        for i in 0..task.kind.dim() {
            self.soft[r + i] = c;
            self.ff[r + i] = match &task.kind {
                TaskKind::Posture { .. } => 0.0,
                TaskKind::AngularMomentum { axes, target } => {
                    let l = match axes {
                        MomentumAxes::Vertical => target.z,
                        MomentumAxes::All => target[i],
                    };
                    l + task.velocity[i]
                }
                _ => task.velocity[i],
            };
        }
    }
}
