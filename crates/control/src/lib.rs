//! Whole-body control of a redundant biped: inverse kinematics, self-collision avoidance,
//! angular momentum and walking (thesis ch. 4, 5, 7).
//!
//! The solvers of [`ik`] work on any task set that implements [`ik::TaskMap`] (task error and
//! Jacobian at `q`): Newton-Raphson and line-search optimisation for a pose
//! ([`ik::PositionIk`]), and resolved motion rate control with a weighted generalized inverse
//! and a null-space term for 1 kHz tracking ([`ik::ClosedLoopIk`], [`ik::Rmrc`]).
//! [`tasks::TaskStack`] stacks generic tasks on any model (frame pose / position / orientation,
//! relative frame, CoM, posture, joint, angular momentum), and [`whole_body::Ik`] runs it on a URDF
//! model by link and joint names with the URDF's joint position and velocity limits kept by
//! default. [`tasks::LolaTasks`] is the walk's task set (Table 4.2: feet and arm CoGs as
//! offsets from the CoG in the planning frame, CoG, upper body, single joints, each
//! switchable), a configuration of a [`tasks::TaskStack`] on any walking robot's frames.
//! [`walk`] puts everything together: a
//! walking pattern ([`pattern`]) tracked by the IK with self-collision avoidance
//! ([`avoidance`]) and one of the thesis's methods for the vertical angular momentum
//! ([`momentum`]), evaluated cycle by cycle ([`walk::run_walk`]), and optionally in the
//! contact simulation of `biped_sim` ([`walk::run_dynamic_walk`]).
//!
//! # Example
//!
//! Lift Lola's right foot by 5 cm relative to its CoG, everything else held, by Newton-Raphson
//! IK; the result is checked with `biped_dynamics`'s kinematics.
//!
//! ```
//! use biped_control::ik::{IkSettings, PositionIk};
//! use biped_control::tasks::{standing_configuration, LolaTasks};
//! use biped_dynamics::{center_of_mass, Data};
//! use biped_robots::lola::{build, LolaType};
//! use nalgebra::{DVector, Vector3};
//!
//! let lola = build(LolaType::Type2)?;
//! let mut tasks = LolaTasks::new(&lola, 0.2)?;
//! let q0 = standing_configuration(&lola);
//! tasks.set_targets_from(&q0)?; // zero task error at q0
//! tasks.targets.foot_position[0] += Vector3::new(0.0, 0.0, 0.05); // [0] = right foot
//!
//! let mut q = q0.clone();
//! let mut ik = PositionIk::new(&tasks, IkSettings::default());
//! let report = ik.newton_raphson(&mut tasks, &mut q)?.require_reached()?;
//! assert!(report.iterations < 10);
//!
//! // sole positions relative to the CoM, before and after
//! let model = &lola.model;
//! let mut data = Data::new(model);
//! let (r_sole, l_sole) = (model.body_id("r_sole").unwrap(), model.body_id("l_sole").unwrap());
//! let mut soles = |q: &DVector<f64>| -> Result<_, Box<dyn std::error::Error>> {
//!     let com = center_of_mass(model, &mut data, q, None)?.position; // also the body poses
//!     Ok((data.world_pos[r_sole] - com, data.world_pos[l_sole] - com))
//! };
//! let ((r0, l0), (r1, l1)) = (soles(&q0)?, soles(&q)?);
//! assert!((r1 - r0 - Vector3::new(0.0, 0.0, 0.05)).norm() < 1e-9);
//! assert!((l1 - l0).norm() < 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! IK on a URDF robot (the Unitree G1 of `biped_dynamics`) with [`whole_body::Ik`] in a few lines:
//! `cargo run --release --example urdf_ik` (in the repository's `examples/`); with a task map
//! of one's own: `cargo run -p biped_control --example g1_ik`.
//!
//! # Modules
//!
//! - [`ik`]: position IK, RMRC, closed-loop and acceleration-level IK, hard joint limits,
//!   joint-limit cost, task blending, orientation errors (on any [`ik::TaskMap`]).
//! - [`whole_body`]: [`whole_body::Ik`], IK on a URDF model by link and joint names with its
//!   limits kept, built from [`tasks`] and [`momentum`].
//! - [`tasks`]: generic tasks on any model ([`tasks::TaskStack`]) and Lola's task description
//!   (Table 4.2) with switchable tasks.
//! - [`avoidance`]: self-collision avoidance from SSV distances (ch. 5).
//! - [`momentum`]: vertical angular momentum compensation and minimisation (ch. 7).
//! - [`pattern`]: walking pattern generation (footsteps, CoM by ZMP preview control, swing
//!   feet).
//! - [`walk`]: the 1 kHz walking IK cycle, its evaluation, and the dynamic walk in simulation.
//! - [`error`]: the error type [`IkError`].

pub mod avoidance;
pub mod error;
pub mod ik;
pub mod momentum;
pub mod pattern;
pub mod tasks;
pub mod walk;
pub mod whole_body;

pub use error::IkError;
pub use ik::Weight;
pub use whole_body::{Ik, IkOptions, StepReport};
