//! IMU damping through the ankles. A robot held stiffly on compliant soles rocks as one rigid
//! body about its feet: the joints do not move relative to each other, so the joint PD cannot
//! see the mode, whose damping the hold's cap on `k_d` ([`super::JointPd::scaled`]) leaves
//! to the soles (TALOS, straight-legged: 1 Hz, damping ratio ~0.01). Ankle torques from the
//! base's angular velocity, as the IMU's gyroscope measures it, damp it: the ankle turns the
//! body against its rotation and the centre of pressure shifts to carry the reaction (the
//! ankle strategy of humanoid stabilisers).

use crate::error::{positive, SimError};
use crate::plant::AnkleAxis;
use nalgebra::Vector3;

/// Ankle torques `tau_l = c_l a_l . omega_l`: `omega_l` the base angular velocity through a
/// first-order low-pass at cutoff `w_l`, `a_l` each ankle's horizontal axis in the base frame
/// ([`crate::plant::Plant::ankle_axes`]), `c_l` its gain.
///
/// With the foot held, turning the body about the ankle is turning the ankle joint, so the
/// term is joint damping `c_l` for the stance motion, which [`super::JointPd::with_stance_damping`]
/// sizes from the damping the hold's cap took from `k_d`. The low-pass keeps it out of the
/// fast modes that set that cap: unfiltered, TALOS's ankles break into a 60 Hz limit cycle
/// from `c_l` ~ 1.8e3 N m s/rad on; filtered at 20-80 rad/s, 6e3 damp the rocking.
#[derive(Debug, Clone, PartialEq)]
pub struct StanceDamping {
    ankles: Vec<StanceAnkle>,
}

/// One damped ankle of [`StanceDamping`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StanceAnkle {
    /// Actuator index (plant order).
    pub actuator: usize,
    /// Gain `c_l` \[N m s/rad].
    pub gain: f64,
    /// Horizontal axis `a_l` in the base frame.
    pub axis: Vector3<f64>,
    /// Low-pass cutoff `w_l` \[rad/s].
    pub cutoff: f64,
    /// Filter factor `1 - exp(-w_l T)` per control period `T`.
    alpha: f64,
    /// Filter state `omega_l`.
    filtered: Vector3<f64>,
}

impl StanceDamping {
    /// Damping of `ankles` with `(c_l [N m s/rad], w_l [rad/s])` in `gains[actuator]`, for
    /// control period `period`; `None` if no ankle has a positive gain.
    pub fn new(
        ankles: &[AnkleAxis],
        gains: &[(f64, f64)],
        period: f64,
    ) -> Result<Option<Self>, SimError> {
        positive("period", period, false)?;
        let mut out = Vec::with_capacity(ankles.len());
        for a in ankles {
            let (c, cutoff) = *gains.get(a.actuator).ok_or(SimError::Length {
                what: "stance damping gains",
                got: gains.len(),
                expected: a.actuator + 1,
            })?;
            positive("stance damping gain", c, true)?;
            positive("stance damping cutoff", cutoff, false)?;
            if c > 0.0 {
                out.push(StanceAnkle {
                    actuator: a.actuator,
                    gain: c,
                    axis: a.axis,
                    cutoff,
                    alpha: -(-cutoff * period).exp_m1(),
                    filtered: Vector3::zeros(),
                });
            }
        }
        Ok((!out.is_empty()).then_some(Self { ankles: out }))
    }

    /// The damped ankles.
    pub fn ankles(&self) -> &[StanceAnkle] {
        &self.ankles
    }

    /// Filters the gyroscope reading `omega` (base frame) and adds the ankle torques to `tau`
    /// (plant actuator order); call once per control period.
    pub fn add_to(&mut self, omega: &Vector3<f64>, tau: &mut [f64]) {
        for a in &mut self.ankles {
            a.filtered += a.alpha * (omega - a.filtered);
            tau[a.actuator] += a.gain * a.axis.dot(&a.filtered);
        }
    }
}
