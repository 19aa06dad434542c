//! Task-space descriptions (thesis 4.5): generic tasks on any model, and Lola's task set
//! (Table 4.2) with switchable, blended tasks (5.1).
//!
//! [`TaskStack`] stacks generic [`Task`]s (frame pose / position / orientation, relative
//! frame, offset of a frame, the CoM or a subtree's CoM from another such point, CoM,
//! posture, joint, angular momentum; see [`task`]) on any
//! [`biped_dynamics::Model`] and implements [`crate::ik::TaskMap`]; [`crate::whole_body::Ik`] builds
//! one from URDF names with the joint limits on.
//!
//! [`LolaTasks`] is one configuration of a [`TaskStack`]: it stacks the active tasks of
//! [`TaskId`] (Table 4.2 plus joint tasks for the
//! head pan/tilt and camera vergence, so that all tasks together are non-redundant:
//! 31 rows for 31 DoF) and implements [`crate::ik::TaskMap`]. Targets are a
//! [`LolaTargets`] struct. The bodies and joints it acts on are a [`WalkTaskFrames`]: Lola's,
//! or any robot's (sole frames with an offset on a foot body, no toes, up to five held trunk
//! and head joints in the joint slots, unused slots off), which is how `biped walk --robot`
//! walks a described robot with the same task set.

mod frames;
mod lola;
mod pose;
mod retract;
mod rows;
mod se3;
mod stack;
mod targets;
pub mod task;

pub use frames::WalkTaskFrames;
pub use lola::LolaTasks;
pub use pose::{lola_joint_cost, standing_configuration};
pub use stack::{TaskHandle, TaskStack};
pub use targets::{FootFrame, LolaTargets, TaskId};
pub use task::{Frame, MomentumAxes, Point, Task, TaskKind};
