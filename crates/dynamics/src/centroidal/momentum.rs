//! Centre of mass and centroidal momentum `h_G = [L_G; p]` (7.1) from the first pass of the
//! forward dynamics ([`crate::forward_dynamics_kinematics`]), without the rotor kinematics it
//! skips and without `A_G`.
//!
//! `h_G = sum_i X_G,i^* M_i v_i`: each body's momentum (2.22) moved to the CoM, which equals
//! `A_G v` of (7.2) (both are the total momentum of the same body velocities). Ordinary bodies
//! use their world pose and velocity from the pass. A spin-invariant Harmonic Drive rotor
//! (3.1)-(3.2) (`subsystem::axial`) has no pose there; its momentum is formed in
//! its carrier's (parent's) frame from constants of the model: CoM `c` fixed in the carrier,
//! inertia `I_c` about it constant in carrier axes (axisymmetry), so with the carrier velocity
//! `[w_p; v_p]` and the spin column `s` (`s.ang = N` times the axis, carrier axes) its linear
//! momentum is `m (v_p + w_p x c)` and its angular momentum about its CoM
//! `I_c (w_p + s.ang qd)` (carrier motion plus the spin term `I N qd` about the axis).
//! Rotors without that symmetry are ordinary bodies of the pass (the general path). The ankle's
//! roller-screw rotors and nuts (axial members, `subsystem::axial`) are formed the same way from
//! the spin rate or the travel the pass recorded (a nut's CoM moves along its axis).
//!
//! Summed by carrier ([`MomentumTable`], built in `Data::new`): the rigid part `M v_p` of
//! every member whose CoM is fixed in its carrier is the carrier's velocity times their summed
//! inertia, so each carrier's inertia and its rotors' and screws' are lumped once per model;
//! per pass a group adds its members' spin terms `u qd` and its sliding nuts' momenta, all in
//! its frame, and is rotated to the world once (not once per member). Massless frames without
//! members are left out (exact zeros).

use crate::jacobian::JacobianError;
use crate::model::Body;
use crate::spatial::{ArticulatedInertia, RigidInertia};
use crate::subsystem::axial::{AxialKind, AxialMember};
use crate::{forward_dynamics_kinematics, Data, Force, Model};
use nalgebra::{DVector, Vector3};
use std::ops::Range;

/// Total mass, centre of mass and centroidal momentum `h_G` (world axes), (7.1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CentroidalMomentum {
    /// Total mass `m = sum_i m_i`.
    pub mass: f64,
    /// Centre of mass `r_C` in world coordinates.
    pub com: Vector3<f64>,
    /// `h_G = [L_G; p]`: angular momentum about the CoM and linear momentum, world axes.
    pub momentum: Force,
}

/// CoM and `h_G` at `(q, v)`: runs [`forward_dynamics_kinematics`] into `data`, then
/// [`centroidal_momentum_current`]. `data` then holds that pass (a following
/// [`crate::forward_dynamics_solve`] may use it).
pub fn centroidal_momentum(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> Result<CentroidalMomentum, JacobianError> {
    forward_dynamics_kinematics(model, data, q, v)?;
    centroidal_momentum_current(model, data)
}

/// CoM and `h_G` from the kinematics of the last [`forward_dynamics_kinematics`] on `data`
/// (its `q`, `v`); [`crate::DynamicsError::KinematicsNotCurrent`] if another kinematics call
/// came since, [`JacobianError::ZeroMass`] for a massless model.
pub fn centroidal_momentum_current(
    model: &Model,
    data: &Data,
) -> Result<CentroidalMomentum, JacobianError> {
    crate::check::data(model, data)?;
    if !data.fd_kinematics {
        return Err(crate::DynamicsError::KinematicsNotCurrent.into());
    }
    // One pass about a reference point near the bodies (the first body's origin, so no
    // cancellation far from the world origin), then the shift to the CoM: L_G = L_r - (G - r) x p.
    let r = data
        .world_pos
        .first()
        .copied()
        .unwrap_or_else(Vector3::zeros);
    let table = &data.momentum_table;
    let (mut mass, mut moment) = (0.0, Vector3::zeros());
    let (mut ang, mut lin) = (Vector3::zeros(), Vector3::zeros());
    for g in &table.groups {
        let (m, first, h) = group_momentum(g, &table.members, data);
        // `h` about the frame origin, first moment `m c` in frame coordinates.
        let (rot, d) = (&data.world_rot[g.body], data.world_pos[g.body] - r);
        let p = rot * h.lin;
        mass += m;
        moment += d * m + rot * first;
        lin += p;
        ang += rot * h.ang + d.cross(&p);
    }
    if mass <= 0.0 {
        return Err(JacobianError::ZeroMass);
    }
    let com_r = moment / mass;
    ang -= com_r.cross(&lin);
    Ok(CentroidalMomentum {
        mass,
        com: r + com_r,
        momentum: Force::new(ang, lin),
    })
}

/// Mass, first moment and momentum about the frame origin (frame axes) of group `g`: its
/// lumped constant inertia at the body's velocity plus its members' spin and sliding terms.
#[inline]
fn group_momentum(g: &MomentumGroup, members: &[usize], data: &Data) -> (f64, Vector3<f64>, Force) {
    let vel = &data.vel[g.body];
    let l = &g.lumped;
    let mut h = l.apply(vel);
    let (mut mass, mut first) = (l.mass(), l.first_moment());
    for &j in members.get(g.members.clone()).unwrap_or_default() {
        let Some(rc) = &data.axial_member[j] else {
            continue;
        };
        let (c, qd, _) = rc.state(data, j);
        h.ang += rc.spin_momentum * qd;
        if rc.kind == AxialKind::Slider {
            // Not lumped: its CoM `c` slides along `s.lin` at `qd`.
            let lin = (vel.lin + vel.ang.cross(&c) + rc.s.lin * qd) * rc.mass;
            h += Force::new(rc.inertia_com * vel.ang + c.cross(&lin), lin);
            mass += rc.mass;
            first += c * rc.mass;
        }
    }
    (mass, first, h)
}

/// One summand of the centroidal momentum: a body with a pose in the forward-dynamics pass,
/// its inertia with its constant-CoM axial members' merged in, and the range of its members in [`MomentumTable::members`].
#[derive(Clone, Debug)]
struct MomentumGroup {
    /// The body (its pose and velocity are the group's).
    body: usize,
    /// Body plus its constant-CoM axial members (frame coordinates).
    lumped: RigidInertia,
    /// Its axial members with per-pass terms (spin, or sliding travel and rate).
    members: Range<usize>,
}

/// Per-model constants of [`centroidal_momentum_current`]: the bodies posed by the
/// forward-dynamics pass, each with the axial members it carries (their rotors' momentum
/// `M v_p + u qd` in its frame, see the module doc) lumped in, so that one rotation to the world
/// serves the group.
#[derive(Clone, Debug, Default)]
pub(crate) struct MomentumTable {
    /// The groups in body order.
    groups: Vec<MomentumGroup>,
    /// Member bodies of all groups, each group's contiguous.
    members: Vec<usize>,
}

impl MomentumTable {
    /// The table of `model` with its axial members `axial` ([`Data::axial_member`]).
    pub(crate) fn new(model: &Model, axial: &[Option<AxialMember>]) -> Self {
        let joins = joined_groups(model, axial);
        let mut table = Self::default();
        for (i, body) in model.bodies.iter().enumerate() {
            if joins[i].is_none() {
                table.push_group(i, body, axial, &joins);
            }
        }
        table
    }

    /// Adds the group of body `i` with the members that join it (`joins`), unless it is a
    /// massless frame without members (a sole or tool frame: its terms are exact zeros).
    fn push_group(
        &mut self,
        i: usize,
        body: &Body,
        axial: &[Option<AxialMember>],
        joins: &[Option<usize>],
    ) {
        let mut lumped = body.inertia;
        let start = self.members.len();
        for (j, rc) in axial.iter().enumerate() {
            if let (Some(rc), true) = (rc, joins[j] == Some(i)) {
                if rc.kind != AxialKind::Slider {
                    let part = RigidInertia::from_parts(rc.mass, rc.com, rc.inertia_com);
                    lumped = lumped.add_shifted(&part, &Vector3::zeros());
                }
                self.members.push(j);
            }
        }
        let members = start..self.members.len();
        if !(members.is_empty() && lumped.to_articulated() == ArticulatedInertia::zero()) {
            self.groups.push(MomentumGroup {
                body: i,
                lumped,
                members,
            });
        }
    }
}

/// Per body: the group it joins, its carrier's, if it is an axial member with a parent (no
/// pose in the forward-dynamics pass) whose carrier has a pose (always so for a model of this
/// crate; otherwise it stands as an ordinary body).
fn joined_groups(model: &Model, axial: &[Option<AxialMember>]) -> Vec<Option<usize>> {
    let carrier: Vec<Option<usize>> = (model.bodies.iter().zip(axial))
        .map(|(b, rc)| rc.filter(|_| b.parent.is_some()).map(|rc| rc.carrier))
        .collect();
    (carrier.iter())
        .map(|c| c.filter(|&c| carrier.get(c) == Some(&None)))
        .collect()
}
