//! [`TrackingController`]: the joint controller of the dynamic walk, a per-joint PD on the
//! reference plus the RNEA feedforward (joint-torque mode):
//! `tau_j = tau_ff,j(t) + k_p,j (q_ref,j(t) - q_j) + k_d,j (qd_ref,j(t) - qd_j)`.
//!
//! The gains are those of [`JointPd::scaled`] (same bandwidth for every joint, capped for the
//! zero-order hold at 1 kHz). The reference is held at its last sample after the walk. An
//! optional [`Stabiliser`] shifts the support ankles' targets from the IMU.

use super::force::ForceControl;
use super::reference::JointReference;
use super::stabiliser::{Stabiliser, StabiliserGains};
use biped_sim::controller::{Commands, Controller, JointPd};
use biped_sim::drive::DriveMode;
use biped_sim::plant::Plant;
use biped_sim::sensors::Sensors;
use biped_sim::SimError;
use nalgebra::DVector;

/// PD + feedforward joint controller over a [`JointReference`].
#[derive(Debug, Clone)]
pub struct TrackingController {
    reference: JointReference,
    period: f64,
    kp: Vec<f64>,
    kd: Vec<f64>,
    feedforward: bool,
    stabiliser: Option<Stabiliser>,
    force: Option<ForceControl>,
    target: Vec<f64>,
    last_error: f64,
}

impl TrackingController {
    /// Controller for `plant` (torque mode, actuators in the order of the reference) with the
    /// gains of [`JointPd::scaled`] at `q0`; `feedforward = false` runs the PD alone,
    /// `stabiliser = None` tracks without the ankle stabiliser (`Some`: on Lola's ankles;
    /// other robots' through [`Self::with_stabiliser`]).
    pub fn new(
        plant: &mut Plant,
        reference: JointReference,
        q0: &DVector<f64>,
        (bandwidth, damping): (f64, f64),
        feedforward: bool,
        stabiliser: Option<StabiliserGains>,
    ) -> Result<Self, SimError> {
        if plant.mode() != DriveMode::Torque || plant.actuators().len() != reference.joints {
            return Err(SimError::InvalidParameter {
                what: "plant".into(),
                reason: "needs torque mode and one actuator per reference joint".into(),
            });
        }
        let period = reference.dt;
        let pd = JointPd::scaled(plant, q0, period, bandwidth, damping)?;
        let names: Vec<String> = plant.actuators().iter().map(|a| a.name.clone()).collect();
        let stabiliser = stabiliser.map(|g| Stabiliser::new(&names, g)).transpose()?;
        Ok(Self {
            stabiliser,
            target: vec![0.0; reference.joints],
            kp: pd.kp().to_vec(),
            kd: pd.kd().to_vec(),
            reference,
            period,
            feedforward,
            force: None,
            last_error: 0.0,
        })
    }

    /// Adds (or replaces) the ankle stabiliser ([`Stabiliser`]) of the tracking.
    pub fn with_stabiliser(mut self, stabiliser: Stabiliser) -> Self {
        self.stabiliser = Some(stabiliser);
        self
    }

    /// Adds the foot force control ([`ForceControl`]) to the tracking.
    pub fn with_force_control(mut self, force: ForceControl) -> Self {
        self.force = Some(force);
        self
    }

    /// The foot force control's height difference `z_left - z_right` \[m] (0 without it).
    pub fn foot_offset(&self) -> f64 {
        self.force.as_ref().map_or(0.0, ForceControl::offset)
    }

    /// Scales all PD gains by `factor` (0 = feedforward only).
    pub fn scale_gains(&mut self, factor: f64) {
        self.kp.iter_mut().for_each(|k| *k *= factor);
        self.kd.iter_mut().for_each(|k| *k *= factor);
    }

    /// The reference.
    pub fn reference(&self) -> &JointReference {
        &self.reference
    }

    /// Largest `|q_ref - q|` over the joints at the last update \[rad].
    pub fn last_error(&self) -> f64 {
        self.last_error
    }
}

impl Controller for TrackingController {
    fn period(&self) -> f64 {
        self.period
    }

    fn mode(&self) -> DriveMode {
        DriveMode::Torque
    }

    fn update(&mut self, t: f64, s: &Sensors, c: &mut Commands) -> Result<(), SimError> {
        let r = &self.reference;
        let n = r.joints;
        if s.joint_positions.len() != n || c.values.len() != n {
            return Err(SimError::Length {
                what: "sensors/commands",
                got: c.values.len(),
                expected: n,
            });
        }
        let k = r.index(t);
        let (qd, tau) = (r.row(&r.qd, k), r.row(&r.tau, k));
        self.target.copy_from_slice(r.row(&r.q, k));
        if let (Some(st), Some(imu)) = (&self.stabiliser, &s.imu) {
            st.apply(imu, r.tilt[k], r.phase[k], &mut self.target);
        }
        if let Some(f) = &mut self.force {
            f.apply(s, r, k, self.period, &mut self.target)
                .map_err(|e| SimError::Controller(e.to_string()))?;
        }
        let mut worst = 0.0_f64;
        for j in 0..n {
            let e = self.target[j] - s.joint_positions[j];
            worst = worst.max(e.abs());
            let ff = if self.feedforward { tau[j] } else { 0.0 };
            c.values[j] = ff + self.kp[j] * e + self.kd[j] * (qd[j] - s.joint_velocities[j]);
        }
        self.last_error = worst;
        c.mode = DriveMode::Torque;
        Ok(())
    }
}
