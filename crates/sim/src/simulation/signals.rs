//! Named signals of a frame for the recorder: `q[<coordinate>]`, `v[<coordinate>]` (joint
//! names, [`biped_dynamics::Model::q_names`]), per foot the ground wrench
//! (`<foot>.fx .. <foot>.tz`, world axes, torque about the sole reference point) and the
//! centre of pressure, per actuator the held command `cmd[<joint>]` (within the drive limits)
//! and the motor current
//! `i[<joint>]`, and optionally the CoM and the centroidal angular momentum `L_G` about it
//! ([`biped_dynamics::centroidal_momentum`]). Those are read from the forward-dynamics pass the
//! plant's workspace holds when it is at the frame's `(q, v)` (the sensors' state pass,
//! [`Plant::state_outputs`], leaves it there every control cycle), so recording adds no
//! kinematics pass; otherwise a pass on an own workspace gives the same values bit for bit.

use super::Frame;
use crate::error::SimError;
use crate::plant::Plant;
use crate::record::{Recorder, SignalId};
use biped_dynamics::dynamics::forward_dynamics_kinematics_current;
use biped_dynamics::{centroidal_momentum, centroidal_momentum_current, CentroidalMomentum, Data};
use nalgebra::DVector;

/// Own workspace and `(q, v)` buffers for the centroidal momentum when the plant's is elsewhere.
type MomentumWork = (Data, DVector<f64>, DVector<f64>);

/// Signal names and a reusable value buffer (own kinematics workspace for `L_G`).
pub struct Signals {
    names: Vec<String>,
    ids: Vec<SignalId>,
    /// The ids are consecutive columns (the usual case): a row is written as one block.
    block: bool,
    values: Vec<f64>,
    momentum: Option<MomentumWork>,
}

impl Signals {
    /// Signals of `plant`; `momentum` adds `com.*` and `L_G.*` (see the module docs).
    pub fn new(plant: &Plant, momentum: bool) -> Self {
        let l = plant.layout();
        let model = plant.model();
        let mut names: Vec<String> = model.q_names().iter().map(|n| format!("q[{n}]")).collect();
        names.extend(model.v_names().iter().map(|n| format!("v[{n}]")));
        debug_assert_eq!(names.len(), l.nq + l.nv);
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
            let d = Data::new(plant.model());
            (d, DVector::zeros(l.nq), DVector::zeros(l.nv))
        });
        let values = Vec::with_capacity(names.len());
        Self {
            names,
            ids: Vec::new(),
            block: false,
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
        if let Some(work) = self.momentum.as_mut() {
            let s = frame_momentum(frame, work)?;
            let (com, h) = (s.com, s.momentum);
            v.extend_from_slice(&[com.x, com.y, com.z, h.ang.x, h.ang.y, h.ang.z]);
        }
        Ok(&self.values)
    }

    /// Registers every signal in `rec` as scalar columns (done by the first [`Self::record`]
    /// otherwise; call it before a timed loop to size the recorder up front, e.g. for
    /// [`Recorder::prefault`]). Idempotent.
    pub fn register(&mut self, rec: &mut Recorder) -> Result<(), SimError> {
        let out = |e: crate::record::RecordError| SimError::Output(e.to_string());
        self.ids.clear();
        for n in &self.names {
            self.ids.push(rec.register(n).map_err(out)?);
        }
        let first = self.ids.first().map_or(0, |id| id.column());
        self.block = (self.ids.iter().enumerate()).all(|(k, id)| id.column() == first + k);
        Ok(())
    }

    /// Appends one row at `frame.t` to `rec` with every signal (registered as scalar columns
    /// on the first call; later calls only write by id).
    pub fn record(&mut self, frame: &Frame, rec: &mut Recorder) -> Result<(), SimError> {
        let out = |e: crate::record::RecordError| SimError::Output(e.to_string());
        if self.ids.is_empty() {
            self.register(rec)?;
        }
        rec.sample(frame.t).map_err(out)?;
        self.values(frame)?;
        if let Some(&first) = self.ids.first().filter(|_| self.block) {
            return rec.set_id(first, &self.values).map_err(out);
        }
        for (id, v) in self.ids.iter().zip(&self.values) {
            rec.set_id(*id, std::slice::from_ref(v)).map_err(out)?;
        }
        Ok(())
    }
}

/// CoM and `h_G` at the frame's state: from the plant's workspace when it holds the
/// forward-dynamics pass at exactly that `(q, v)`, else by a pass on `work`.
fn frame_momentum(frame: &Frame, work: &mut MomentumWork) -> Result<CentroidalMomentum, SimError> {
    let l = frame.plant.layout();
    let (q, v) = (&frame.z[l.q()], &frame.z[l.v()]);
    let (model, data) = (frame.plant.model(), frame.plant.data());
    if forward_dynamics_kinematics_current(data, q, v) {
        return Ok(centroidal_momentum_current(model, data)?);
    }
    let (d, qw, vw) = work;
    qw.as_mut_slice().copy_from_slice(q);
    vw.as_mut_slice().copy_from_slice(v);
    Ok(centroidal_momentum(model, d, qw, vw)?)
}
