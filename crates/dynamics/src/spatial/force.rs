//! Spatial force vectors `[moment about O; force]` (2.22, 2.56).

use super::Motion;
use nalgebra::{Vector3, Vector6};
use std::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

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

impl Default for Force {
    fn default() -> Self {
        Self::zero()
    }
}

impl Force {
    /// Force vector from a moment (about the frame origin) and a force.
    #[inline]
    pub fn new(torque: Vector3<f64>, force: Vector3<f64>) -> Self {
        Self {
            ang: torque,
            lin: force,
        }
    }

    /// The zero force.
    #[inline]
    pub fn zero() -> Self {
        Self::new(Vector3::zeros(), Vector3::zeros())
    }

    /// Force vector from a stacked 6-vector `[moment; force]`.
    #[inline]
    pub fn from_vector(v: &Vector6<f64>) -> Self {
        Self::new(v.fixed_rows::<3>(0).into(), v.fixed_rows::<3>(3).into())
    }

    /// Stacked 6-vector `[moment; force]`.
    #[inline]
    pub fn to_vector(&self) -> Vector6<f64> {
        Vector6::new(
            self.ang.x, self.ang.y, self.ang.z, self.lin.x, self.lin.y, self.lin.z,
        )
    }

    /// Power pairing with a motion vector.
    #[inline]
    pub fn dot(&self, m: &Motion) -> f64 {
        m.dot(self)
    }

    /// True if every component is finite.
    pub fn is_finite(&self) -> bool {
        self.ang
            .iter()
            .chain(self.lin.iter())
            .all(|x| x.is_finite())
    }
}

impl Add for Force {
    type Output = Force;
    #[inline]
    fn add(self, o: Force) -> Force {
        Force::new(self.ang + o.ang, self.lin + o.lin)
    }
}

impl AddAssign for Force {
    #[inline]
    fn add_assign(&mut self, o: Force) {
        self.ang += o.ang;
        self.lin += o.lin;
    }
}

impl Sub for Force {
    type Output = Force;
    #[inline]
    fn sub(self, o: Force) -> Force {
        Force::new(self.ang - o.ang, self.lin - o.lin)
    }
}

impl SubAssign for Force {
    #[inline]
    fn sub_assign(&mut self, o: Force) {
        self.ang -= o.ang;
        self.lin -= o.lin;
    }
}

impl Neg for Force {
    type Output = Force;
    #[inline]
    fn neg(self) -> Force {
        Force::new(-self.ang, -self.lin)
    }
}

impl Mul<f64> for Force {
    type Output = Force;
    #[inline]
    fn mul(self, s: f64) -> Force {
        Force::new(self.ang * s, self.lin * s)
    }
}
