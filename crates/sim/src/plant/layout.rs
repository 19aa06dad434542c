//! Layout of the plant state `z` (2.2) after the model layers of Table 2.3.

use serde::Serialize;
use std::ops::Range;

/// Slices of `z = [q | v | s | i]`: mechanical positions (incl. Type 3 motor angles),
/// velocities, contact-layer bristle states (2 per point) and motor currents (voltage mode
/// only). The position block for symplectic Euler is `q`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct StateLayout {
    /// Number of position coordinates.
    pub nq: usize,
    /// Number of velocity coordinates (mechanical DoF).
    pub nv: usize,
    /// Number of contact-layer states.
    pub ncontact: usize,
    /// Number of electrical states (motor currents).
    pub ncurrent: usize,
}

impl StateLayout {
    /// Dimension of `z`.
    pub fn dim(&self) -> usize {
        self.nq + self.nv + self.ncontact + self.ncurrent
    }

    /// Range of `q`.
    pub fn q(&self) -> Range<usize> {
        0..self.nq
    }

    /// Range of `v`.
    pub fn v(&self) -> Range<usize> {
        self.nq..self.nq + self.nv
    }

    /// Range of the contact states.
    pub fn contact(&self) -> Range<usize> {
        let s = self.nq + self.nv;
        s..s + self.ncontact
    }

    /// Range of the motor currents.
    pub fn currents(&self) -> Range<usize> {
        let s = self.nq + self.nv + self.ncontact;
        s..s + self.ncurrent
    }

    /// Number of first-order ODEs split as in Table 2.3: (mechanical DoF, contact, electrical,
    /// total).
    pub fn table_2_3(&self) -> [usize; 4] {
        [self.nv, self.ncontact, self.ncurrent, self.dim()]
    }
}
