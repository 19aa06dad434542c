//! Rigid transforms applied as rotation matrix plus translation (cheaper per point than the
//! quaternion form when many points share one pose).

use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

/// A pose as `x -> R x + t`.
#[derive(Debug, Clone, Copy)]
pub(super) struct RigidMatrix {
    /// Rotation matrix R.
    pub rot: Matrix3<f64>,
    /// Translation t.
    pub t: Vector3<f64>,
}

impl RigidMatrix {
    /// The matrix form of `pose`.
    #[inline]
    pub fn new(pose: &Isometry3<f64>) -> Self {
        Self {
            rot: pose.rotation.to_rotation_matrix().into_inner(),
            t: pose.translation.vector,
        }
    }

    /// The transformed point.
    #[inline]
    pub fn point(&self, p: &Point3<f64>) -> Point3<f64> {
        Point3::from(self.rot * p.coords + self.t)
    }
}
