//! Cascade control (end of 2.1.1): an outer loop at period `T` writes a setpoint that an inner
//! loop at period `T / r` (integer `r`) turns into the actuator commands; the simulation runs
//! the cascade at the inner period.

use super::{Commands, Controller};
use crate::drive::{DriveMode, Transmission};
use crate::error::{positive, SimError};
use crate::plant::Plant;
use crate::sensors::Sensors;

/// An inner loop: turns the outer loop's setpoint into commands every inner period.
pub trait InnerController {
    /// Inner period \[s].
    fn period(&self) -> f64;
    /// Kind of command written.
    fn mode(&self) -> DriveMode;
    /// One inner cycle: `setpoint` from the outer loop, writes `out`.
    fn update(
        &mut self,
        t: f64,
        s: &Sensors,
        setpoint: &Commands,
        out: &mut Commands,
    ) -> Result<(), SimError>;
}

/// Outer controller `O` at an integer multiple of the inner controller `I`'s period.
#[derive(Debug)]
pub struct Cascade<O, I> {
    outer: O,
    inner: I,
    setpoint: Commands,
    ratio: u64,
    count: u64,
}

impl<O: Controller, I: InnerController> Cascade<O, I> {
    /// Cascade of `outer` over `inner` for `n` actuators; the outer period must be an integer
    /// multiple of the inner one (relative tolerance 1e-9).
    pub fn new(outer: O, inner: I, n: usize) -> Result<Self, SimError> {
        let r = outer.period() / inner.period();
        let ratio = r.round();
        if !(ratio >= 1.0 && (r - ratio).abs() <= 1e-9 * r) {
            return Err(SimError::InvalidParameter {
                what: "cascade periods".into(),
                reason: format!("outer / inner period = {r} is not a positive integer"),
            });
        }
        let setpoint = Commands::new(outer.mode(), n);
        Ok(Self {
            outer,
            inner,
            setpoint,
            ratio: ratio as u64,
            count: 0,
        })
    }

    /// The outer loop's latest setpoint.
    pub fn setpoint(&self) -> &Commands {
        &self.setpoint
    }

    /// The outer controller.
    pub fn outer(&self) -> &O {
        &self.outer
    }
}

impl<O: Controller, I: InnerController> Controller for Cascade<O, I> {
    fn period(&self) -> f64 {
        self.inner.period()
    }

    fn mode(&self) -> DriveMode {
        self.inner.mode()
    }

    fn update(&mut self, t: f64, s: &Sensors, c: &mut Commands) -> Result<(), SimError> {
        if self.count.is_multiple_of(self.ratio) {
            self.outer.update(t, s, &mut self.setpoint)?;
        }
        self.count += 1;
        self.inner.update(t, s, &self.setpoint, c)
    }
}

/// Inner current loop: current setpoint `i_ref` (or a joint-torque setpoint mapped per
/// actuator as `tau / (k_t n_nominal)`) -> voltage
/// `u = R i_ref + k_e omega + k_p (i_ref - i) + k_i int (i_ref - i)` (feed-forward of the
/// steady-state voltage and back-EMF plus PI). Direct (motorless) joints pass their torque
/// setpoint through. Use a current-output outer loop
/// ([`super::JointPd::with_current_output`]) where motors drive several joints (ankles).
#[derive(Debug, Clone)]
pub struct CurrentPi {
    period: f64,
    kp: f64,
    ki: f64,
    /// Per actuator: `(R, k_e, 1 / (k_t n))`, or `None` for a direct joint.
    motors: Vec<Option<(f64, f64, f64)>>,
    integral: Vec<f64>,
}

impl CurrentPi {
    /// Current PI with gains in V/A and V/(A s) for every motor of `plant`.
    pub fn new(plant: &Plant, period: f64, kp: f64, ki: f64) -> Result<Self, SimError> {
        positive("period", period, false)?;
        positive("kp", kp, true)?;
        positive("ki", ki, true)?;
        let motors = plant
            .actuators()
            .iter()
            .map(|a| {
                (a.transmission != Transmission::Direct).then(|| {
                    (
                        a.motor.resistance,
                        a.motor.back_emf,
                        1.0 / (a.motor.torque_constant * a.nominal_ratio),
                    )
                })
            })
            .collect::<Vec<_>>();
        let integral = vec![0.0; motors.len()];
        Ok(Self {
            period,
            kp,
            ki,
            motors,
            integral,
        })
    }
}

impl InnerController for CurrentPi {
    fn period(&self) -> f64 {
        self.period
    }

    fn mode(&self) -> DriveMode {
        DriveMode::Voltage
    }

    fn update(
        &mut self,
        _t: f64,
        s: &Sensors,
        sp: &Commands,
        out: &mut Commands,
    ) -> Result<(), SimError> {
        let n = self.motors.len();
        if sp.values.len() != n || out.values.len() != n || s.motor_currents.len() != n {
            return Err(SimError::Length {
                what: "current loop vectors",
                got: out.values.len(),
                expected: n,
            });
        }
        for (k, motor) in self.motors.iter().enumerate() {
            let Some((r, ke, scale)) = *motor else {
                out.values[k] = sp.values[k];
                continue;
            };
            let i_ref = match sp.mode {
                DriveMode::Current => sp.values[k],
                _ => sp.values[k] * scale,
            };
            let e = i_ref - s.motor_currents[k];
            self.integral[k] += e * self.period;
            out.values[k] =
                r * i_ref + ke * s.motor_velocities[k] + self.kp * e + self.ki * self.integral[k];
        }
        out.mode = DriveMode::Voltage;
        Ok(())
    }
}
