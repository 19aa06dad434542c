//! Parameter checks of the avoidance layer's laws (the laws themselves know no errors).

use super::error::AvoidanceError;
use super::law::RepulsiveLaw;

impl RepulsiveLaw {
    /// Checks the parameters (finite, `m < 0`, `s > 0`, `s0 > 0`, `0 <= t <= 1`).
    pub fn validate(&self) -> Result<(), AvoidanceError> {
        let ok = match *self {
            RepulsiveLaw::Linear { m } => m.is_finite() && m < 0.0,
            RepulsiveLaw::Quadratic { s } => s.is_finite() && s > 0.0,
            RepulsiveLaw::Blended { s0, t } => {
                s0.is_finite() && s0 > 0.0 && (0.0..=1.0).contains(&t)
            }
        };
        if ok {
            Ok(())
        } else {
            Err(AvoidanceError::BadLaw(*self))
        }
    }
}
