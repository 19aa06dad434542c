//! Walking pattern generation: footsteps, CoM (LIPM, ZMP preview), feet and upper body.
//!
//! The thesis uses the walking pattern of Lola's real-time generator as the input of its
//! inverse kinematics (4.5, 7.3) without specifying it; this module provides a standard one
//! so the IK, collision avoidance and momentum tracking can be exercised on whole walks:
//!
//! - [`footsteps`]: footstep planner (straight, sideways, turning; half first and last steps).
//! - [`timeline`]: step timing, support phases and the C2 ZMP reference.
//! - [`preview`] + [`dare`]: cart-table ZMP preview servo (Katayama-type LQ servo with
//!   integral action), gains from the DARE solved by doubling.
//! - [`swing`]: minimum-jerk swing-foot trajectories with a C2 lift profile.
//! - [`generate`]: [`WalkingPattern`], sampled at the control period.
//! - [`fit`]: defaults fitted to the Lola-like model (CoM height, hip spacing).
//!
//! Conventions: world frame with the ground at `z = 0`, x forward and the feet initially at
//! `y = +-step_width / 2`; foot poses are the sole frames (`l_sole`, `r_sole` of the model).

pub mod dare;
mod error;
pub mod fit;
pub mod footsteps;
pub mod generate;
mod params;
pub mod preview;
pub mod swing;
pub mod timeline;

pub use error::PatternError;
pub use footsteps::{Foot, Footstep, FootstepPlan, Pose2};
pub use generate::{FootState, PatternSample, WalkingPattern};
pub use params::{FootGeometry, PatternParams, LOLA_COM_HEIGHT, LOLA_STEP_WIDTH};
pub use timeline::Phase;
