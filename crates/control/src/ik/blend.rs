//! Smooth task switching (thesis 5.1): activation ramps for blending tasks in and out and a
//! rate limit on the null-space input, so that joint velocities do not jump when the task
//! set changes.
//!
//! Switching a task row off abruptly changes `J` and hence `qd` (5.1, "velocity jumps on the
//! joint level"). Instead each task has an activation `a` in [0, 1] that ramps towards its
//! target with rate `1/T`; its rows get the softness (see [`crate::ik::rmrc`])
//! `c = C_HARD (C_OFF / C_HARD)^(1 - w)` with the smoothstep weight `w = 3a^2 - 2a^3`: `w = 1`
//! is a hard task (c = 0), `w -> 0` drops the row (rows with `w = 0` are removed). The
//! log-linear sweep over 16 decades matters: a row's influence changes only while `c` is
//! within about a decade of its effective stiffness (a Schur complement of `J W^-1 J^T`,
//! unknown in advance and unit dependent), so a linear law `c ~ 1/w - 1` would concentrate
//! the whole transition in a few samples; the log sweep spreads it over the ramp. The jumps
//! at the ends (c = 0 -> C_HARD, C_OFF -> removed) are of relative size 1e-8. GIENGER et al. limit the jerk of the
//! null-space motion by scaling the null-space velocity; we bound the rate of change of the
//! null-space input vector `alpha_N grad_H` by scaling its increment
//! ([`NullSpaceLimiter`]), so a jump in the cost gradient becomes a ramp.

use crate::error::IkError;
use nalgebra::DVector;

/// Softness of a row at the start of blending out (practically hard).
pub const C_HARD: f64 = 1e-8;
/// Softness of a row just before it is removed (practically absent).
pub const C_OFF: f64 = 1e8;

/// Activation ramp of one task (5.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Activation {
    /// Current activation in [0, 1].
    pub level: f64,
    /// Target activation (0 = off, 1 = on).
    pub target: f64,
    /// Ramp duration T \[s] from 0 to 1 (0 = switch immediately).
    pub ramp_time: f64,
}

impl Activation {
    /// Fully on (`on = true`) or off, with ramp duration `ramp_time`.
    pub fn new(on: bool, ramp_time: f64) -> Self {
        let level = if on { 1.0 } else { 0.0 };
        Self {
            level,
            target: level,
            ramp_time: ramp_time.max(0.0),
        }
    }

    /// Requests switching on or off (ramped by [`Self::advance`]).
    pub fn switch(&mut self, on: bool) {
        self.target = if on { 1.0 } else { 0.0 };
    }

    /// Advances the ramp by `dt`.
    pub fn advance(&mut self, dt: f64) {
        let step = if self.ramp_time > 0.0 {
            dt.max(0.0) / self.ramp_time
        } else {
            1.0
        };
        let d = self.target - self.level;
        self.level += d.clamp(-step, step);
    }

    /// Smoothstep weight `w = 3a^2 - 2a^3`.
    pub fn weight(&self) -> f64 {
        let a = self.level.clamp(0.0, 1.0);
        a * a * (3.0 - 2.0 * a)
    }

    /// True if the rows take part (weight > 0).
    pub fn is_active(&self) -> bool {
        self.weight() > 0.0
    }

    /// Row softness `C_HARD (C_OFF / C_HARD)^(1 - w)` (0 when fully on; only meaningful if
    /// active).
    pub fn softness(&self) -> f64 {
        let w = self.weight();
        if w >= 1.0 {
            0.0
        } else {
            C_HARD * (C_OFF / C_HARD).powf(1.0 - w)
        }
    }
}

/// Rate limit on the null-space input `alpha_N grad_H` (5.1, after GIENGER et al.).
#[derive(Debug, Clone)]
pub struct NullSpaceLimiter {
    prev: DVector<f64>,
    /// Largest norm of the change per second.
    pub max_rate: f64,
    started: bool,
}

impl NullSpaceLimiter {
    /// Limiter for n-vectors with the given maximum rate of change.
    pub fn new(n: usize, max_rate: f64) -> Self {
        Self {
            prev: DVector::zeros(n),
            max_rate,
            started: false,
        }
    }

    /// Restarts from `value` (no limiting against the history).
    pub fn reset(&mut self, value: &DVector<f64>) {
        self.prev.copy_from(value);
        self.started = true;
    }

    /// Scales the increment of `v` over the previous output so that `|dv| <= max_rate dt`;
    /// `v` receives the limited vector, which becomes the new history.
    pub fn apply(&mut self, v: &mut DVector<f64>, dt: f64) -> Result<(), IkError> {
        if v.len() != self.prev.len() {
            return Err(IkError::Dimension {
                what: "null-space vector",
                expected: self.prev.len(),
                got: v.len(),
            });
        }
        if !(dt >= 0.0 && dt.is_finite() && self.max_rate >= 0.0) {
            return Err(IkError::InvalidParameter {
                name: "dt/max_rate",
                reason: "need finite >= 0",
            });
        }
        if !self.started {
            self.reset(v);
            return Ok(());
        }
        let dist = v.metric_distance(&self.prev);
        let limit = self.max_rate * dt;
        if dist > limit {
            let s = limit / dist;
            for (x, p) in v.iter_mut().zip(self.prev.iter()) {
                *x = p + s * (*x - p);
            }
        }
        self.prev.copy_from(v);
        Ok(())
    }
}
