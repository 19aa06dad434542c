//! One actuator: motor, friction and the transmission to the generalized coordinates.

use super::{DriveMode, FrictionLaw, FrictionParams, MotorParams};
use crate::error::SimError;
use biped_dynamics::mechanism::{Coupling, MAX_COUPLED};
use biped_dynamics::model::Mechanism;
use biped_dynamics::{BodyId, Data, JointModel, Model};
use serde::Serialize;

/// How the motor is connected to the generalized coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Transmission {
    /// Ideal joint-torque source on the joint coordinate (no motor); takes torque commands in
    /// every drive mode.
    Direct,
    /// Rigid gear of ratio `N` (motor speed `N qdot`), e.g. a rigid Harmonic Drive (3.1).
    Gear {
        /// Gear ratio `N`.
        ratio: f64,
    },
    /// Motor rotor that is a coupled part (knee, ankle roller screws): the motor-rate row is
    /// the spin (part-frame z) row of the rotor's relative Jacobian (3.5), (3.32).
    Rotor {
        /// Rotor body.
        body: BodyId,
        /// Input coordinates (q indices), first `n` used.
        q_in: [usize; MAX_COUPLED],
        /// Input coordinates (v indices), first `n` used.
        v_in: [usize; MAX_COUPLED],
        /// Number of inputs.
        n: usize,
    },
    /// Elastic gear of Type 3: the motor has its own coordinate; the gear spring-damper acts
    /// between motor and link (added by the plant).
    Elastic {
        /// Motor coordinate in `q`.
        motor_q: usize,
        /// Motor coordinate in `v`.
        motor_v: usize,
        /// Gear ratio `N`.
        ratio: f64,
    },
}

/// Motor-rate row `omega_m = n(q) v`: at most [`MAX_COUPLED`] non-zeros.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MotorRow {
    idx: [usize; MAX_COUPLED],
    coef: [f64; MAX_COUPLED],
    len: usize,
}

impl MotorRow {
    fn single(idx: usize, coef: f64) -> Self {
        let mut r = Self::default();
        r.idx[0] = idx;
        r.coef[0] = coef;
        r.len = 1;
        r
    }

    /// Motor speed `n v`.
    #[inline]
    pub fn rate(&self, v: &[f64]) -> f64 {
        let n = self.len.min(MAX_COUPLED);
        self.idx[..n]
            .iter()
            .zip(&self.coef[..n])
            .map(|(&i, c)| c * v[i])
            .sum()
    }

    /// Adds `n^T tau` to the generalized forces.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn apply(&self, tau: f64, gen: &mut [f64]) {
        let n = self.len.min(MAX_COUPLED);
        for (&i, c) in self.idx[..n].iter().zip(&self.coef[..n]) {
            gen[i] += c * tau;
        }
    }

    /// The non-zero `(v index, coefficient)` pairs.
    pub fn entries(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        (0..self.len).map(|k| (self.idx[k], self.coef[k]))
    }
}

/// One actuated joint with its drive.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Actuator {
    /// Joint name.
    pub name: String,
    /// Joint coordinate in `q`.
    pub joint_q: usize,
    /// Joint coordinate in `v`.
    pub joint_v: usize,
    /// Motor-to-coordinates transmission.
    pub transmission: Transmission,
    /// Motor constants.
    pub motor: MotorParams,
    /// Motor-side friction.
    pub friction: FrictionParams,
    /// Nominal `|d omega_m / d qdot_joint|` at the initial configuration (1 for `Direct`), for
    /// converting joint torques to motor torques in simple controllers.
    pub nominal_ratio: f64,
    /// Joint torque limit (e.g. a URDF `effort`): torque commands are clamped to
    /// `[-effort, effort]` \[N m or N]; `f64::INFINITY` = none. (Current and voltage commands are
    /// limited by the motor's `max_current` instead.)
    pub effort: f64,
    /// Joint speed limit `omega_max` (e.g. a URDF `velocity`) \[rad/s or m/s]: with a finite
    /// `effort`, torque commands held by [`crate::plant::Plant::hold_commands`] are clamped to
    /// the DC motor's torque-speed line at the sampled speed ([`Self::torque_envelope`]);
    /// `f64::INFINITY` = none.
    pub velocity: f64,
}

/// Motor-side quantities of one actuator at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DriveState {
    /// Motor speed \[rad/s].
    pub speed: f64,
    /// Motor torque `k_t i` (or the commanded torque over the nominal ratio) \[N m].
    pub torque: f64,
    /// Friction torque \[N m].
    pub friction: f64,
    /// Current \[A] (commanded, integrated, or estimated in torque mode).
    pub current: f64,
    /// `di/dt` (voltage mode only, else 0).
    pub current_rate: f64,
}

impl Actuator {
    /// Joint torque range `[lo, hi]` at joint speed `w`: `[-effort, effort]`, narrowed with a
    /// finite speed limit to the DC motor's line `tau = effort (+-1 - w / omega_max)` (as Isaac
    /// Lab's `DCMotor` with the saturation torque at the effort limit): no driving torque at
    /// `omega_max`, braking only beyond it (the full effort beyond `2 omega_max`), the full effort
    /// against the motion.
    #[inline]
    pub fn torque_envelope(&self, w: f64) -> (f64, f64) {
        let e = self.effort;
        if self.velocity.is_finite() && e.is_finite() {
            let back = e * w / self.velocity;
            ((-e - back).clamp(-e, e), (e - back).clamp(-e, e))
        } else {
            (-e, e)
        }
    }

    /// Command `cmd` of kind `mode` within the drive's limits at joint speed `w`: torque
    /// commands in [`Self::torque_envelope`], a motor-driven joint's (`driven`: it has a motor
    /// row) current and voltage commands within the motor's `max_current` and `max_voltage`.
    #[inline]
    pub fn limit(&self, mode: DriveMode, cmd: f64, w: f64, driven: bool) -> f64 {
        let m = &self.motor;
        // max/min, not `clamp`: no assertion on the bounds (checked in `Plant::new`).
        let (lo, hi) = match mode {
            DriveMode::Torque => self.torque_envelope(w),
            DriveMode::Current if driven => (-m.max_current, m.max_current),
            DriveMode::Voltage if driven => (-m.max_voltage, m.max_voltage),
            _ => return cmd,
        };
        cmd.max(lo).min(hi)
    }

    /// The rotor transmission of coupled body `body`, its inputs read from the model.
    pub fn rotor_transmission(model: &Model, body: BodyId) -> Result<Transmission, SimError> {
        let b = model.body(body).ok_or_else(|| SimError::Unknown {
            kind: "rotor body",
            name: format!("#{body}"),
        })?;
        let JointModel::Coupled { inputs, .. } = b.joint() else {
            return Err(SimError::Unsupported(format!(
                "`{}` is not a coupled part",
                b.name()
            )));
        };
        let (mut q_in, mut v_in) = ([0; MAX_COUPLED], [0; MAX_COUPLED]);
        for (k, &inp) in inputs.iter().take(MAX_COUPLED).enumerate() {
            let ib = model.body(inp).ok_or_else(|| SimError::Unknown {
                kind: "input body",
                name: format!("#{inp}"),
            })?;
            q_in[k] = ib.q_index();
            v_in[k] = ib.v_index();
        }
        let n = inputs.len().min(MAX_COUPLED);
        Ok(Transmission::Rotor {
            body,
            q_in,
            v_in,
            n,
        })
    }

    /// Whether the motor-rate row depends on `q` (roller-screw rotors); the rows of the other
    /// transmissions are constant and need [`Self::motor_row`] only once.
    pub fn row_varies(&self) -> bool {
        matches!(self.transmission, Transmission::Rotor { .. })
    }

    /// Motor-rate row at `q`; `None` for `Direct`.
    pub fn motor_row(&self, model: &Model, q: &[f64]) -> Result<Option<MotorRow>, SimError> {
        Ok(match self.transmission {
            Transmission::Direct => None,
            Transmission::Gear { ratio } => Some(MotorRow::single(self.joint_v, ratio)),
            Transmission::Elastic { motor_v, .. } => Some(MotorRow::single(motor_v, 1.0)),
            Transmission::Rotor {
                body,
                q_in,
                v_in,
                n,
            } => {
                let Some(JointModel::Coupled { mechanism, .. }) =
                    model.body(body).map(|b| b.joint())
                else {
                    return Err(SimError::Unsupported("rotor is not a coupled part".into()));
                };
                let coef = if let Mechanism::Knee(knee) = mechanism {
                    // Fast path (3.3), (3.5): spin rate N_screw dl/dq, no part frames.
                    let t = knee.drive.transmission(q[q_in[0]])?;
                    [knee.drive.screw_ratio() * t.dtravel, 0.0, 0.0]
                } else {
                    let mut qv = [0.0; MAX_COUPLED];
                    for k in 0..n {
                        qv[k] = q[q_in[k]];
                    }
                    let m = mechanism.motion(&qv[..n], &[0.0; MAX_COUPLED][..n])?;
                    std::array::from_fn(|k| if k < n { m.jacobian[k][2] } else { 0.0 })
                };
                Some(MotorRow {
                    idx: v_in,
                    coef,
                    len: n,
                })
            }
        })
    }

    /// Motor-rate row at `q` from the mechanism loops that `data`'s last kinematics pass
    /// closed (e.g. `forward_dynamics_kinematics` at the same `q`): rotor rows by
    /// [`Data::coupled_spin_row`] (a cache lookup instead of a loop closure, always correct
    /// for `q`), the other transmissions as [`Self::motor_row`].
    pub fn motor_row_cached(
        &self,
        model: &Model,
        data: &Data,
        q: &[f64],
    ) -> Result<Option<MotorRow>, SimError> {
        match self.transmission {
            Transmission::Rotor { body, v_in, n, .. } => Ok(Some(MotorRow {
                idx: v_in,
                coef: data.coupled_spin_row(model, body, q)?,
                len: n,
            })),
            _ => self.motor_row(model, q),
        }
    }

    /// [`Self::motor_row_cached`] written into `row`: a rotor row that is already there only
    /// gets its coefficients replaced (no temporary row: moving one into place stalls on store
    /// forwarding in the plant's right-hand side).
    #[inline]
    pub fn refresh_motor_row(
        &self,
        model: &Model,
        data: &Data,
        q: &[f64],
        row: &mut Option<MotorRow>,
    ) -> Result<(), SimError> {
        match (&self.transmission, row.as_mut()) {
            (Transmission::Rotor { body, .. }, Some(r)) => {
                r.coef = data.coupled_spin_row(model, *body, q)?;
            }
            _ => *row = self.motor_row_cached(model, data, q)?,
        }
        Ok(())
    }

    /// Adds this actuator's generalized forces to `gen` for the command `cmd` (interpreted by
    /// `mode`) and the current state `i` (voltage mode), returns the motor-side state: the
    /// forces of [`Self::hold`] and [`Self::forces`] in one call.
    #[allow(clippy::too_many_arguments)]
    pub fn apply(
        &self,
        row: Option<&MotorRow>,
        mode: DriveMode,
        cmd: f64,
        i: f64,
        v: &[f64],
        gen: &mut [f64],
    ) -> DriveState {
        let law = FrictionLaw::from(&self.friction);
        let hold = self.hold(&law, mode, cmd, i, row.is_some());
        gen[hold.index] += hold.direct;
        self.forces(&hold, &law, row, v, gen)
    }

    /// The part of this actuator's action fixed by the command `cmd` of kind `mode` (limited as
    /// [`Self::limit`] at rest) and, in voltage mode, the current `i`; `driven`: the actuator
    /// has a motor row. `law` is [`FrictionLaw::from`] this actuator's friction. The direct
    /// force ([`DriveHold::direct`] at [`DriveHold::index`]) does not depend on `i`.
    #[inline]
    pub fn hold(
        &self,
        law: &FrictionLaw,
        mode: DriveMode,
        cmd: f64,
        i: f64,
        driven: bool,
    ) -> DriveHold {
        let cmd = self.limit(mode, cmd, 0.0, driven);
        let direct = DriveHold {
            direct: cmd,
            index: self.joint_v,
            torque: cmd,
            ..DriveHold::default()
        };
        if !driven {
            return direct;
        }
        let m = &self.motor;
        let (torque, current) = match mode {
            DriveMode::Torque => {
                let tau = cmd / self.nominal_ratio;
                (tau, tau / m.torque_constant)
            }
            DriveMode::Current => (m.torque(cmd), cmd),
            DriveMode::Voltage => (m.torque(i), i),
        };
        let (direct, index) = match (mode, self.transmission) {
            (DriveMode::Torque, Transmission::Elastic { motor_v, ratio, .. }) => {
                (cmd / ratio, motor_v)
            }
            (DriveMode::Torque, _) => (cmd, self.joint_v),
            _ => (0.0, self.joint_v),
        };
        DriveHold {
            direct,
            index,
            drive: if mode == DriveMode::Torque {
                0.0
            } else {
                torque
            },
            torque,
            current,
            level: law.level(torque),
            voltage: (mode == DriveMode::Voltage).then_some(cmd),
        }
    }

    /// Adds the motor-row forces of `hold` (drive torque less friction at the motor speed
    /// `row v`; nothing without a row) to `gen`, returns the motor-side state. The direct force
    /// of `hold` is the caller's to add. Inlined into the plant's loop over the drives, whose
    /// per-drive work is small next to a call.
    #[inline(always)]
    pub fn forces(
        &self,
        hold: &DriveHold,
        law: &FrictionLaw,
        row: Option<&MotorRow>,
        v: &[f64],
        gen: &mut [f64],
    ) -> DriveState {
        let Some(row) = row else {
            return DriveState {
                torque: hold.torque,
                ..DriveState::default()
            };
        };
        let speed = row.rate(v);
        let friction = law.torque(speed, hold.level);
        row.apply(hold.drive - friction, gen);
        let current_rate = hold
            .voltage
            .map_or(0.0, |u| self.motor.current_rate(u, hold.current, speed));
        DriveState {
            speed,
            torque: hold.torque,
            friction,
            current: hold.current,
            current_rate,
        }
    }
}

/// What an actuator's command fixes of its action ([`Actuator::hold`]): constant over a
/// control period's right-hand sides in torque and current mode.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DriveHold {
    /// Generalized force added directly at [`Self::index`] (a torque command, or any command
    /// of a drive without motor row).
    pub direct: f64,
    /// `v` index of [`Self::direct`].
    pub index: usize,
    /// Motor torque applied through the motor row (0 for torque commands).
    pub drive: f64,
    /// Motor torque `k_t i` (or the commanded torque over the nominal ratio) \[N m].
    pub torque: f64,
    /// Current \[A].
    pub current: f64,
    /// Coulomb level of the friction at [`Self::torque`] ([`FrictionLaw::level`]).
    pub level: f64,
    /// The limited voltage command (voltage mode only).
    pub voltage: Option<f64>,
}

#[cfg(test)]
mod tests;
