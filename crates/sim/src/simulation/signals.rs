//! Named signals of a frame for the recorder: `q[i]`, `v[i]`, per foot the ground wrench
//! (`<foot>.fx .. <foot>.tz`, world axes, torque about the sole reference point) and the
//! centre of pressure, per actuator the command `cmd[<joint>]` and the motor current
//! `i[<joint>]`, and optionally the CoM and the centroidal angular momentum `L_G` about it
//! (one kinematics pass per recorded frame, [`super::momentum`]).

use super::Frame;
use crate::error::SimError;
use crate::plant::Plant;
use crate::record::{Recorder, SignalId};
use biped_dynamics::centroidal_momentum;
use biped_dynamics::{Data, Model};
use nalgebra::DVector;

/// Own model copy, workspace and `(q, v)` buffers for the centroidal momentum.
type MomentumWork = (Model, Data, DVector<f64>, DVector<f64>);

/// Signal names and a reusable value buffer (own kinematics workspace for `L_G`).
pub struct Signals {
    names: Vec<String>,
    ids: Vec<SignalId>,
    values: Vec<f64>,
    momentum: Option<MomentumWork>,
}

impl Signals {
    /// Signals of `plant`; `momentum` adds `com.*` and `L_G.*` (one kinematics pass per
    /// recorded frame).
    pub fn new(plant: &Plant, momentum: bool) -> Self {
        let l = plant.layout();
        let mut names: Vec<String> = (0..l.nq).map(|i| format!("q[{i}]")).collect();
        names.extend((0..l.nv).map(|i| format!("v[{i}]")));
        for f in plant.contact().specs() {
            for c in ["fx", "fy", "fz", "tx", "ty", "tz", "cop_x", "cop_y"] {
                names.push(format!("{}.{c}", f.name));
            }
        }
        for a in plant.actuators() {
            names.push(format!("cmd[{}]", a.name));
        }
        for a in plant.actuators() {
            names.push(format!("i[{}]", a.name));
        }
        let momentum = momentum.then(|| {
            names.extend(["com.x", "com.y", "com.z", "L_G.x", "L_G.y", "L_G.z"].map(String::from));
            let m = plant.model().clone();
            let d = Data::new(&m);
            (m, d, DVector::zeros(l.nq), DVector::zeros(l.nv))
        });
        let values = Vec::with_capacity(names.len());
        Self {
            names,
            ids: Vec::new(),
            values,
            momentum,
        }
    }

    /// Signal names, in value order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Values of `frame`, in name order.
    pub fn values(&mut self, frame: &Frame) -> Result<&[f64], SimError> {
        let l = frame.plant.layout();
        let v = &mut self.values;
        v.clear();
        v.extend_from_slice(&frame.z[l.q()]);
        v.extend_from_slice(&frame.z[l.v()]);
        for f in &frame.plant.last_outputs().contact.feet {
            let cop = f.cop.unwrap_or_default();
            v.extend_from_slice(&[
                f.force.x, f.force.y, f.force.z, f.torque.x, f.torque.y, f.torque.z, cop.x, cop.y,
            ]);
        }
        v.extend_from_slice(&frame.commands.values);
        v.extend_from_slice(&frame.sensors.motor_currents);
        if let Some((m, d, q, qd)) = self.momentum.as_mut() {
            q.as_mut_slice().copy_from_slice(&frame.z[l.q()]);
            qd.as_mut_slice().copy_from_slice(&frame.z[l.v()]);
            let s = centroidal_momentum(m, d, q, qd)?;
            let (com, h) = (s.com, s.momentum);
            v.extend_from_slice(&[com.x, com.y, com.z, h.ang.x, h.ang.y, h.ang.z]);
        }
        Ok(&self.values)
    }

    /// Appends one row at `frame.t` to `rec` with every signal (registered as scalar columns
    /// on the first call; later calls only write by id).
    pub fn record(&mut self, frame: &Frame, rec: &mut Recorder) -> Result<(), SimError> {
        let out = |e: crate::record::RecordError| SimError::Output(e.to_string());
        if self.ids.is_empty() {
            for n in &self.names {
                self.ids.push(rec.register(n).map_err(out)?);
            }
        }
        rec.sample(frame.t).map_err(out)?;
        self.values(frame)?;
        for (id, v) in self.ids.iter().zip(&self.values) {
            rec.set_id(*id, std::slice::from_ref(v)).map_err(out)?;
        }
        Ok(())
    }
}
