//! Physical ranges of the calibration inputs and the repeated-name check. A value outside its
//! range is a unit or typing mistake (millimetres for metres, degrees for radians, a stray
//! exponent such as 1e300) and is reported before solving, never carried into offsets.

use biped_dynamics::{JointModel, Model};
use std::collections::HashMap;
use std::f64::consts::TAU;

/// The accepted magnitudes of one kind of input.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// Smallest accepted value.
    pub min: f64,
    /// Largest accepted value.
    pub max: f64,
    /// Unit, for messages.
    pub unit: &'static str,
}

/// Lengths \[m]: jig targets, frame offsets and prismatic encoder readings, within 10 m
/// (larger than any jig; a length in millimetres is caught).
pub const LENGTH: Range = Range {
    min: -10.0,
    max: 10.0,
    unit: "m",
};

/// Angles \[rad]: roll/pitch/yaw and revolute encoder readings, within one turn each way
/// (a reading `q_true - offset` of a joint angle and a mounting offset, both in
/// `[-pi, pi]`; an angle in degrees is caught unless below 6.3).
pub const ANGLE: Range = Range {
    min: -TAU,
    max: TAU,
    unit: "rad",
};

/// Weights \[1/m or 1/rad]: non-negative, at most 1e9 (the inverse of a 1 nm or 1 nrad
/// standard deviation).
pub const WEIGHT: Range = Range {
    min: 0.0,
    max: 1e9,
    unit: "",
};

impl Range {
    /// `Err(message)` unless `x` is finite and within the range.
    pub fn check(&self, x: f64) -> Result<(), String> {
        if x.is_finite() && (self.min..=self.max).contains(&x) {
            return Ok(());
        }
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        Err(format!(
            "{}{unit} is outside the physical range [{}, {}]{unit}",
            show(x),
            show(self.min),
            show(self.max)
        ))
    }
}

/// A number for messages: exponent form when very large or small (`1e300`, not 301 digits).
fn show(x: f64) -> String {
    if x != 0.0 && !(1e-4..1e6).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{}", (x * 1e6).round() / 1e6)
    }
}

/// The range of an encoder reading of joint `name`: [`LENGTH`] for a prismatic joint, else
/// [`ANGLE`].
pub(crate) fn reading(model: &Model, name: &str) -> Range {
    let prismatic = model
        .bodies()
        .iter()
        .any(|b| b.joint_name() == name && matches!(b.joint(), JointModel::Prismatic { .. }));
    if prismatic {
        LENGTH
    } else {
        ANGLE
    }
}

/// The first name that repeats an earlier one: `(earlier index, repeating index)`.
pub(crate) fn first_repeat<'a>(names: impl IntoIterator<Item = &'a str>) -> Option<(usize, usize)> {
    let mut seen = HashMap::new();
    for (i, name) in names.into_iter().enumerate() {
        if let Some(&first) = seen.get(name) {
            return Some((first, i));
        }
        seen.insert(name, i);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_accept_their_bounds_and_reject_beyond() {
        for r in [LENGTH, ANGLE, WEIGHT] {
            assert!(r.check(r.min).is_ok() && r.check(r.max).is_ok());
            for bad in [r.max * 1.001, r.min - 1e-3, f64::NAN, f64::INFINITY, 1e300] {
                assert!(r.check(bad).is_err(), "{bad} in {r:?}");
            }
        }
        let msg = LENGTH.check(1e300).unwrap_err();
        assert_eq!(msg, "1e300 m is outside the physical range [-10, 10] m");
        assert!(ANGLE
            .check(90.0)
            .unwrap_err()
            .contains("[-6.283185, 6.283185] rad"));
    }

    #[test]
    fn first_repeat_finds_the_repetition() {
        assert_eq!(first_repeat(["a", "b", "c", "b", "a"]), Some((1, 3)));
        assert_eq!(first_repeat(["a", "b"]), None);
    }
}
