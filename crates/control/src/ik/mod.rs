//! Position-based and differential inverse kinematics (thesis 4.2-4.4).
//!
//! - [`position`]: Newton-Raphson (Alg. 4.1) and optimisation with Wolfe line search
//!   (Alg. 4.2), stopping criteria of Table 4.1.
//! - [`rmrc`]: RMRC with W-weighted generalized inverse and null-space term, Klein-Huang
//!   (Alg. 4.3), damped least squares and manipulability (4.22); soft unit rows (posture and
//!   joint tasks) folded into the joint weight instead of stacked.
//! - [`differential`]: closed-loop tracking (4.13)-(4.16), Jacobian transpose (4.17),
//!   resolved acceleration (4.18)-(4.21).
//! - [`joint_cost`]: joint-limit and comfort cost H_J (Fig. 4.2).
//! - [`orientation`]: angle-axis orientation error and Euler Z-X-Z (Appendix C).
//! - [`blend`]: task activation ramps and null-space rate limiting (5.1).
//! - [`limits`] + [`saturation`]: hard joint position and velocity limits kept by saturation
//!   in the null space (SNS) around Algorithm 4.3, for any task map.

pub mod blend;
pub mod differential;
pub mod joint_cost;
pub mod limits;
pub mod linalg;
pub mod line_search;
pub mod orientation;
pub mod position;
pub mod rmrc;
pub mod saturation;
pub mod task_map;
pub mod weight;

pub use blend::{Activation, NullSpaceLimiter};
pub use differential::{
    jacobian_transpose, AccelerationInput, ClosedLoopIk, CycleInput, ResolvedAcceleration,
};
pub use joint_cost::{JointCost, JointCostEntry};
pub use limits::{JointLimits, JointRange, LimitSettings};
pub use position::{IkReport, IkSettings, PositionIk, StopReason};
pub use rmrc::{Rmrc, RmrcProblem};
pub use saturation::{SaturatedRmrc, SaturationReport};
pub use task_map::{TaskBuffers, TaskMap};
pub use weight::Weight;
