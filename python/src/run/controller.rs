//! A Python controller in the loop: a callable `controller(t, sensors)` called once per
//! control cycle after the scenario's joint PD, with the sensor sample as a dict of numpy
//! arrays (and the PD's commands under `"commands"`); it returns the actuator commands (an
//! array of one value per actuator, in the order of `sensors["actuators"]`) or `None` to
//! keep the PD's. An exception it raises ends the run and is raised again by `simulate`.

use biped_sim::controller::{Commands, Hook};
use biped_sim::plant::Plant;
use biped_sim::sensors::Sensors;
use biped_sim::SimError;
use numpy::{AllowTypeChange, PyArray1, PyArray2, PyArrayLike1};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use std::sync::{Arc, Mutex};

/// Where the hook leaves the Python exception that stopped a run.
#[derive(Clone, Default)]
pub struct Stash(Arc<Mutex<Option<PyErr>>>);

impl Stash {
    /// Keeps `err` (the first one wins).
    pub fn put(&self, err: PyErr) {
        if let Ok(mut slot) = self.0.lock() {
            slot.get_or_insert(err);
        }
    }

    /// The kept exception, if any.
    pub fn take(&self) -> Option<PyErr> {
        self.0.lock().ok().and_then(|mut slot| slot.take())
    }
}

/// The hook that calls `callback` with the sensors of `plant`, leaving its exceptions in
/// `stash`.
pub fn hook(callback: Py<PyAny>, stash: Stash, plant: &Plant) -> Hook {
    let names: Vec<String> = plant.actuators().iter().map(|a| a.name.clone()).collect();
    let mut tuple: Option<Py<PyTuple>> = None;
    Box::new(move |t, sensors, commands| {
        Python::attach(|py| {
            let names = match &tuple {
                Some(names) => names.bind(py).clone(),
                None => tuple
                    .insert(PyTuple::new(py, &names)?.unbind())
                    .bind(py)
                    .clone(),
            };
            let sample = sensor_dict(py, sensors, commands, names)?;
            let out = callback.call1(py, (t, sample))?;
            write_commands(out.bind(py), commands)
        })
        .map_err(|e| {
            let line = format!("the Python controller failed at t = {t:.4} s: {e}");
            stash.put(e);
            SimError::Controller(line)
        })
    })
}

/// The sensor sample as a dict of arrays.
fn sensor_dict<'py>(
    py: Python<'py>,
    s: &Sensors,
    commands: &Commands,
    names: Bound<'py, PyTuple>,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("t", s.t)?;
    d.set_item("actuators", names)?;
    for (key, values) in [
        ("joint_positions", &s.joint_positions),
        ("joint_velocities", &s.joint_velocities),
        ("motor_positions", &s.motor_positions),
        ("motor_velocities", &s.motor_velocities),
        ("motor_currents", &s.motor_currents),
        ("commands", &commands.values),
    ] {
        d.set_item(key, PyArray1::from_slice(py, values))?;
    }
    let wrenches: Vec<Vec<f64>> = s
        .foot_wrenches
        .iter()
        .map(|w| vec![w.lin.x, w.lin.y, w.lin.z, w.ang.x, w.ang.y, w.ang.z])
        .collect();
    d.set_item("foot_wrenches", PyArray2::from_vec2(py, &wrenches)?)?;
    match &s.imu {
        Some(imu) => {
            let q = imu.orientation.quaternion();
            let quat = [q.w, q.i, q.j, q.k];
            d.set_item("imu_orientation", PyArray1::from_slice(py, &quat))?;
            let w = imu.angular_velocity;
            d.set_item(
                "imu_angular_velocity",
                PyArray1::from_slice(py, w.as_slice()),
            )?;
            let a = imu.linear_acceleration;
            d.set_item(
                "imu_linear_acceleration",
                PyArray1::from_slice(py, a.as_slice()),
            )?;
        }
        None => {
            for key in [
                "imu_orientation",
                "imu_angular_velocity",
                "imu_linear_acceleration",
            ] {
                d.set_item(key, py.None())?;
            }
        }
    }
    Ok(d)
}

/// Copies the callback's return value into `commands` (`None` keeps them).
fn write_commands(out: &Bound<'_, PyAny>, commands: &mut Commands) -> PyResult<()> {
    if out.is_none() {
        return Ok(());
    }
    let n = commands.values.len();
    let bad = || {
        crate::error::biped_err(format!(
            "controller: expected None or {n} commands (one per actuator), got {}",
            out.repr().map_or_else(|_| "?".into(), |r| r.to_string())
        ))
    };
    let array: PyArrayLike1<f64, AllowTypeChange> = out.extract().map_err(|_| bad())?;
    let values = array.as_array();
    if values.len() != n {
        return Err(bad());
    }
    if let Some(i) = values.iter().position(|x| !x.is_finite()) {
        return Err(crate::error::biped_err(format!(
            "controller: command {i} ({}) is not finite",
            values[i]
        )));
    }
    commands
        .values
        .iter_mut()
        .zip(values.iter())
        .for_each(|(c, v)| *c = *v);
    Ok(())
}
