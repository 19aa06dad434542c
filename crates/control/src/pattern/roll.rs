//! Heel-to-toe roll-over of the feet: toe-off at the end of double support and heel strike at
//! its start, as in the walking control of Lola that the thesis builds on (4.5, 7.3).
//!
//! - Toe-off: in the double support before a lift-off the rear foot rotates about its toe
//!   joint axis (heel up, pitch `0 -> theta_off`) while the toe segment stays flat on the
//!   ground; the toe joint angle is `-pitch`. The heel lifts once the ZMP reference has
//!   passed the rear toe axis (before, the rear foot's flat sole carries it), at the latest
//!   in the last `toe_off_fraction` of the double support.
//! - Heel strike: the swing foot touches down on its heel edge with the toes up (pitch
//!   `-theta_hs`) and rolls flat about the heel edge, flat before the ZMP reference passes
//!   the heel edge, at the latest after `heel_roll_fraction` of the double support. So the
//!   ZMP reference stays inside the support of the rolling feet (rear foot flat or on its
//!   toe, front foot on its heel edge or flat).
//! - Swing: the foot keeps its lift-off pitch (toes down, toe segment parallel to the
//!   ground) for the first `swing_hold` of the swing, which keeps the swing ankle out of its
//!   dorsiflexion limit while the knee folds, then turns to the touch-down pitch.
//! - Both angles scale with the reach of the leg at the contact switch: `theta = angle * d /
//!   full_distance`, capped at `angle * max_scale`, with `d` the fore-aft distance (in the
//!   foot's frame) of the CoM ahead of the lifting foot at lift-off, resp. of the landing
//!   foot ahead of the CoM at touch-down ([`super::RollPlan`]). Short steps roll little,
//!   side steps and steps in place not at all, the first step (lifting beside the CoM) has
//!   no toe-off, the closing step (landing under the CoM) no heel strike, and the first
//!   and the stopping steps, which land further ahead of the CoM, strike more.
//! - Pitch profiles are minimum-jerk blends with zero rate at every contact switch.

use super::blend::min_jerk;
pub use super::blend::min_jerk_inverse;
use super::PatternError;
use serde::{Deserialize, Serialize};

/// Contact state of a foot.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Contact {
    /// Sole flat on the ground.
    Flat,
    /// Heel edge on the ground, toes up (heel strike, rolling flat).
    Heel,
    /// Toe segment flat on the ground, heel lifted (toe-off).
    Toe,
    /// In the air.
    Swing,
}

/// Toe-off and heel-strike parameters (defaults for the Lola-like model, see module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct FootRoll {
    /// Heel-lift angle at lift-off with the CoM `full_distance` ahead of the foot \[rad].
    pub toe_off_angle: f64,
    /// Longest fraction of the double support (at its end) in which the heel lifts, in
    /// \[0, 1] (it starts later when the ZMP reference passes the toe axis later).
    pub toe_off_fraction: f64,
    /// Toe-up angle at touch-down for a foot landing `full_distance` ahead of the CoM \[rad].
    pub heel_strike_angle: f64,
    /// Longest fraction of the double support (at its start) in which the foot rolls flat, in
    /// \[0, 1] (shorter when the ZMP reference reaches the heel edge earlier).
    pub heel_roll_fraction: f64,
    /// Fore-aft CoM-to-foot distance at which the angles take their nominal value \[m].
    pub full_distance: f64,
    /// Cap of the distance scaling (`theta <= angle * max_scale`).
    pub max_scale: f64,
    /// Fraction of the swing (at its start) in which the foot keeps its lift-off pitch, in
    /// \[0, 0.9].
    pub swing_hold: f64,
}

impl Default for FootRoll {
    fn default() -> Self {
        Self {
            toe_off_angle: 0.35,
            toe_off_fraction: 1.0,
            heel_strike_angle: 0.35,
            heel_roll_fraction: 0.9,
            full_distance: 0.25,
            max_scale: 1.25,
            swing_hold: 0.3,
        }
    }
}

impl FootRoll {
    /// No roll-over: feet stay flat on the ground (the flat-footed pattern).
    pub fn flat() -> Self {
        Self {
            toe_off_angle: 0.0,
            heel_strike_angle: 0.0,
            ..Self::default()
        }
    }

    /// Heel-lift angle at lift-off of a foot `behind` metres behind the CoM \[rad].
    pub fn toe_off(&self, behind: f64) -> f64 {
        self.toe_off_angle * self.scale(behind)
    }

    /// Toe-up angle at touch-down of a foot landing `ahead` metres ahead of the CoM \[rad].
    pub fn heel_strike(&self, ahead: f64) -> f64 {
        self.heel_strike_angle * self.scale(ahead)
    }

    /// Largest heel-lift angle any step can ask for \[rad].
    pub fn max_toe_off(&self) -> f64 {
        self.toe_off_angle * self.max_scale
    }

    fn scale(&self, d: f64) -> f64 {
        (d / self.full_distance).clamp(0.0, self.max_scale)
    }

    /// Checks ranges; `name` errors carry the field path.
    pub fn validate(&self) -> Result<(), PatternError> {
        let checks: [(&'static str, f64, f64, f64, &'static str); 7] = [
            (
                "roll.toe_off_angle",
                self.toe_off_angle,
                0.0,
                0.8,
                "0 to 0.8 rad",
            ),
            (
                "roll.toe_off_fraction",
                self.toe_off_fraction,
                0.0,
                1.0,
                "0 to 1",
            ),
            (
                "roll.heel_strike_angle",
                self.heel_strike_angle,
                0.0,
                0.5,
                "0 to 0.5 rad",
            ),
            (
                "roll.heel_roll_fraction",
                self.heel_roll_fraction,
                0.0,
                1.0,
                "0 to 1",
            ),
            (
                "roll.full_distance",
                self.full_distance,
                0.01,
                2.0,
                "0.01 to 2 m",
            ),
            ("roll.max_scale", self.max_scale, 0.0, 4.0, "0 to 4"),
            ("roll.swing_hold", self.swing_hold, 0.0, 0.9, "0 to 0.9"),
        ];
        for (name, value, lo, hi, reason) in checks {
            if !(value.is_finite() && value >= lo && value <= hi) {
                return Err(PatternError::InvalidParameter {
                    name,
                    value,
                    reason,
                });
            }
        }
        Ok(())
    }
}

/// Pitch and pitch rate `[p, dp/dt]` of a minimum-jerk blend from `from` to `to` over the
/// window `[start, start + width]` of the double support (`tau`, `width` as fractions of
/// `ds_time`); constant outside the window.
pub fn window_blend(
    from: f64,
    to: f64,
    tau: f64,
    start: f64,
    width: f64,
    ds_time: f64,
) -> [f64; 2] {
    if width <= 0.0 {
        return if tau < start { [from, 0.0] } else { [to, 0.0] };
    }
    let u = (tau - start) / width;
    let [s, ds, _] = min_jerk(u);
    let rate = if (0.0..=1.0).contains(&u) {
        ds / (width * ds_time)
    } else {
        0.0
    };
    [from + s * (to - from), rate * (to - from)]
}
