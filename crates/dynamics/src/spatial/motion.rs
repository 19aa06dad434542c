//! Spatial motion vectors `[omega; rdot]` (2.32).

use super::vector::spatial_vector_ops;
use super::Force;
use nalgebra::Vector3;

/// A 6-D motion vector (velocity or conventional acceleration), angular part first (2.32).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Angular part `omega` (or `omegadot`).
    pub ang: Vector3<f64>,
    /// Linear part: velocity (or acceleration) of the frame origin.
    pub lin: Vector3<f64>,
}

impl Motion {
    /// Motion from its angular and linear parts.
    #[inline]
    pub fn new(ang: Vector3<f64>, lin: Vector3<f64>) -> Self {
        Self { ang, lin }
    }

    /// Power pairing `m . f = omega . T + v . F`.
    #[inline]
    pub fn dot(&self, f: &Force) -> f64 {
        self.ang.dot(&f.ang) + self.lin.dot(&f.lin)
    }
}

spatial_vector_ops!(Motion);
