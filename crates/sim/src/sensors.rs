//! Sensor data given to the controller each control period (Fig. 2.1): joint
//! encoders, motor encoders, motor currents, foot force/torque sensors and an IMU on the
//! floating base.
//!
//! Choices, documented: the F/T sensor reports the ground wrench on the foot in the foot body
//! frame about the body origin (no foot inertia between sole and sensor). Motor encoders read
//! `N q` for rigid gears, the motor coordinate for Type 3, and an incremental count starting
//! at 0 for roller-screw rotors (trapezoidal integral of the motor speed between samples).
//! The IMU's linear acceleration is the specific force `A^T (a - g)` with `a` the mean
//! acceleration of the base origin over the last control period (difference of velocities),
//! which avoids an extra dynamics evaluation per period; at the first sample `a = 0`.
//!
//! A sample runs the plant's state pass ([`Plant::state_outputs`]): F/T and drive readings are
//! those a right-hand side at that state computes, and the kinematics pass it leaves in the
//! plant's workspace serves the recorder and the first integration stage of the period.

use crate::drive::{DriveMode, Transmission};
use crate::error::SimError;
use crate::plant::Plant;
use biped_dynamics::Wrench;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// IMU reading on the floating base.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Imu {
    /// Base orientation (body -> world).
    pub orientation: UnitQuaternion<f64>,
    /// Angular velocity in the base frame \[rad/s].
    pub angular_velocity: Vector3<f64>,
    /// Specific force in the base frame \[m/s^2] (reads `+9.81 z` at rest, upright).
    pub linear_acceleration: Vector3<f64>,
}

/// One sample of all sensors.
#[derive(Debug, Clone)]
pub struct Sensors {
    /// Sample time \[s].
    pub t: f64,
    /// Joint encoder angles, one per actuator \[rad].
    pub joint_positions: Vec<f64>,
    /// Joint velocities, one per actuator \[rad/s].
    pub joint_velocities: Vec<f64>,
    /// Motor encoder angles, one per actuator \[rad].
    pub motor_positions: Vec<f64>,
    /// Motor speeds, one per actuator \[rad/s].
    pub motor_velocities: Vec<f64>,
    /// Motor currents \[A] (commanded, integrated, or estimated from the torque).
    pub motor_currents: Vec<f64>,
    /// F/T wrenches, one per contact entry in the order of the plant's contact specs (feet and
    /// their parts such as toes: each on its own body, body frame, moment about the body origin).
    pub foot_wrenches: Vec<Wrench>,
    /// IMU on the floating base (`None` without a floating base).
    pub imu: Option<Imu>,
    /// Previous sample time and base-origin velocity (world), for the IMU acceleration.
    prev: Option<(f64, Vector3<f64>)>,
}

impl Sensors {
    /// Buffers sized for `plant`.
    pub fn new(plant: &Plant) -> Self {
        let n = plant.actuators().len();
        Self {
            t: 0.0,
            joint_positions: vec![0.0; n],
            joint_velocities: vec![0.0; n],
            motor_positions: vec![0.0; n],
            motor_velocities: vec![0.0; n],
            motor_currents: vec![0.0; n],
            foot_wrenches: vec![Wrench::zero(); plant.contact().nfeet()],
            imu: None,
            prev: None,
        }
    }

    /// Samples the sensors at `(t, z)` with the plant's held command.
    pub fn update(&mut self, plant: &mut Plant, t: f64, z: &[f64]) -> Result<(), SimError> {
        let l = plant.layout();
        let dt = self.prev.map_or(0.0, |(tp, _)| t - tp);
        plant.state_outputs(z)?;
        let (q, v) = (&z[l.q()], &z[l.v()]);
        let mode = plant.mode();
        for (k, a) in plant.actuators().iter().enumerate() {
            let d = plant.last_outputs().drives[k];
            self.joint_positions[k] = q[a.joint_q];
            self.joint_velocities[k] = v[a.joint_v];
            self.motor_positions[k] = match a.transmission {
                Transmission::Direct => q[a.joint_q],
                Transmission::Gear { ratio } => ratio * q[a.joint_q],
                Transmission::Elastic { motor_q, .. } => q[motor_q],
                Transmission::Rotor { .. } => {
                    self.motor_positions[k] + 0.5 * (self.motor_velocities[k] + d.speed) * dt
                }
            };
            self.motor_velocities[k] = d.speed;
            self.motor_currents[k] = if mode == DriveMode::Voltage {
                z[l.currents().start + k]
            } else {
                d.current
            };
        }
        for (k, body) in plant.contact().bodies().enumerate() {
            self.foot_wrenches[k] = plant.external_wrenches()[body];
        }
        self.imu = plant.floating_base().map(|(qi, vi)| {
            let quat = Quaternion::new(q[qi + 6], q[qi + 3], q[qi + 4], q[qi + 5]);
            let rot = UnitQuaternion::new_normalize(quat);
            let vel = rot * Vector3::new(v[vi], v[vi + 1], v[vi + 2]);
            let acc = match self.prev {
                Some((_, pv)) if dt > 0.0 => (vel - pv) / dt,
                _ => Vector3::zeros(),
            };
            self.prev = Some((t, vel));
            Imu {
                orientation: rot,
                angular_velocity: Vector3::new(v[vi + 3], v[vi + 4], v[vi + 5]),
                linear_acceleration: rot.inverse() * (acc - plant.model().gravity()),
            }
        });
        if self.imu.is_none() {
            self.prev = Some((t, Vector3::zeros()));
        }
        self.t = t;
        Ok(())
    }
}
