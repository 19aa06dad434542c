//! The feet's contact with the ground during the dynamic walk, per side (a foot with its toe,
//! [`biped_sim::contact::ContactOutput::sides`]): load, toe load, heel lift, friction use and
//! slip, sampled once per control cycle; [`SlipTracker`] turns the slip speeds into the
//! verdict.
//!
//! - Friction use: `|F_t| / (mu F_n)` of the side's total wrench (tangential force over the
//!   Coulomb limit of its normal force; at most 1, since every point's force lies in its cone).
//! - Slip speed: the load-weighted mean sliding speed of the side's points in contact,
//!   `sum f_n,j |u_j| / sum f_n,j`, with `u_j` the part of point `j`'s velocity its bristle
//!   does not take up ([`biped_sim::contact::ContactSet::side_slip_speed`]: 0 while it
//!   sticks), i.e. the friction power over `mu F_n`. Not a point's velocity: a sticking sole
//!   moves its points by the bristles' deflection (up to `mu f_n / k_t` ~ 0.7 mm, at up to
//!   0.1-0.2 m/s during impacts), and a foot rolling about its heel or toe moves its sole's
//!   reference point without any slip (in toe-off the sole centre, 0.11 m behind the toe joint,
//!   swings forward at ~0.1 m/s while the toe stands still).
//! - Slip: a side slides [`SLIP_DISTANCE`] (the slip speed integrated) within one contact.
//!   Touch-down and lift-off of the default walk on `mu = 0.8` slide at up to ~0.27 m/s for a
//!   few ms, ~1.4 mm at most per contact; on `mu = 0.2` the same walk slides 9 mm.
//!
//! Friction use and slip count only while the side has at least [`SLIP_POINTS`] points in
//! contact (a side touching down or lifting off on one or two points has no grip to lose).

use crate::walk::error::{model_err, WalkError};
use biped_sim::contact::ContactSet;
use biped_sim::plant::Plant;

/// Sliding distance within one contact \[m] from which a side slips.
pub const SLIP_DISTANCE: f64 = 0.005;

/// Least points in contact for a side's friction use and slip speed to count.
pub const SLIP_POINTS: usize = 3;

/// One side's contact at one control cycle.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SideSample {
    /// Vertical force on the side (foot and toe) \[N].
    pub fz: f64,
    /// Vertical torque on the side about the foot's sole point \[N m].
    pub tau_z: f64,
    /// Vertical force on the toe segment \[N].
    pub toe_fz: f64,
    /// Heel lift: the foot's pitch, positive with the heel up \[rad].
    pub heel_lift: f64,
    /// `|F_t| / (mu F_n)` of the side's wrench (0 below [`SLIP_POINTS`] points in contact).
    pub friction_usage: f64,
    /// Load-weighted sliding speed of the points in contact \[m/s] (0 below [`SLIP_POINTS`]).
    pub slip_speed: f64,
    /// Points in contact (foot and toe).
    pub points: usize,
}

/// The `[left, right]` sides of a plant's contact set, resolved once.
#[derive(Debug, Clone)]
pub struct SideContact {
    /// Side index of `left`, `right`.
    sides: [usize; 2],
}

impl SideContact {
    /// The sides named `left` and `right` of `contact`.
    pub fn new(contact: &ContactSet) -> Result<Self, WalkError> {
        let side = |name: &str| {
            contact
                .side_index(name)
                .ok_or_else(|| model_err(format!("the plant has no contact side `{name}`")))
        };
        Ok(Self {
            sides: [side("left")?, side("right")?],
        })
    }

    /// `[left, right]` at the state `z` whose outputs the plant holds (the frame's).
    pub fn sample(&self, plant: &Plant, z: &[f64]) -> [SideSample; 2] {
        self.sides.map(|side| self.side(plant, z, side))
    }

    /// One side at the plant's last outputs.
    fn side(&self, plant: &Plant, z: &[f64], side: usize) -> SideSample {
        let (c, out) = (plant.contact(), &plant.last_outputs().contact);
        let entries = c.side_entries(side);
        let (Some(&foot), Some(w)) = (entries.first(), out.sides.get(side)) else {
            return SideSample::default();
        };
        let rot = out.foot_states[foot].rot;
        let mut s = SideSample {
            fz: w.force.z,
            tau_z: w.torque.z,
            toe_fz: entries[1..].iter().map(|&e| out.feet[e].force.z).sum(),
            heel_lift: (-rot[(2, 0)]).clamp(-1.0, 1.0).asin(),
            points: w.points_in_contact,
            ..SideSample::default()
        };
        if s.points < SLIP_POINTS || w.force.z <= 0.0 {
            return s;
        }
        let mu = c.params().friction;
        if mu > 0.0 {
            s.friction_usage = w.force.xy().norm() / (mu * w.force.z);
        }
        let bristles = z.get(plant.layout().contact()).unwrap_or(&[]);
        s.slip_speed = c.side_slip_speed(side, bristles, out);
        s
    }
}

/// Slip verdict over a walk: the peak slip speed, the sliding distance of each side within its
/// current contact and the first time one reached [`SLIP_DISTANCE`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SlipTracker {
    /// Largest slip speed so far \[m/s].
    pub max_speed: f64,
    /// Largest sliding distance within one contact so far \[m].
    pub max_distance: f64,
    /// First time a side slid [`SLIP_DISTANCE`] within one contact \[s].
    pub slip_at: Option<f64>,
    /// Sliding distance of `[left, right]` since it touched down \[m].
    distance: [f64; 2],
}

impl SlipTracker {
    /// Adds one cycle at time `t` of length `dt` with the sides' samples.
    pub fn add(&mut self, t: f64, dt: f64, sides: &[SideSample; 2]) {
        for (d, s) in self.distance.iter_mut().zip(sides) {
            if s.points < SLIP_POINTS {
                *d = 0.0;
                continue;
            }
            *d += s.slip_speed * dt;
            self.max_speed = self.max_speed.max(s.slip_speed);
            self.max_distance = self.max_distance.max(*d);
            if *d >= SLIP_DISTANCE && self.slip_at.is_none() {
                self.slip_at = Some(t);
            }
        }
    }
}
