//! Decentralised joint position control: a PD law per actuated joint without gravity
//! compensation, with gains scaled by the joint-space inertia so that every joint gets the
//! same closed-loop bandwidth.

use super::{Commands, Controller, StanceDamping};
use crate::drive::{DriveMode, Transmission};
use crate::error::{finite, positive, SimError};
use crate::plant::Plant;
use crate::sensors::Sensors;
use nalgebra::{DMatrix, DVector};

/// Joint reference trajectory: writes `q_ref(t)` (one per actuator) into the slice.
pub type Trajectory = Box<dyn FnMut(f64, &mut [f64]) + Send>;

/// Share of the capped-off damping that [`JointPd::with_stance_damping`] restores.
const STANCE_SHARE: f64 = 0.5;

/// PD joint position controller: `tau = k_p (q_ref - q) - k_d qdot`.
pub struct JointPd {
    period: f64,
    target: Vec<f64>,
    kp: Vec<f64>,
    kd: Vec<f64>,
    trajectory: Option<Trajectory>,
    /// Current mode: joint torques -> commands map and `(tau, out)` buffers.
    current_map: Option<(DMatrix<f64>, DVector<f64>, DVector<f64>)>,
    /// Per actuator: `Some(N)` feeds back the motor encoder divided by `N` (collocated control
    /// of an elastic gear), `None` the joint encoder.
    motor_feedback: Vec<Option<f64>>,
    mode: DriveMode,
    /// Per actuator `(k_d` before the hold's cap, the cap on `k_p)` of [`Self::scaled`]
    /// (`(k_d, inf)` after [`Self::new`]): what [`Self::with_stance_damping`] may add.
    uncapped: Vec<(f64, f64)>,
    /// IMU damping through the ankles, added to the joint torques.
    stance: Option<StanceDamping>,
}

impl std::fmt::Debug for JointPd {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("JointPd")
            .field("period", &self.period)
            .field("kp", &self.kp)
            .field("kd", &self.kd)
            .finish()
    }
}

impl JointPd {
    /// PD with explicit gains (torque output); all vectors of the same length.
    pub fn new(
        period: f64,
        target: Vec<f64>,
        kp: Vec<f64>,
        kd: Vec<f64>,
    ) -> Result<Self, SimError> {
        positive("period", period, false)?;
        let n = target.len();
        for (what, x) in [("kp", &kp), ("kd", &kd)] {
            if x.len() != n {
                return Err(SimError::Length {
                    what,
                    got: x.len(),
                    expected: n,
                });
            }
        }
        finite("target", &target)?;
        finite("gains", &kp)?;
        finite("gains", &kd)?;
        Ok(Self {
            period,
            target,
            kp,
            kd: kd.clone(),
            trajectory: None,
            current_map: None,
            motor_feedback: vec![None; n],
            mode: DriveMode::Torque,
            uncapped: kd.iter().map(|&d| (d, f64::INFINITY)).collect(),
            stance: None,
        })
    }

    /// Gains `k_p = w^2 m_j`, `k_d = 2 zeta w m_j` with `m_j = m_sub + m_rest` of
    /// [`Plant::actuator_inertias`] at `q0`: a leg joint gets bandwidth `w` both when its
    /// subtree swings freely and when the ground holds the subtree and the joint moves the rest
    /// of the robot (a stance ankle carrying the body as an inverted pendulum). Both gains are
    /// capped for the free subtree under the zero-order hold of period `T`: with
    /// `a = k_p T^2 / m_sub` and `b = k_d T / m_sub` the sampled loop has the characteristic
    /// polynomial `z^2 + (a/2 + b - 2) z + (a/2 - b + 1)`, stable (Jury) for `a/2 < b < 2`;
    /// the caps `a <= 1/2`, `b <= 1/2` keep it inside with margin (larger caps, e.g. `a = 1`,
    /// `b = 3/2`, destabilise Lola's coupled legs and contacts at 1 kHz). The price: stance
    /// ankles are lightly damped (a drop leaves a slow fore-aft rocking for seconds), which
    /// [`Self::with_stance_damping`] makes up for through the IMU. Target = the joint angles of
    /// `q0`.
    ///
    /// Elastic (Type 3) gears are controlled collocated: the feedback is the motor encoder over
    /// `N` (PD on the link encoder through the gear spring is non-collocated and goes unstable
    /// at these gains), and the cap uses the reflected motor inertia `N^2 J_m` only.
    pub fn scaled(
        plant: &mut Plant,
        q0: &DVector<f64>,
        period: f64,
        bandwidth: f64,
        damping: f64,
    ) -> Result<Self, SimError> {
        positive("period", period, false)?;
        positive("bandwidth", bandwidth, false)?;
        positive("damping", damping, true)?;
        let m = plant.actuator_inertias(q0)?;
        let target = plant.actuators().iter().map(|a| q0[a.joint_q]).collect();
        let t2 = period * period;
        let kp_cap: Vec<f64> = m.iter().map(|i| 0.5 * i.free / t2).collect();
        let kp = m
            .iter()
            .zip(&kp_cap)
            .map(|(i, cap)| (bandwidth * bandwidth * (i.sub + i.rest)).min(*cap))
            .collect();
        let wanted: Vec<f64> = m
            .iter()
            .map(|i| 2.0 * damping * bandwidth * (i.sub + i.rest))
            .collect();
        let kd = m
            .iter()
            .zip(&wanted)
            .map(|(i, w)| w.min(0.5 * i.free / period))
            .collect();
        let mut pd = Self::new(period, target, kp, kd)?;
        pd.uncapped = wanted.into_iter().zip(kp_cap).collect();
        for (f, a) in pd.motor_feedback.iter_mut().zip(plant.actuators()) {
            if let Transmission::Elastic { ratio, .. } = a.transmission {
                *f = Some(ratio);
            }
        }
        Ok(pd)
    }

    /// Follows `trajectory` instead of the constant target.
    pub fn with_trajectory(mut self, trajectory: Trajectory) -> Self {
        self.trajectory = Some(trajectory);
        self
    }

    /// Adds IMU damping through the ankles of `plant` at `q0` ([`StanceDamping`]): each
    /// ankle's gain `c` is half the damping the hold's cap took from its `k_d`,
    /// `(2 zeta w m_j - k_d) / 2` (at the full amount and a cutoff `w`, Lola Type 3
    /// destabilises from ~0.6 of it on), and its gyroscope low-pass cutoff
    /// `w_f = min(w, k_p,max / c)`: above the cutoff the filtered term acts as a spring `c w_f`
    /// on the stance angle and gets the `k_p` cap (TALOS's 0.12 kg m^2 ankles keep ~20 rad/s;
    /// the G1's rotor-less 1e-4 kg m^2 ankle rolls ~0.1 rad/s, i.e. next to none, where 40
    /// rad/s turns their limit cycle into hopping). Nothing after [`Self::new`] (no cap) and
    /// on elastic-gear ankles (through the gear spring the gyroscope is non-collocated
    /// feedback); Lola's ankles are rigid roller screws in Type 3 too.
    pub fn with_stance_damping(
        mut self,
        plant: &mut Plant,
        q0: &DVector<f64>,
        bandwidth: f64,
    ) -> Result<Self, SimError> {
        let ankles = plant.ankle_axes(q0)?;
        let gains: Vec<(f64, f64)> = (self.uncapped.iter().zip(&self.kd))
            .zip(&self.motor_feedback)
            .map(|((&(want, kp_cap), kd), elastic)| {
                let c = match elastic {
                    Some(_) => 0.0,
                    None => STANCE_SHARE * (want - kd).max(0.0),
                };
                (
                    c,
                    if c > 0.0 {
                        bandwidth.min(kp_cap / c)
                    } else {
                        bandwidth
                    },
                )
            })
            .collect();
        self.stance = StanceDamping::new(&ankles, &gains, self.period)?;
        Ok(self)
    }

    /// The IMU damping through the ankles, if any.
    pub fn stance_damping(&self) -> Option<&StanceDamping> {
        self.stance.as_ref()
    }

    /// Outputs motor currents for a plant in current mode: the joint torques `tau` become
    /// motor torques `A^-1 tau` through the transmission matrix `A` of
    /// [`Plant::transmission_matrix`] at `q0` (the two ankle screws drive both ankle joints),
    /// divided by `k_t` (direct joints keep torque commands).
    pub fn with_current_output(
        mut self,
        plant: &Plant,
        q0: &DVector<f64>,
    ) -> Result<Self, SimError> {
        let a = plant.transmission_matrix(q0)?;
        let n = a.nrows();
        let mut map = a.try_inverse().ok_or_else(|| SimError::InvalidParameter {
            what: "transmission matrix".into(),
            reason: "singular at q0".into(),
        })?;
        for (k, act) in plant.actuators().iter().enumerate() {
            if act.transmission != Transmission::Direct {
                map.row_mut(k).scale_mut(1.0 / act.motor.torque_constant);
            }
        }
        self.current_map = Some((map, DVector::zeros(n), DVector::zeros(n)));
        self.mode = DriveMode::Current;
        Ok(self)
    }

    /// Current joint reference.
    pub fn target(&self) -> &[f64] {
        &self.target
    }

    /// Proportional gains.
    pub fn kp(&self) -> &[f64] {
        &self.kp
    }

    /// Derivative gains.
    pub fn kd(&self) -> &[f64] {
        &self.kd
    }

    /// The derivative gains the bandwidth asked for before the zero-order-hold cap of
    /// [`Self::scaled`] (equal to [`Self::kd`] where nothing was capped).
    pub fn kd_wanted(&self) -> impl Iterator<Item = f64> + '_ {
        self.uncapped.iter().map(|&(want, _)| want)
    }
}

impl Controller for JointPd {
    fn period(&self) -> f64 {
        self.period
    }

    fn mode(&self) -> DriveMode {
        self.mode
    }

    fn update(&mut self, t: f64, s: &Sensors, c: &mut Commands) -> Result<(), SimError> {
        let n = self.target.len();
        if s.joint_positions.len() != n || c.values.len() != n {
            return Err(SimError::Length {
                what: "sensors/commands",
                got: c.values.len(),
                expected: n,
            });
        }
        if let Some(traj) = self.trajectory.as_mut() {
            traj(t, &mut self.target);
            finite("trajectory", &self.target)?;
        }
        for j in 0..n {
            let (q, qd) = match self.motor_feedback[j] {
                Some(ratio) => (s.motor_positions[j] / ratio, s.motor_velocities[j] / ratio),
                None => (s.joint_positions[j], s.joint_velocities[j]),
            };
            let tau = self.kp[j] * (self.target[j] - q) - self.kd[j] * qd;
            c.values[j] = tau;
        }
        if let (Some(stance), Some(imu)) = (&mut self.stance, &s.imu) {
            stance.add_to(&imu.angular_velocity, &mut c.values);
        }
        if let Some((map, tau, out)) = self.current_map.as_mut() {
            tau.as_mut_slice().copy_from_slice(&c.values);
            map.mul_to(tau, out);
            c.values.copy_from_slice(out.as_slice());
        }
        c.mode = self.mode;
        Ok(())
    }
}
