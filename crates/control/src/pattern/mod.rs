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
//! - [`reach`]: steps within the legs' reach and step times long enough for the swing.
//! - [`roll`]: toe-off and heel strike (heel lift about the toe joint axis at the end of
//!   double support, heel-first landing rolling flat at its start).
//! - [`generate`]: [`WalkingPattern`], sampled at the control period.
//! - [`fit`]: defaults fitted to the Lola-like model (CoM height, hip spacing).
//!
//! Choices where the brief/thesis leave freedom (documented in the sub-modules):
//! - `step_length` is the distance of each footprint ahead of the previous one (the first
//!   and last steps are half steps); `step_sideways` is the side step of the leading foot,
//!   the trailing foot closes to the nominal width (so the feet never come closer than
//!   `step_width`); overlapping foot rectangles are rejected.
//! - The ZMP reference point of a foot is its sole origin (below the ankle axis); transfers
//!   in double support use the minimum-jerk blend.
//! - The CoM runs at the sample period `dt` (1 ms): at such short periods the doubling
//!   iteration alone leaves DARE residuals ~1e-5, so its result is polished by
//!   Newton-Kleinman steps (residual ~1e-18) and accepted only if stabilising.
//! - The default CoM height is the Lola-like model's CoM above the soles at 0.4 rad knee
//!   bend (0.960 m, [`fit::standing_com_height`]); the default step width is its hip spacing.
//!
//! Conventions: world frame with the ground at `z = 0`, x forward and the feet initially at
//! `y = +-step_width / 2`; foot poses are the sole frames (`l_sole`, `r_sole` of the model).

mod blend;
pub mod dare;
mod error;
mod feet;
pub mod fit;
pub mod footsteps;
pub mod generate;
mod params;
pub mod preview;
pub mod reach;
pub mod roll;
pub mod swing;
pub mod timeline;

pub use error::PatternError;
pub use feet::RollPlan;
pub use footsteps::{Foot, Footstep, FootstepPlan, Pose2};
pub use generate::{FootState, PatternSample, WalkingPattern};
pub use params::{FootGeometry, PatternParams, LOLA_COM_HEIGHT, LOLA_STEP_WIDTH};
pub use roll::{Contact, FootRoll};
pub use timeline::Phase;
