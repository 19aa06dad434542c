//! Joint angle <-> motor encoder conversions for the start-up initialisation of the
//! incremental motor encoders from absolute joint angles (thesis 3.5, footnote 5): closed-form
//! forward transmission, Newton-Raphson inverse for the nonlinear knee and ankle drives.

use super::CalibrationError;
use biped_dynamics::mechanism::ankle::AnkleDrive;
use biped_dynamics::mechanism::knee::KneeDrive;
use std::f64::consts::TAU;

/// An incremental motor encoder: counts per motor revolution (after quadrature decoding).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IncrementalEncoder {
    /// Counts per motor revolution.
    pub counts_per_rev: f64,
}

impl IncrementalEncoder {
    /// Validates a positive, finite resolution.
    pub fn new(counts_per_rev: f64) -> Result<Self, CalibrationError> {
        if counts_per_rev.is_finite() && counts_per_rev > 0.0 {
            Ok(Self { counts_per_rev })
        } else {
            Err(CalibrationError::Invalid(format!(
                "encoder resolution {counts_per_rev} must be positive and finite"
            )))
        }
    }

    /// Motor angle \[rad] -> counts, rounded to the nearest count.
    pub fn counts(&self, motor_angle: f64) -> Result<i64, CalibrationError> {
        let c = (motor_angle / TAU * self.counts_per_rev).round();
        if c.is_finite() && c.abs() < 9.0e15 {
            Ok(c as i64)
        } else {
            Err(CalibrationError::NonFinite("motor angle".into()))
        }
    }

    /// Counts -> motor angle \[rad].
    pub fn angle(&self, counts: i64) -> f64 {
        counts as f64 * TAU / self.counts_per_rev
    }

    /// Motor angle quantisation step \[rad].
    pub fn resolution(&self) -> f64 {
        TAU / self.counts_per_rev
    }
}

/// Knee angle -> motor encoder counts through the roller-screw drive (3.3)-(3.4).
pub fn knee_counts(
    drive: &KneeDrive,
    encoder: &IncrementalEncoder,
    knee_angle: f64,
) -> Result<i64, CalibrationError> {
    encoder.counts(drive.motor_angle(knee_angle)?)
}

/// Motor encoder counts -> knee angle by Newton-Raphson on (3.3) (footnote 5).
pub fn knee_angle_from_counts(
    drive: &KneeDrive,
    encoder: &IncrementalEncoder,
    counts: i64,
) -> Result<f64, CalibrationError> {
    Ok(drive.knee_angle(encoder.angle(counts))?)
}

/// Ankle angles `[flexion, adduction]` -> the two motor encoder counts (3.22)-(3.29).
pub fn ankle_counts(
    drive: &AnkleDrive,
    encoder: &IncrementalEncoder,
    ankle_angles: [f64; 2],
) -> Result<[i64; 2], CalibrationError> {
    let m = drive.transmission(ankle_angles, [0.0; 2])?.motor_angles;
    Ok([encoder.counts(m.x)?, encoder.counts(m.y)?])
}

/// Two motor encoder counts -> ankle angles by 2x2 Newton-Raphson (footnote 5).
pub fn ankle_angles_from_counts(
    drive: &AnkleDrive,
    encoder: &IncrementalEncoder,
    counts: [i64; 2],
    guess: Option<[f64; 2]>,
) -> Result<[f64; 2], CalibrationError> {
    let m = [encoder.angle(counts[0]), encoder.angle(counts[1])];
    Ok(drive.ankle_angles(m, guess)?)
}
