//! Spatial force vectors `[moment about O; force]` (2.22, 2.56).

use super::vector::spatial_vector_ops;
use super::Motion;
use nalgebra::Vector3;

/// A 6-D force vector: moment about the frame origin first, then the force (2.56).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Force {
    /// Moment about the frame origin.
    pub ang: Vector3<f64>,
    /// Force.
    pub lin: Vector3<f64>,
}

/// External force/torque on a body, in the body frame, moment about the body origin.
pub type Wrench = Force;

impl Force {
    /// Force vector from a moment (about the frame origin) and a force.
    #[inline]
    pub fn new(torque: Vector3<f64>, force: Vector3<f64>) -> Self {
        Self {
            ang: torque,
            lin: force,
        }
    }

    /// Power pairing with a motion vector.
    #[inline]
    pub fn dot(&self, m: &Motion) -> f64 {
        m.dot(self)
    }
}

spatial_vector_ops!(Force);
