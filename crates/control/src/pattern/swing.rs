//! Swing-foot and blending profiles: minimum-jerk blend and the lift profile.
//!
//! Horizontal position and yaw of the swing foot follow the minimum-jerk blend
//! `s(tau) = 10 tau^3 - 15 tau^4 + 6 tau^5` (zero velocity and acceleration at both ends);
//! the height follows `z(tau) = 64 h tau^3 (1 - tau)^3`, which is C2 with zero velocity and
//! acceleration at lift-off and touch-down and peaks at `h` for `tau = 1/2`. Pitch and toe
//! angle blend with the same `s` from their lift-off to their touch-down values.

pub use super::blend::min_jerk;
use super::footsteps::Pose2;
use super::roll::Contact;
use nalgebra::{UnitQuaternion, Vector3};

/// Lift profile `[z, dz/dtau]` with peak `height` at `tau = 1/2` (clamped to \[0, 1]).
pub fn lift(tau: f64, height: f64) -> [f64; 2] {
    let t = tau.clamp(0.0, 1.0);
    let u = 1.0 - t;
    [
        64.0 * height * t * t * t * u * u * u,
        192.0 * height * t * t * u * u * (1.0 - 2.0 * t),
    ]
}

/// Sole frame motion: planar pose, height and pitch with their rates, toe joint angle, contact.
///
/// The sole rotation is `R_z(yaw) R_y(pitch)` (pitch > 0: toes down, heel up).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoleMotion {
    /// Planar pose (continuous yaw).
    pub pose: Pose2,
    /// Height of the sole origin above the ground \[m].
    pub z: f64,
    /// Pitch about the foot's lateral axis \[rad].
    pub pitch: f64,
    /// Linear velocity of the sole origin \[m/s].
    pub velocity: Vector3<f64>,
    /// Yaw rate \[rad/s].
    pub yaw_rate: f64,
    /// Pitch rate \[rad/s].
    pub pitch_rate: f64,
    /// Toe joint angle (toe segment relative to the foot) \[rad].
    pub toe: f64,
    /// Toe joint rate \[rad/s].
    pub toe_rate: f64,
    /// Contact state.
    pub contact: Contact,
}

impl SoleMotion {
    /// A foot standing still and flat at `pose`.
    pub fn standing(pose: Pose2) -> Self {
        Self {
            pose,
            z: 0.0,
            pitch: 0.0,
            velocity: Vector3::zeros(),
            yaw_rate: 0.0,
            pitch_rate: 0.0,
            toe: 0.0,
            toe_rate: 0.0,
            contact: Contact::Flat,
        }
    }

    /// Foot on the footprint `print` pitched by `[pitch, rate]` about the lateral line through
    /// `(px, 0, pz)` of the footprint frame (toe axis for toe-off, heel edge for heel strike);
    /// with [`Contact::Toe`] the toe joint keeps the toe segment flat (`toe = -pitch`).
    pub fn pivot(
        print: Pose2,
        (px, pz): (f64, f64),
        [pitch, rate]: [f64; 2],
        contact: Contact,
    ) -> Self {
        let (s, c) = pitch.sin_cos();
        // sole origin relative to the pivot, rotated: R_y(p) (-px, 0, -pz)
        let (rx, rz) = (-c * px - s * pz, s * px - c * pz);
        let (drx, drz) = (s * px - c * pz, c * px + s * pz);
        let at = print.compose(px + rx, 0.0, 0.0);
        let (sy, cy) = print.yaw.sin_cos();
        let toe = if contact == Contact::Toe { -1.0 } else { 0.0 };
        Self {
            pose: at,
            z: pz + rz,
            pitch,
            velocity: rate * Vector3::new(cy * drx, sy * drx, drz),
            yaw_rate: 0.0,
            pitch_rate: rate,
            toe: toe * pitch,
            toe_rate: toe * rate,
            contact,
        }
    }

    /// Swing foot at phase `tau` of a single support lasting `duration`: minimum-jerk blend of
    /// position and yaw from the lift-off state `a` to the touch-down state `b` (both at
    /// rest), plus the lift profile of peak `height`; pitch and toe angle keep their lift-off
    /// values for the first `hold` of the swing and blend to touch-down in the rest.
    pub fn swing(
        a: &SoleMotion,
        b: &SoleMotion,
        tau: f64,
        duration: f64,
        height: f64,
        hold: f64,
    ) -> Self {
        let [s, ds, _] = min_jerk(tau);
        let [z, dz] = lift(tau, height);
        let rate = ds / duration;
        let mix = |x: f64, y: f64| x + s * (y - x);
        let u = (tau - hold) / (1.0 - hold);
        let [sp, dsp, _] = min_jerk(u);
        let prate = if (0.0..=1.0).contains(&u) {
            dsp / ((1.0 - hold) * duration)
        } else {
            0.0
        };
        let pmix = |x: f64, y: f64| x + sp * (y - x);
        Self {
            pose: Pose2 {
                x: mix(a.pose.x, b.pose.x),
                y: mix(a.pose.y, b.pose.y),
                yaw: mix(a.pose.yaw, b.pose.yaw),
            },
            z: mix(a.z, b.z) + z,
            pitch: pmix(a.pitch, b.pitch),
            velocity: Vector3::new(
                rate * (b.pose.x - a.pose.x),
                rate * (b.pose.y - a.pose.y),
                rate * (b.z - a.z) + dz / duration,
            ),
            yaw_rate: rate * (b.pose.yaw - a.pose.yaw),
            pitch_rate: prate * (b.pitch - a.pitch),
            toe: pmix(a.toe, b.toe),
            toe_rate: prate * (b.toe - a.toe),
            contact: Contact::Swing,
        }
    }

    /// Sole rotation `R_z(yaw) R_y(pitch)`.
    pub fn rotation(&self) -> UnitQuaternion<f64> {
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), self.pose.yaw)
            * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), self.pitch)
    }

    /// Angular velocity (world) `yaw_rate z + pitch_rate R_z(yaw) y`.
    pub fn angular(&self) -> Vector3<f64> {
        let (s, c) = self.pose.yaw.sin_cos();
        Vector3::new(-s * self.pitch_rate, c * self.pitch_rate, self.yaw_rate)
    }
}
