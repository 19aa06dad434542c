//! Trunk-inclination stabiliser through the support ankles (ankle strategy; not in the
//! thesis, which tracks the walk kinematically): the base's roll and pitch in its heading
//! frame are measured by the IMU and compared with the reference's; every support foot's
//! ankle flexion and adduction references are shifted by
//! `dq = k_p (phi - phi_ref) + k_d omega` (clamped to `max_offset`), which tilts the legs
//! back over the feet and moves the centre of pressure towards the falling side.
//!
//! Sign: Lola's ankle flexion (`*_ankle_cross`, axis y) and adduction (`*_foot`, axis x)
//! rotate the foot relative to the shank; with the foot on the ground a positive change
//! rotates the leg by the negative angle, so a forward (positive pitch) lean is answered by a
//! positive flexion offset. Other robots' ankles ([`DynamicLeg`]) carry the sign of their
//! axes, so that the offset turns their feet the same way.

use super::robot_legs::DynamicLeg;
use crate::pattern::Phase;
use biped_sim::sensors::Imu;
use biped_sim::SimError;
use nalgebra::{Rotation3, UnitQuaternion, Vector3};

/// Gains of the [`Stabiliser`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StabiliserGains {
    /// Ankle offset per inclination error \[rad/rad] (0 switches the stabiliser off).
    pub kp: f64,
    /// Ankle offset per inclination rate \[rad/(rad/s)].
    pub kd: f64,
    /// Largest ankle offset \[rad].
    pub max_offset: f64,
}

impl Default for StabiliserGains {
    /// `k_p = 0.2`, `k_d = 0.05 s`, 0.15 rad: the middle of the range that walks the default
    /// 10 x 0.4 m / 0.8 s walk (k_p 0..0.3 with k_d 0.05, k_d 0.03..0.1 with k_p 0.2 all walk;
    /// k_d = 0 or 0.02 falls; k_p = 0.5 walks with 0.09 rad trunk tilt).
    fn default() -> Self {
        Self {
            kp: 0.2,
            kd: 0.05,
            max_offset: 0.15,
        }
    }
}

/// `[roll, pitch]` of the body z axis in the heading (yaw-free) frame of `rot` \[rad].
pub fn roll_pitch(rot: &UnitQuaternion<f64>) -> [f64; 2] {
    let z = heading(rot) * (rot * Vector3::z());
    [(-z.y).atan2(z.z), z.x.atan2(z.z)]
}

/// Rotation from world to the heading frame of `rot` (yaw of its x axis removed).
fn heading(rot: &UnitQuaternion<f64>) -> Rotation3<f64> {
    let x = rot * Vector3::x();
    Rotation3::from_axis_angle(&Vector3::z_axis(), -x.y.atan2(x.x))
}

/// The ankle stabiliser: actuator indices and axis signs of `[left, right]`
/// `[flexion, adduction]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Stabiliser {
    gains: StabiliserGains,
    ankles: [[(usize, f64); 2]; 2],
}

impl Stabiliser {
    /// Stabiliser for Lola's actuators named `names` (`l_ankle_cross`, `l_foot`, ...).
    pub fn new(names: &[String], gains: StabiliserGains) -> Result<Self, SimError> {
        Self::for_legs(
            names,
            &[DynamicLeg::lola("l"), DynamicLeg::lola("r")],
            gains,
        )
    }

    /// Stabiliser on the ankles of the `[left, right]` legs `legs`, for actuators named
    /// `names`.
    pub fn for_legs(
        names: &[String],
        legs: &[DynamicLeg; 2],
        gains: StabiliserGains,
    ) -> Result<Self, SimError> {
        let find = |(n, sign): &(String, f64)| {
            names
                .iter()
                .position(|a| a == n)
                .map(|i| (i, *sign))
                .ok_or_else(|| SimError::Unknown {
                    kind: "ankle actuator",
                    name: n.clone(),
                })
        };
        let ok = |x: f64| x.is_finite() && x >= 0.0;
        if !(ok(gains.kp) && ok(gains.kd) && ok(gains.max_offset)) {
            return Err(SimError::InvalidParameter {
                what: "stabiliser gains".into(),
                reason: "must be finite and >= 0".into(),
            });
        }
        let [l, r] = legs;
        Ok(Self {
            gains,
            ankles: [
                [find(&l.ankle[0])?, find(&l.ankle[1])?],
                [find(&r.ankle[0])?, find(&r.ankle[1])?],
            ],
        })
    }

    /// Adds the ankle offsets for `imu` against the reference inclination `reference`
    /// (`[roll, pitch]`) to the joint targets `q` of the support feet of `phase`.
    pub fn apply(&self, imu: &Imu, reference: [f64; 2], phase: Phase, q: &mut [f64]) {
        let g = &self.gains;
        let tilt = roll_pitch(&imu.orientation);
        let w = heading(&imu.orientation) * (imu.orientation * imu.angular_velocity);
        let off = |k: usize, rate: f64| {
            (g.kp * (tilt[k] - reference[k]) + g.kd * rate).clamp(-g.max_offset, g.max_offset)
        };
        let (d_roll, d_pitch) = (off(0, w.x), off(1, w.y));
        let support = match phase {
            Phase::Double => [true, true],
            Phase::LeftStance => [true, false],
            Phase::RightStance => [false, true],
        };
        for (foot, on) in support.into_iter().enumerate() {
            if on {
                let [(pitch, sp), (roll, sr)] = self.ankles[foot];
                q[pitch] += sp * d_pitch;
                q[roll] += sr * d_roll;
            }
        }
    }
}
