//! Spatial motion vectors `[omega; rdot]` (2.32).

use super::Force;
use nalgebra::{Vector3, Vector6};
use std::ops::{Add, AddAssign, Mul, Neg, Sub};

/// A 6-D motion vector (velocity or conventional acceleration), angular part first (2.32).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Angular part `omega` (or `omegadot`).
    pub ang: Vector3<f64>,
    /// Linear part: velocity (or acceleration) of the frame origin.
    pub lin: Vector3<f64>,
}

impl Default for Motion {
    fn default() -> Self {
        Self::zero()
    }
}

impl Motion {
    /// Motion from its angular and linear parts.
    #[inline]
    pub fn new(ang: Vector3<f64>, lin: Vector3<f64>) -> Self {
        Self { ang, lin }
    }

    /// The zero motion.
    #[inline]
    pub fn zero() -> Self {
        Self::new(Vector3::zeros(), Vector3::zeros())
    }

    /// Motion from a stacked 6-vector `[ang; lin]`.
    #[inline]
    pub fn from_vector(v: &Vector6<f64>) -> Self {
        Self::new(v.fixed_rows::<3>(0).into(), v.fixed_rows::<3>(3).into())
    }

    /// Stacked 6-vector `[ang; lin]`.
    #[inline]
    pub fn to_vector(&self) -> Vector6<f64> {
        Vector6::new(
            self.ang.x, self.ang.y, self.ang.z, self.lin.x, self.lin.y, self.lin.z,
        )
    }

    /// Power pairing `m . f = omega . T + v . F`.
    #[inline]
    pub fn dot(&self, f: &Force) -> f64 {
        self.ang.dot(&f.ang) + self.lin.dot(&f.lin)
    }

    /// True if every component is finite.
    pub fn is_finite(&self) -> bool {
        self.ang
            .iter()
            .chain(self.lin.iter())
            .all(|x| x.is_finite())
    }
}

impl Add for Motion {
    type Output = Motion;
    #[inline]
    fn add(self, o: Motion) -> Motion {
        Motion::new(self.ang + o.ang, self.lin + o.lin)
    }
}

impl AddAssign for Motion {
    #[inline]
    fn add_assign(&mut self, o: Motion) {
        self.ang += o.ang;
        self.lin += o.lin;
    }
}

impl Sub for Motion {
    type Output = Motion;
    #[inline]
    fn sub(self, o: Motion) -> Motion {
        Motion::new(self.ang - o.ang, self.lin - o.lin)
    }
}

impl Neg for Motion {
    type Output = Motion;
    #[inline]
    fn neg(self) -> Motion {
        Motion::new(-self.ang, -self.lin)
    }
}

impl Mul<f64> for Motion {
    type Output = Motion;
    #[inline]
    fn mul(self, s: f64) -> Motion {
        Motion::new(self.ang * s, self.lin * s)
    }
}
