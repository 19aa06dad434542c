//! Hard joint position and velocity limits of a differential IK step, as a box on `qd`.
//!
//! For a joint with range `[lo, hi]`, margin `m` and the distance `d = hi - m - q` left to
//! the shrunk upper bound, the largest admissible velocity of the next step of length `dt` is
//! `min(v_max, v_b(d), d / dt)` for `d >= 0`, with the discrete braking curve
//! `v_b = (sqrt(a^2 dt^2 + 8 a d) - a dt) / 2` (`a = a_max`, `v_b^2 / 2a + v_b dt / 2 = d`):
//! moving at `v_b` the next step's `v_b` is exactly `a dt` lower, so a joint approaching its
//! bound brakes with `a_max`; `d / dt` (binding only in the last `a dt^2`) lands it on the
//! bound without passing it. Beyond the bound (`d < 0`) it is `k_r d`: moved back inside at
//! the recovery rate `k_r`. The lower bound is the mirror image. The box is what
//! [`super::saturation`] keeps the RMRC solution in, so `q` stays within `[lo + m, hi - m]`
//! once inside. Generic over the robot: a joint is named only by its `q`/`v` indices.

use crate::error::IkError;
use nalgebra::DVector;

/// Range of one single-DoF joint.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointRange {
    /// Index into q.
    pub q_index: usize,
    /// Index into v.
    pub v_index: usize,
    /// Lower limit.
    pub lower: f64,
    /// Upper limit.
    pub upper: f64,
}

/// How close and how fast the joints may approach their limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitSettings {
    /// Distance kept from every limit (q stays in `[lo + margin, hi - margin]`) \[rad or m].
    pub margin: f64,
    /// Velocity limit `v_max` of every joint \[rad/s or m/s].
    pub max_velocity: f64,
    /// Deceleration `a_max` with which a joint must be able to stop at its bound \[1/s^2]
    /// (default 200: the toe-off of 0.5 m steps lifts the heel by 0.4 rad within the last
    /// 0.1 s of the double support, which asks the toe joint for up to ~220 rad/s^2; at 100 the
    /// IK lags it by 2 cm).
    pub max_deceleration: f64,
    /// Rate `k_r` at which a joint beyond its shrunk range is moved back \[1/s].
    pub recovery_rate: f64,
    /// Damping of the solve once joints are held, relative to the mean diagonal of
    /// `J W^-1 J^T` ([`super::saturation`]).
    pub regularisation: f64,
}

impl Default for LimitSettings {
    fn default() -> Self {
        Self {
            margin: 0.01,
            max_velocity: 10.0,
            max_deceleration: 200.0,
            recovery_rate: 20.0,
            regularisation: 1e-3,
        }
    }
}

/// Position and velocity limits of a set of joints (the box on `qd` of one IK step).
#[derive(Debug, Clone, PartialEq)]
pub struct JointLimits {
    ranges: Vec<JointRange>,
    settings: LimitSettings,
    /// Velocity limit of every range (same order): `settings.max_velocity` unless set per joint.
    velocity: Vec<f64>,
}

impl JointLimits {
    /// Validated limits: finite ranges wider than twice the margin, positive rates.
    pub fn new(ranges: Vec<JointRange>, settings: LimitSettings) -> Result<Self, IkError> {
        let s = settings;
        let positive = [s.max_velocity, s.max_deceleration, s.recovery_rate];
        let non_negative = [s.margin, s.regularisation];
        if non_negative.iter().any(|v| !(*v >= 0.0 && v.is_finite()))
            || positive.iter().any(|v| v.is_nan() || *v <= 0.0)
        {
            return Err(IkError::InvalidParameter {
                name: "limit settings",
                reason: "need margin, regularisation >= 0 and positive velocity, deceleration and recovery rate",
            });
        }
        let narrow = |r: &JointRange| {
            let width = r.upper - r.lower;
            width.is_nan() || !width.is_finite() || width <= 2.0 * s.margin
        };
        if ranges.iter().any(narrow) {
            return Err(IkError::InvalidParameter {
                name: "joint range",
                reason: "every range must be finite and wider than twice the margin",
            });
        }
        let velocity = vec![s.max_velocity; ranges.len()];
        Ok(Self {
            ranges,
            settings,
            velocity,
        })
    }

    /// The same limits with a velocity limit of its own for the joints listed as
    /// `(v_index, v_max)` (e.g. a URDF's `<limit velocity>`); the others keep
    /// `settings.max_velocity`. Errors on a limit that is not finite and positive or a
    /// `v_index` without a range.
    pub fn with_velocities(mut self, limits: &[(usize, f64)]) -> Result<Self, IkError> {
        for &(v_index, v_max) in limits {
            if !(v_max > 0.0 && v_max.is_finite()) {
                return Err(IkError::InvalidParameter {
                    name: "joint velocity limit",
                    reason: "must be finite and > 0",
                });
            }
            let k = self.ranges.iter().position(|r| r.v_index == v_index);
            let k = k.ok_or(IkError::InvalidParameter {
                name: "joint velocity limit",
                reason: "names a v index without a joint range",
            })?;
            self.velocity[k] = v_max;
        }
        Ok(self)
    }

    /// Velocity limit of every range, in [`Self::ranges`] order.
    pub fn velocity_limits(&self) -> &[f64] {
        &self.velocity
    }

    /// The joints.
    pub fn ranges(&self) -> &[JointRange] {
        &self.ranges
    }

    /// The settings.
    pub fn settings(&self) -> &LimitSettings {
        &self.settings
    }

    /// Largest speed towards a bound `d >= 0` away (negative beyond it) for steps `dt`, for a
    /// joint with velocity limit `v_max`.
    fn admissible(&self, d: f64, dt: f64, v_max: f64) -> f64 {
        let s = &self.settings;
        let adt = s.max_deceleration * dt;
        if d >= 0.0 {
            v_max
                .min(0.5 * ((adt * adt + 8.0 * s.max_deceleration * d).sqrt() - adt))
                .min(d / dt)
        } else {
            (s.recovery_rate * d).max(-v_max)
        }
    }

    /// Fills the velocity box `[lo, hi]` (length nv) of a step `dt` at `q`; entries of joints
    /// without a range are `-inf` / `+inf`.
    pub fn velocity_box(
        &self,
        q: &DVector<f64>,
        dt: f64,
        lo: &mut DVector<f64>,
        hi: &mut DVector<f64>,
    ) {
        lo.fill(f64::NEG_INFINITY);
        hi.fill(f64::INFINITY);
        let m = self.settings.margin;
        for (r, &v_max) in self.ranges.iter().zip(&self.velocity) {
            let x = q[r.q_index];
            let up = self.admissible(r.upper - m - x, dt, v_max);
            let down = -self.admissible(x - r.lower - m, dt, v_max);
            // both bands cannot be violated at once (range > 2 margin); keep lo <= hi
            lo[r.v_index] = down.min(up);
            hi[r.v_index] = up.max(down);
        }
    }

    /// Smallest distance of a joint to its nearer limit at `q` (negative: beyond).
    pub fn min_margin(&self, q: &DVector<f64>) -> f64 {
        self.ranges
            .iter()
            .map(|r| (q[r.q_index] - r.lower).min(r.upper - q[r.q_index]))
            .fold(f64::INFINITY, f64::min)
    }
}
