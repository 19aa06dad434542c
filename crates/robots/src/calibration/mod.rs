//! Kinematic calibration of absolute joint encoders in a calibration jig (thesis 3.5).
//!
//! Closed-loop calibration: the robot is clamped into jig poses in which the relative pose of
//! chosen frames is known (pelvis and both feet in Lola's jig, Fig. 3.5-3.6). The absolute
//! encoders, mounted in an arbitrary angular position, read `q_meas = q_true - offset`; the
//! unknown offsets of the chosen joints minimise the weighted jig-closure residual
//! `sum_poses |r(q_meas + offset)|^2` ([`calibrate`], Levenberg-Marquardt with the analytic
//! Jacobian of [`JigConstraint::residual`]). The residual of a constraint is the position of
//! frame `b` in frame `a` minus the target (frame-`a` axes) and the rotation vector
//! `log(R_target^T R_a^T R_b)` (angle-axis, Appendix C), scaled by the weights. Before solving,
//! the rank of the column-scaled stacked Jacobian is checked ([`check_observability`]): joints in
//! an unobservable direction are reported as [`CalibrationError::Unobservable`]. The per-pose
//! report ([`PoseReport`]) shows what the offsets could not absorb: with a correct model only
//! noise remains, a geometric error (e.g. a link length) leaves a clearly larger residual.
//! The solver works with the weights divided by the largest one (the same minimiser; weights of
//! any magnitude neither overflow nor look unobservable), and a result with an infinite or NaN
//! number is [`CalibrationError::NonFiniteResult`], never a report.
//!
//! [`knee_counts`], [`ankle_counts`] and their inverses convert joint angles to motor encoder
//! counts for the nonlinear knee and ankle drives (footnote 5: Newton-Raphson inverse).
//!
//! # File format (JSON)
//!
//! - `model`: `urdf` path (relative to the file) and `floating` (default `false`).
//! - `joints`: the one-DoF joints whose offsets are estimated (`q_true = q_meas + offset`).
//! - `constraints`: `name`; `frame_a`, `frame_b` = `link` (URDF link) with optional offset
//!   `xyz` \[m] / `rpy` \[rad] in the link frame; `components` = `"pose"` (default) or
//!   `"position"`; `position_weight` \[1/m] and `orientation_weight` \[1/rad] (default 1).
//! - `poses`: `name`; `encoders` = joint name -> encoder reading (unlisted joints are at the
//!   neutral value); `targets` = constraint name -> pose of `frame_b` in `frame_a`
//!   (`xyz`, `rpy` with `R = Rz(yaw) Ry(pitch) Rx(roll)` as in URDF). Only the constraints named
//!   in `targets` are active in that pose (feet bolted to different jig positions per pose).
//! - `reference_offsets` (optional): known offsets of synthetic data, compared by the CLI.
//!
//! Unknown keys, repeated keys (`encoders`, `targets`, `reference_offsets`) and repeated names
//! (`joints`, constraint and pose names) are errors, and so are numbers outside their physical
//! ranges ([`limits`]): lengths within 10 m, angles (`rpy`, revolute encoder readings) within
//! 2 pi rad, weights in `[0, 1e9]`. A leading byte-order mark is skipped. Every error names
//! the file, line and field. A complete file
//! (`crates/robots/data/calibration_example.json` is a 3-pose G1 example):
//!
//! ```
//! let text = r#"{
//!   "model": { "urdf": "g1_29dof_rev_1_0.urdf", "floating": false },
//!   "joints": ["left_knee_joint", "left_hip_pitch_joint"],
//!   "constraints": [
//!     { "name": "left_foot",
//!       "frame_a": { "link": "pelvis" },
//!       "frame_b": { "link": "left_ankle_roll_link", "xyz": [0.0, 0.0, -0.03] },
//!       "components": "pose", "position_weight": 10.0, "orientation_weight": 1.0 }
//!   ],
//!   "poses": [
//!     { "name": "pose 1",
//!       "encoders": { "left_knee_joint": 0.61, "left_hip_pitch_joint": -0.32 },
//!       "targets": { "left_foot": { "xyz": [0.02, 0.12, -0.62], "rpy": [0.0, 0.05, 0.0] } } }
//!   ],
//!   "reference_offsets": { "left_knee_joint": 0.01 }
//! }"#;
//! let file = biped_robots::calibration::LoadedFile::parse("example.json", text.into()).unwrap();
//! assert_eq!(file.spec.joints.len(), 2);
//! assert_eq!(file.spec.poses[0].targets["left_foot"].xyz[2], -0.62);
//! ```

mod encoder;
mod error;
mod file;
mod jig;
pub mod limits;
mod locate;
mod problem;
mod report;
mod solve;
mod spec;
mod validate;

pub use encoder::*;
pub use error::CalibrationError;
pub use file::LoadedFile;
pub use jig::{
    so3_log, so3_right_jacobian_inv, BodyFrame, ClosureError, Components, JigConstraint,
};
pub use problem::{CalibratedJoint, CalibrationProblem, JigPose};
pub use report::{ConstraintReport, PoseReport};
pub use solve::{calibrate, check_observability, Calibration, SolveOptions};
pub use spec::{CalibrationFile, ConstraintSpec, FrameSpec, ModelSpec, PoseEntry, PoseSpec};
