//! Lola's task-space description (thesis 4.5, Table 4.2) with switchable, blended tasks (5.1).
//!
//! [`LolaTasks`] stacks the active tasks of [`TaskId`] (Table 4.2 plus joint tasks for the
//! head pan/tilt and camera vergence, so that all tasks together are non-redundant:
//! 31 rows for 31 DoF) and implements [`crate::ik::TaskMap`]. Targets are a
//! [`LolaTargets`] struct.

mod lola;
mod pose;
mod se3;
mod targets;

pub use lola::LolaTasks;
pub use pose::{lola_joint_cost, standing_configuration};
pub use targets::{FootFrame, LolaTargets, TaskId};
