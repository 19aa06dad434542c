//! Parameters of the walking pattern generator with defaults fitted to the Lola-like model.

use super::{FootRoll, PatternError};
use serde::{Deserialize, Serialize};

/// Sole rectangle of one foot in its sole frame (x forward, y left), the support region.
///
/// Defaults: the foot box of `crates/robots/data/lola.toml` (0.22 m x 0.12 m, centre 0.02 m in
/// front of the ankle axis, which lies above the sole frame origin) and its toe joint (axis at
/// the front edge, 0.02 m above the sole; toe segment 0.06 m long), see `fit::toe_axis`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct FootGeometry {
    /// Distance from the sole origin to the toe edge, the toe joint axis \[m].
    pub front: f64,
    /// Distance from the sole origin to the heel edge \[m].
    pub back: f64,
    /// Half the foot width \[m].
    pub half_width: f64,
    /// Height of the toe joint axis above the sole plane \[m].
    pub toe_height: f64,
    /// Length of the toe segment ahead of its joint axis (toe-off support) \[m].
    pub toe_length: f64,
}

impl Default for FootGeometry {
    fn default() -> Self {
        Self {
            front: 0.13,
            back: 0.09,
            half_width: 0.06,
            toe_height: 0.02,
            toe_length: 0.06,
        }
    }
}

/// Everything that defines a walk: footsteps, timing, LIPM and preview-control settings.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PatternParams {
    /// Number of steps including the first and the closing step (>= 1).
    pub n_steps: usize,
    /// Forward distance of each footprint ahead of the previous one \[m].
    pub step_length: f64,
    /// Lateral side-step of the leading foot per step pair (> 0: to the left) \[m].
    pub step_sideways: f64,
    /// Yaw change of each footprint relative to the previous one (> 0: turn left) \[rad].
    pub turn_angle: f64,
    /// Nominal lateral distance between the feet (Lola-like hip spacing) \[m].
    pub step_width: f64,
    /// Duration of one step: single support plus double support \[s].
    pub step_time: f64,
    /// Fraction of `step_time` spent in double support, in (0, 1).
    pub ds_ratio: f64,
    /// Peak height of the swing foot above the ground \[m].
    pub step_height: f64,
    /// Constant CoM height above the ground of the linear inverted pendulum \[m].
    pub com_height: f64,
    /// Gravitational acceleration \[m/s^2].
    pub gravity: f64,
    /// Sample (control) period \[s].
    pub dt: f64,
    /// Standing double support before the first step; the ZMP shifts in its second half \[s].
    pub start_time: f64,
    /// Standing double support after the last step \[s].
    pub end_time: f64,
    /// Preview horizon of the ZMP preview controller \[s].
    pub preview_time: f64,
    /// Weight `Q_e` of the ZMP tracking error.
    pub zmp_weight: f64,
    /// Weight `Q_x` of the state increments (may be 0).
    pub state_weight: f64,
    /// Weight `R` of the jerk increments.
    pub input_weight: f64,
    /// Support rectangle of the feet.
    pub foot: FootGeometry,
    /// Toe-off and heel strike (timing and angles).
    pub roll: FootRoll,
    /// Largest distance between consecutive footprints the legs reach \[m] (Lola-like model in
    /// the walking posture: at 0.5 m steps, 0.53 m between the sole origins, the legs are
    /// stretched at touch-down).
    pub reach: f64,
    /// Top speed of the swing foot \[m/s] (sets the shortest single support, [`super::reach`]).
    pub max_swing_speed: f64,
}

/// Standing CoM height of the Lola-like model with 0.4 rad knee bend (`fit::standing_com_height` = 0.9603 m) \[m].
pub const LOLA_COM_HEIGHT: f64 = 0.96;

/// Lateral hip joint spacing of the Lola-like model (2 x 0.09 m in `lola.toml`) \[m].
pub const LOLA_STEP_WIDTH: f64 = 0.18;

impl Default for PatternParams {
    fn default() -> Self {
        Self {
            n_steps: 10,
            step_length: 0.4,
            step_sideways: 0.0,
            turn_angle: 0.0,
            step_width: LOLA_STEP_WIDTH,
            step_time: 0.8,
            ds_ratio: 0.2,
            step_height: 0.05,
            com_height: LOLA_COM_HEIGHT,
            gravity: 9.81,
            dt: 1e-3,
            start_time: 1.0,
            end_time: 1.5,
            preview_time: 1.6,
            zmp_weight: 1.0,
            state_weight: 0.0,
            input_weight: 1e-6,
            foot: FootGeometry::default(),
            roll: FootRoll::default(),
            reach: 0.55,
            max_swing_speed: 4.0,
        }
    }
}

/// Checks `lo <= value <= hi` (and finiteness).
fn range(
    name: &'static str,
    value: f64,
    lo: f64,
    hi: f64,
    reason: &'static str,
) -> Result<(), PatternError> {
    if value.is_finite() && value >= lo && value <= hi {
        Ok(())
    } else {
        Err(PatternError::InvalidParameter {
            name,
            value,
            reason,
        })
    }
}

impl PatternParams {
    /// Single-support duration `(1 - ds_ratio) step_time` \[s].
    pub fn ss_time(&self) -> f64 {
        (1.0 - self.ds_ratio) * self.step_time
    }

    /// Double-support duration `ds_ratio step_time` \[s].
    pub fn ds_time(&self) -> f64 {
        self.ds_ratio * self.step_time
    }

    /// Total duration of the walk \[s].
    pub fn duration(&self) -> f64 {
        self.start_time + self.n_steps as f64 * self.step_time + self.end_time
    }

    /// Rejects non-finite, non-positive or absurd values, then steps beyond the legs' reach
    /// and step times too short for the swing ([`super::reach`]), with typed errors.
    pub fn validate(&self) -> Result<(), PatternError> {
        for (name, value, lo, hi, reason) in self.ranges() {
            range(name, value, lo, hi, reason)?;
        }
        self.roll.validate()?;
        range("reach", self.reach, 0.05, 5.0, "0.05 to 5 m")?;
        let swing = self.max_swing_speed;
        range("max_swing_speed", swing, 0.1, 50.0, "0.1 to 50 m/s")?;
        let (min_phase, big) = (2.0 * self.dt, f64::MAX);
        let ds = "double support shorter than 2 dt";
        range("ds_ratio", self.ds_time(), min_phase, big, ds)?;
        let ss = "single support shorter than 2 dt";
        range("ds_ratio", self.ss_time(), min_phase, big, ss)?;
        let samples = self.duration() / self.dt;
        range("dt", samples, 1.0, 1e7, "more than 1e7 samples")?;
        let preview = self.preview_time / self.dt;
        range(
            "preview_time",
            preview,
            1.0,
            1e5,
            "more than 1e5 preview samples",
        )?;
        super::reach::check(self)
    }

    /// The plain range checks of [`Self::validate`]: `(name, value, lo, hi, reason)`.
    fn ranges(&self) -> [(&'static str, f64, f64, f64, &'static str); 22] {
        [
            (
                "n_steps",
                self.n_steps as f64,
                1.0,
                1000.0,
                "1 to 1000 steps",
            ),
            (
                "step_length",
                self.step_length,
                -1.0,
                1.0,
                "|step_length| <= 1 m",
            ),
            (
                "step_sideways",
                self.step_sideways,
                -0.5,
                0.5,
                "|step_sideways| <= 0.5 m",
            ),
            (
                "turn_angle",
                self.turn_angle,
                -0.6,
                0.6,
                "|turn_angle| <= 0.6 rad",
            ),
            ("step_width", self.step_width, 0.0, 1.0, "0 to 1 m"),
            ("step_time", self.step_time, 0.2, 10.0, "0.2 to 10 s"),
            ("ds_ratio", self.ds_ratio, 0.01, 0.9, "0.01 to 0.9"),
            ("step_height", self.step_height, 0.0, 0.5, "0 to 0.5 m"),
            ("com_height", self.com_height, 0.1, 3.0, "0.1 to 3 m"),
            ("gravity", self.gravity, 0.1, 100.0, "0.1 to 100 m/s^2"),
            ("dt", self.dt, 1e-5, 0.05, "1e-5 to 0.05 s"),
            ("start_time", self.start_time, 0.0, 60.0, "0 to 60 s"),
            ("end_time", self.end_time, 0.0, 60.0, "0 to 60 s"),
            ("preview_time", self.preview_time, 0.1, 10.0, "0.1 to 10 s"),
            ("zmp_weight", self.zmp_weight, 1e-12, 1e12, "positive"),
            ("state_weight", self.state_weight, 0.0, 1e12, "non-negative"),
            ("input_weight", self.input_weight, 1e-15, 1e12, "positive"),
            ("foot.front", self.foot.front, 0.0, 1.0, "0 to 1 m"),
            ("foot.back", self.foot.back, 0.0, 1.0, "0 to 1 m"),
            (
                "foot.half_width",
                self.foot.half_width,
                0.0,
                0.5,
                "0 to 0.5 m",
            ),
            (
                "foot.toe_height",
                self.foot.toe_height,
                0.0,
                0.2,
                "0 to 0.2 m",
            ),
            (
                "foot.toe_length",
                self.foot.toe_length,
                0.0,
                0.5,
                "0 to 0.5 m",
            ),
        ]
    }
}
