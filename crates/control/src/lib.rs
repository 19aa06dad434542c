//! Whole-body control of a redundant biped (thesis ch. 4, 5, 7).
//!
//! - [`ik`]: position-based and differential inverse kinematics (4.2-4.4).
//! - [`tasks`]: Lola's task-space description (Table 4.2) with switchable tasks.
//! - [`avoidance`]: self-collision avoidance from SSV distances (ch. 5).
//! - [`momentum`]: vertical angular momentum compensation and minimisation (ch. 7).
//! - [`pattern`]: walking pattern generation (CoM, feet and upper body trajectories).

pub mod avoidance;
pub mod error;
pub mod ik;
pub mod momentum;
pub mod pattern;
pub mod tasks;
pub mod walk;

pub use error::IkError;
pub use ik::Weight;
