//! Kinematic calibration of absolute joint encoders in a calibration jig (thesis 3.5).
//!
//! (file format documented below once written)

mod encoder;
mod error;
mod file;
mod jig;
mod problem;
mod solve;

pub use encoder::*;
pub use error::CalibrationError;
pub use file::{
    CalibrationFile, ConstraintSpec, FrameSpec, LoadedFile, ModelSpec, PoseEntry, PoseSpec,
};
pub use jig::{
    so3_log, so3_right_jacobian_inv, BodyFrame, ClosureError, Components, JigConstraint,
};
pub use problem::{CalibratedJoint, CalibrationProblem, JigPose};
pub use solve::{
    calibrate, check_observability, Calibration, ConstraintReport, PoseReport, SolveOptions,
};
