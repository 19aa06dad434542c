//! Swing-foot and blending profiles: minimum-jerk blend and the lift profile.
//!
//! Horizontal position and yaw of the swing foot follow the minimum-jerk blend
//! `s(tau) = 10 tau^3 - 15 tau^4 + 6 tau^5` (zero velocity and acceleration at both ends);
//! the height follows `z(tau) = 64 h tau^3 (1 - tau)^3`, which is C2 with zero velocity and
//! acceleration at lift-off and touch-down and peaks at `h` for `tau = 1/2`.

use super::footsteps::{Footstep, Pose2};
use nalgebra::Vector3;

/// Minimum-jerk blend `[s, ds/dtau, d2s/dtau2]` at `tau` (clamped to \[0, 1]).
pub fn min_jerk(tau: f64) -> [f64; 3] {
    let t = tau.clamp(0.0, 1.0);
    let (t2, t3) = (t * t, t * t * t);
    [
        t3 * (10.0 - 15.0 * t + 6.0 * t2),
        30.0 * t2 * (1.0 - t) * (1.0 - t),
        60.0 * t * (1.0 - t) * (1.0 - 2.0 * t),
    ]
}

/// Lift profile `[z, dz/dtau]` with peak `height` at `tau = 1/2` (clamped to \[0, 1]).
pub fn lift(tau: f64, height: f64) -> [f64; 2] {
    let t = tau.clamp(0.0, 1.0);
    let u = 1.0 - t;
    [
        64.0 * height * t * t * t * u * u * u,
        192.0 * height * t * t * u * u * (1.0 - 2.0 * t),
    ]
}

/// Planar sole pose with height, linear velocity and yaw rate (world).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoleMotion {
    /// Planar pose (continuous yaw).
    pub pose: Pose2,
    /// Height above the ground \[m].
    pub z: f64,
    /// Linear velocity of the sole origin \[m/s].
    pub velocity: Vector3<f64>,
    /// Yaw rate \[rad/s].
    pub yaw_rate: f64,
}

impl SoleMotion {
    /// A foot standing still at `pose`.
    pub fn standing(pose: Pose2) -> Self {
        Self {
            pose,
            z: 0.0,
            velocity: Vector3::zeros(),
            yaw_rate: 0.0,
        }
    }

    /// Swing foot of `step` at phase `tau` of a single support lasting `duration`.
    pub fn swing(step: &Footstep, tau: f64, duration: f64, height: f64) -> Self {
        let [s, ds, _] = min_jerk(tau);
        let [z, dz] = lift(tau, height);
        let (a, b) = (&step.from, &step.to);
        let rate = ds / duration;
        Self {
            pose: Pose2 {
                x: a.x + s * (b.x - a.x),
                y: a.y + s * (b.y - a.y),
                yaw: a.yaw + s * (b.yaw - a.yaw),
            },
            z,
            velocity: Vector3::new(rate * (b.x - a.x), rate * (b.y - a.y), dz / duration),
            yaw_rate: rate * (b.yaw - a.yaw),
        }
    }
}
