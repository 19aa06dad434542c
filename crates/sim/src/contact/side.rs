//! Sides: a foot entry with the entries that are parts of it (a toe segment on its own body).
//! The entries keep their exact per-body wrenches; a side's wrench sums its parts into the
//! foot by shifting their moments to the foot's sole reference point, so consumers that want
//! "the ground wrench on the left foot" get one wrench whatever the foot is made of.

use super::{ContactOutput, ContactSet, FootSpec, FootWrench};
use crate::error::SimError;
use biped_dynamics::BodyId;
use nalgebra::Vector2;

impl FootWrench {
    /// The sum of this wrench and `part`'s with the moment about this wrench's reference
    /// point: `F = F_a + F_b`, `M = M_a + M_b + (r_b - r_a) x F_b`; the centre of pressure is
    /// the mean of both weighted by their normal forces, the point counts add up.
    pub fn with_part(&self, part: &FootWrench) -> FootWrench {
        let shift = (part.reference - self.reference).cross(&part.force);
        let (fa, fb) = (cop_weight(self), cop_weight(part));
        let cop = match (self.cop, part.cop) {
            (Some(a), Some(b)) if fa + fb > 0.0 => Some((a * fa + b * fb) / (fa + fb)),
            (a, b) => a.or(b),
        };
        FootWrench {
            force: self.force + part.force,
            torque: self.torque + part.torque + shift,
            reference: self.reference,
            cop,
            points_in_contact: self.points_in_contact + part.points_in_contact,
        }
    }
}

/// Weight of a wrench's centre of pressure: its normal force (the sum of its points' normal
/// forces, each `>= 0`), 0 without contact.
fn cop_weight(w: &FootWrench) -> f64 {
    if w.cop.is_some() {
        w.force.z.max(0.0)
    } else {
        0.0
    }
}

/// Entry indices per side, the foot first, sides in the order of the feet in `specs`; an
/// entry naming no foot entry (or a part) in `part_of` is an error.
pub(super) fn group(specs: &[FootSpec]) -> Result<Vec<Vec<usize>>, SimError> {
    let mut sides: Vec<Vec<usize>> = specs
        .iter()
        .enumerate()
        .filter(|(_, s)| s.part_of.is_none())
        .map(|(k, _)| vec![k])
        .collect();
    for (k, spec) in specs.iter().enumerate() {
        let Some(foot) = &spec.part_of else {
            continue;
        };
        let side = sides
            .iter_mut()
            .find(|side| specs[side[0]].name == *foot)
            .ok_or_else(|| SimError::InvalidParameter {
                what: format!("foot `{}` part_of", spec.name),
                reason: format!("`{foot}` is not the name of a foot entry (one without part_of)"),
            })?;
        side.push(k);
    }
    Ok(sides)
}

impl ContactSet {
    /// Number of sides (the feet; parts are summed into them).
    pub fn nsides(&self) -> usize {
        self.sides.len()
    }

    /// Names of the sides (their foot entries' names), in the order of
    /// [`ContactOutput::sides`].
    pub fn side_names(&self) -> impl Iterator<Item = &str> {
        self.sides
            .iter()
            .map(|s| self.feet[s[0]].spec.name.as_str())
    }

    /// Index of the side whose foot entry is named `name`.
    pub fn side_index(&self, name: &str) -> Option<usize> {
        self.side_names().position(|n| n == name)
    }

    /// Body ids of the feet (one per side, without their parts).
    pub fn side_bodies(&self) -> impl Iterator<Item = BodyId> + '_ {
        self.sides.iter().map(|s| self.feet[s[0]].body)
    }

    /// Entry indices of side `side` (the foot first, then its parts); empty if out of range.
    pub fn side_entries(&self, side: usize) -> &[usize] {
        self.sides.get(side).map_or(&[], Vec::as_slice)
    }

    /// Load-weighted mean sliding speed of side `side`'s points in contact,
    /// `sum f_n,j |u_j| / sum f_n,j` with `u_j` the point's sliding velocity
    /// ([`super::ContactParams::sliding_velocity`]: 0 while it sticks), i.e. the power the
    /// side's friction dissipates over `mu F_n`; from the bristle states `bristles` (the state's
    /// contact layer) and the outputs `out` of the same state. 0 without contact.
    pub fn side_slip_speed(&self, side: usize, bristles: &[f64], out: &ContactOutput) -> f64 {
        let (mut power, mut load) = (0.0, 0.0);
        for &e in self.side_entries(side) {
            let (foot, st) = (&self.feet[e], &out.foot_states[e]);
            for (j, c) in foot.spec.points.iter().enumerate() {
                let k = foot.first + j;
                let (f, b) = (out.point_forces[k], bristles.get(2 * k..2 * k + 2));
                let (Some(b), true) = (b, f.z > 0.0) else {
                    continue;
                };
                let v = st.point(c).1.xy();
                let u = self
                    .params
                    .sliding_velocity(Vector2::new(b[0], b[1]), v, f.xy());
                power += f.z * u.norm();
                load += f.z;
            }
        }
        if load > 0.0 {
            power / load
        } else {
            0.0
        }
    }

    /// Fills `out.sides` from the entries' wrenches in `out.feet`.
    pub(super) fn sum_sides(&self, out: &mut ContactOutput) {
        for (side, w) in self.sides.iter().zip(out.sides.iter_mut()) {
            let mut sum = out.feet[side[0]];
            for &part in &side[1..] {
                sum = sum.with_part(&out.feet[part]);
            }
            *w = sum;
        }
    }
}
