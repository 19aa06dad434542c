//! Whether the legs can walk the footsteps of a parameter set: the distance between
//! consecutive footprints within the legs' reach, and a single support long enough for the
//! swing foot's travel at its top speed (checked up front by `PatternParams::validate`).
//!
//! The swing foot covers up to twice the step (from behind the stance foot to ahead of it)
//! with the minimum-jerk blend, whose peak speed is `15/8 travel / ss_time`; with the top
//! speed `max_swing_speed` the single support must last at least `15/8 travel /
//! max_swing_speed`, so the step time at least that over `1 - ds_ratio`.

use super::{PatternError, PatternParams};

/// Peak of the minimum-jerk blend's rate, `max ds/dtau = 15/8`.
const MIN_JERK_PEAK_RATE: f64 = 1.875;

/// Largest `|step_length|` the legs reach with the lateral offset of `p` \[m].
pub fn max_step_length(p: &PatternParams) -> f64 {
    let lateral = p.step_width + p.step_sideways.abs();
    (p.reach * p.reach - lateral * lateral).max(0.0).sqrt()
}

/// Shortest step time for the swing of `p`'s steps at `max_swing_speed` \[s].
pub fn min_step_time(p: &PatternParams) -> f64 {
    let forward = 2.0 * p.step_length.abs();
    let side = p.step_sideways.abs();
    let travel = forward.hypot(side);
    MIN_JERK_PEAK_RATE * travel / p.max_swing_speed / (1.0 - p.ds_ratio)
}

/// Rejects steps beyond the legs' reach and step times too short for the swing, with the
/// valid range in the error.
pub(crate) fn check(p: &PatternParams) -> Result<(), PatternError> {
    let max = max_step_length(p);
    if p.step_length.abs() > max {
        return Err(PatternError::OutOfRange {
            name: "step_length",
            value: p.step_length,
            min: -max,
            max,
            why: "the distance between consecutive footprints exceeds the legs' reach",
        });
    }
    let min = min_step_time(p);
    if p.step_time < min {
        return Err(PatternError::OutOfRange {
            name: "step_time",
            value: p.step_time,
            min,
            max: 10.0,
            why: "the single support is too short for the swing at max_swing_speed",
        });
    }
    Ok(())
}
