//! The plant's right-hand side (2.2)-(2.4) and its force layers.
//!
//! Right-hand side: [`biped_dynamics::forward_dynamics_kinematics`] (first forward recursion:
//! body poses, velocities, mechanism loops), then contact forces from the foot poses and
//! velocities of that pass, drive and gear torques (roller-screw motor rows read from the
//! loops that pass closed, [`crate::drive::Actuator::motor_row_cached`]), then
//! [`biped_dynamics::forward_dynamics_solve`]. So one evaluation runs one kinematics pass.
//!
//! [`Plant::state_outputs`] (the sensors' sample) runs the same first half, the state pass:
//! the kinematics it leaves in the plant's workspace serve the recorder (CoM, `h_G`) and are
//! reused by the first Runge-Kutta stage at that state (`forward_dynamics_kinematics` skips a
//! pass at the `(q, v)` it holds), and so are its contact forces and bristle rates
//! ([`ContactMemo`]: the contact layer depends on `q`, `v` and the bristle states only, not on
//! the command the controller sets in between). [`Plant::outputs`] (contact and drive outputs for other
//! users) takes the foot states from each foot's own joint chain
//! ([`crate::contact::BodyChain`]) instead, cheaper than a pass over all bodies when nothing
//! else reads it; its motor rows miss the loop caches and close the loops once. `tests/sim_fastpath.rs` checks both routes
//! against a reference assembled from the general parts (chains, rows re-evaluated from the
//! mechanisms, `forward_dynamics` in one call).

use super::{Plant, PlantOutputs, StateLayout};
use crate::drive::DriveMode;
use crate::error::SimError;
use biped_dynamics::{forward_dynamics_kinematics, forward_dynamics_solve};

/// One of the force routes (`chain_forces`, `pass_forces`): state `z`, rates into `zdot`.
type ForcePass = fn(&mut Plant, &[f64], &mut [f64]) -> Result<(), SimError>;

impl Plant {
    /// Contact and drive outputs at `z` with the held command from the foot chains (no
    /// dynamics call, the plant's workspace untouched); the contact-state rates computed on the
    /// way are discarded.
    pub fn outputs(&mut self, z: &[f64]) -> Result<&PlantOutputs, SimError> {
        self.contact_memo.clear();
        self.with_scratch(z, Self::chain_forces)
    }

    /// Contact and drive outputs at `z` with the held command from the forward-dynamics
    /// kinematics pass on the plant's workspace (the state pass, no solve): the same values a
    /// right-hand side at `z` gives. The pass stays in [`Self::data`] for readers (CoM,
    /// momentum) and for the next right-hand side at `z`, which reuses it.
    pub fn state_outputs(&mut self, z: &[f64]) -> Result<&PlantOutputs, SimError> {
        self.contact_memo.clear();
        let mut scratch = std::mem::take(&mut self.scratch);
        let r = self.pass_forces(z, &mut scratch);
        if r.is_ok() {
            self.contact_memo.store(self.layout, z, &scratch);
        }
        self.scratch = scratch;
        r.map(|_| &self.out)
    }

    /// Runs `forces` at `z` with the scratch rate buffer; the outputs.
    fn with_scratch(&mut self, z: &[f64], forces: ForcePass) -> Result<&PlantOutputs, SimError> {
        let mut scratch = std::mem::take(&mut self.scratch);
        let r = forces(self, z, &mut scratch);
        self.scratch = scratch;
        r.map(|_| &self.out)
    }

    /// Checks the lengths of `z` and `zdot` and copies `q`, `v` of `z` into the work vectors.
    fn load(&mut self, z: &[f64], zdot: &[f64]) -> Result<(), SimError> {
        if zdot.len() != self.layout.dim() {
            return Err(SimError::Length {
                what: "zdot",
                got: zdot.len(),
                expected: self.layout.dim(),
            });
        }
        self.load_state(z)
    }

    /// Checks the length of `z` and copies its `q`, `v` into the work vectors.
    pub(crate) fn load_state(&mut self, z: &[f64]) -> Result<(), SimError> {
        let l = self.layout;
        if z.len() != l.dim() {
            return Err(SimError::Length {
                what: "z",
                got: z.len(),
                expected: l.dim(),
            });
        }
        self.q.as_mut_slice().copy_from_slice(&z[l.q()]);
        self.v.as_mut_slice().copy_from_slice(&z[l.v()]);
        Ok(())
    }

    /// Contact forces from the foot chains, then drive and gear torques (the general route,
    /// no dynamics workspace involved); contact and current rates into `zdot`.
    pub(super) fn chain_forces(&mut self, z: &[f64], zdot: &mut [f64]) -> Result<(), SimError> {
        self.load(z, zdot)?;
        let l = self.layout;
        let (q, v) = (self.q.as_slice(), self.v.as_slice());
        let (s, sdot) = (&z[l.contact()], &mut zdot[l.contact()]);
        let out = &mut self.out.contact;
        self.contact.evaluate(q, v, s, sdot, &mut self.fext, out);
        self.drive_forces(z, zdot, false)
    }

    /// Drive torques of every actuator, elastic gear torques and the passive joint layer
    /// (end stops, joint friction) into `tau`; current rates into
    /// `zdot` in voltage mode. `tau` starts from the direct forces of the held commands and
    /// each drive adds its motor-row forces from its hold ([`crate::drive::Actuator::forces`];
    /// in voltage mode the hold is redone at the state's current first). Motor rows of
    /// roller-screw rotors are refreshed at `q` by
    /// [`crate::drive::Actuator::motor_row_cached`]: a cache hit after the kinematics pass of a
    /// right-hand side, one closed-form loop closure otherwise (always correct for `q`), unless
    /// `rows_at_q`: the last pass was the state pass at this `q` (a [`ContactMemo`] hit), whose
    /// rows are still in place.
    fn drive_forces(
        &mut self,
        z: &[f64],
        zdot: &mut [f64],
        rows_at_q: bool,
    ) -> Result<(), SimError> {
        let l = self.layout;
        let (q, v) = (self.q.as_slice(), self.v.as_slice());
        let tau = self.tau.as_mut_slice();
        tau.copy_from_slice(&self.tau_held);
        let mode = self.config.mode;
        let voltage = mode == DriveMode::Voltage;
        let currents = l.currents().start;
        let held = self.holds.iter_mut().zip(&self.laws).zip(&self.commands);
        let drives = self.actuators.iter().zip(self.rows.iter_mut()).zip(held);
        for (k, ((a, row), ((hold, law), &cmd))) in drives.enumerate() {
            if a.row_varies() && !rows_at_q {
                a.refresh_motor_row(&self.model, &self.data, q, row)?;
            }
            if voltage {
                *hold = a.hold(law, mode, cmd, z[currents + k], row.is_some());
            }
            let ds = a.forces(hold, law, row.as_ref(), v, tau);
            if voltage {
                zdot[currents + k] = ds.current_rate;
            }
            self.out.drives[k] = ds;
        }
        let k = self.config.gear_stiffness;
        for (g, &d) in self.gears.iter().zip(&self.gear_damping) {
            let torque = k * (q[g.motor_q] / g.ratio - q[g.link_q])
                + d * (v[g.motor_v] / g.ratio - v[g.link_v]);
            tau[g.link_v] += torque;
            tau[g.motor_v] -= torque / g.ratio;
        }
        self.passive.apply(q, v, tau);
        Ok(())
    }

    /// The state pass at `z`: the forward-dynamics kinematics on the plant's workspace (skipped
    /// when it already holds `z`'s `(q, v)`), contact forces from its foot states, then drive and
    /// gear torques; contact and current rates into `zdot`.
    pub(super) fn pass_forces(&mut self, z: &[f64], zdot: &mut [f64]) -> Result<(), SimError> {
        self.load(z, zdot)?;
        let l = self.layout;
        forward_dynamics_kinematics(&self.model, &mut self.data, &self.q, &self.v)?;
        let (s, sdot) = (&z[l.contact()], &mut zdot[l.contact()]);
        let recalled = self.contact_memo.recall(l, z, sdot);
        if !recalled {
            let out = &mut self.out.contact;
            self.contact
                .evaluate_from(&self.data, s, sdot, &mut self.fext, out);
        }
        self.drive_forces(z, zdot, recalled)
    }

    /// The right-hand side with typed errors (one kinematics pass, see the module docs).
    pub(super) fn eval(&mut self, z: &[f64], zdot: &mut [f64]) -> Result<(), SimError> {
        self.rhs_count += 1;
        let r = self.pass_forces(z, zdot);
        self.contact_memo.clear();
        r?;
        let l = self.layout;
        let (m, algo) = (&self.model, self.config.algorithm);
        // A non-finite qddot is an error of the solve itself.
        let ddq = forward_dynamics_solve(m, &mut self.data, &self.tau, Some(&self.fext), algo)?;
        zdot[l.v()].copy_from_slice(ddq.as_slice());
        self.qdot.qdot(&z[l.q()], &z[l.v()], &mut zdot[l.q()]);
        Ok(())
    }
}

/// The contact layer's result at the last state pass ([`Plant::state_outputs`]), recalled by
/// the next right-hand side at bitwise the same `q`, `v` and bristle states (the first
/// Runge-Kutta stage after a sensor sample) instead of evaluating the contact points again. Its
/// forces are still in the plant's `fext` and outputs, and its roller-screw motor rows in the
/// plant's rows: every other writer of them clears it.
#[derive(Debug, Clone, Default)]
pub(super) struct ContactMemo {
    /// `[q | v | s]` of the state pass; empty when cleared.
    key: Vec<f64>,
    /// The bristle rates computed there.
    rates: Vec<f64>,
}

impl ContactMemo {
    /// Forgets the stored result (keeps the buffers).
    pub(super) fn clear(&mut self) {
        self.key.clear();
    }

    /// Stores the key of `z` and the bristle rates of `zdot` (no allocation after the first).
    fn store(&mut self, l: StateLayout, z: &[f64], zdot: &[f64]) {
        let c = l.contact();
        self.key.clear();
        self.key.extend_from_slice(&z[..c.end]);
        self.rates.clear();
        self.rates.extend_from_slice(&zdot[c]);
    }

    /// Writes the stored rates into `sdot` if `z` has the stored key; false otherwise.
    fn recall(&self, l: StateLayout, z: &[f64], sdot: &mut [f64]) -> bool {
        let key = &z[..l.contact().end];
        let same = self.key.len() == key.len()
            && self
                .key
                .iter()
                .zip(key)
                .all(|(a, b)| a.to_bits() == b.to_bits());
        if same {
            sdot.copy_from_slice(&self.rates);
        }
        same
    }
}
