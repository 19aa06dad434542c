//! Drive-coordinate rows of coupled parts read back from the loop caches of the last
//! kinematics pass (thesis 3.1-3.3: motor rate `omega_m = n(q) qdot`, (3.1), (3.5), (3.32)).
//!
//! Validity rule: the caches are keyed by each drive's exact input values, so
//! [`Data::coupled_spin_row`] is always correct for the `q` it is given; it costs a few
//! comparisons when the last pass that evaluated coupled kinematics (forward kinematics, the
//! first phase of forward dynamics, ...) used the same input coordinates, and one loop
//! closure (no allocation) otherwise (also when a model has more than
//! [`super::cache::LOOP_SLOTS`] drives of one type and the oldest loops were evicted).

use super::{Coupling, MechanismError, MAX_COUPLED};
use crate::model::{JointModel, Mechanism};
use crate::{BodyId, Data, Model};

const NAME: &str = "coupled spin row";

impl Data {
    /// Part-frame z (spin) row of coupled body `body`'s relative Jacobian at `q`: coefficient
    /// `k` multiplies the velocity of the part's `k`-th input (order of
    /// [`JointModel::Coupled::inputs`], v index `model.body(body).v_set()[k]`); unused entries
    /// are zero. For a motor rotor this is the motor-rate row, so the motor speed is
    /// `sum_k row[k] v[v_set[k]]` ((3.1) Harmonic Drive, (3.5) knee screw, (3.32) ankle).
    pub fn coupled_spin_row(
        &self,
        model: &Model,
        body: BodyId,
        q: &[f64],
    ) -> Result<[f64; MAX_COUPLED], MechanismError> {
        let bad = |reason: String| MechanismError::BadInput {
            mechanism: NAME,
            reason,
        };
        let b = model
            .body(body)
            .ok_or_else(|| bad(format!("no body #{body}")))?;
        let JointModel::Coupled { mechanism, .. } = b.joint() else {
            return Err(bad(format!("body #{body} is not a coupled part")));
        };
        let set = b.q_set().as_slice();
        let mut qin = [0.0; MAX_COUPLED];
        for (x, &k) in qin.iter_mut().zip(set) {
            *x = *q
                .get(k)
                .ok_or_else(|| bad(format!("q has {} entries, needs {}", q.len(), k + 1)))?;
        }
        let qin = &qin[..set.len().min(MAX_COUPLED)];
        let mut row = [0.0; MAX_COUPLED];
        match mechanism {
            Mechanism::Ankle(part) => {
                row[..2].copy_from_slice(&part.spin_row_cached(qin, self.ankle_loop.as_ref())?)
            }
            Mechanism::Knee(part) => row[0] = part.spin_row_cached(qin, self.knee_loop.as_ref())?,
            other => {
                let m = other.motion(qin, &[0.0; MAX_COUPLED][..qin.len()])?;
                for (r, col) in row.iter_mut().zip(&m.jacobian) {
                    *r = col[2];
                }
            }
        }
        Ok(row)
    }
}
