//! The operations motion and force vectors share: both are pairs `[ang; lin]` of 3-vectors.

/// Implements `Default`, `zero`, `from_vector`, `to_vector`, `is_finite` and the linear-space
/// operators for a spatial vector type with fields `ang` and `lin` and a `new(ang, lin)`.
macro_rules! spatial_vector_ops {
    ($t:ident) => {
        impl Default for $t {
            fn default() -> Self {
                Self::zero()
            }
        }

        impl $t {
            /// The zero vector.
            #[inline]
            pub fn zero() -> Self {
                Self::new(nalgebra::Vector3::zeros(), nalgebra::Vector3::zeros())
            }

            /// From a stacked 6-vector `[ang; lin]`.
            #[inline]
            pub fn from_vector(v: &nalgebra::Vector6<f64>) -> Self {
                Self::new(v.fixed_rows::<3>(0).into(), v.fixed_rows::<3>(3).into())
            }

            /// Stacked 6-vector `[ang; lin]`.
            #[inline]
            pub fn to_vector(&self) -> nalgebra::Vector6<f64> {
                nalgebra::Vector6::new(
                    self.ang.x, self.ang.y, self.ang.z, self.lin.x, self.lin.y, self.lin.z,
                )
            }

            /// True if every component is finite.
            pub fn is_finite(&self) -> bool {
                self.ang
                    .iter()
                    .chain(self.lin.iter())
                    .all(|x| x.is_finite())
            }
        }

        impl std::ops::Add for $t {
            type Output = $t;
            #[inline]
            fn add(self, o: $t) -> $t {
                $t::new(self.ang + o.ang, self.lin + o.lin)
            }
        }

        impl std::ops::AddAssign for $t {
            #[inline]
            fn add_assign(&mut self, o: $t) {
                self.ang += o.ang;
                self.lin += o.lin;
            }
        }

        impl std::ops::Sub for $t {
            type Output = $t;
            #[inline]
            fn sub(self, o: $t) -> $t {
                $t::new(self.ang - o.ang, self.lin - o.lin)
            }
        }

        impl std::ops::SubAssign for $t {
            #[inline]
            fn sub_assign(&mut self, o: $t) {
                self.ang -= o.ang;
                self.lin -= o.lin;
            }
        }

        impl std::ops::Neg for $t {
            type Output = $t;
            #[inline]
            fn neg(self) -> $t {
                $t::new(-self.ang, -self.lin)
            }
        }

        impl std::ops::Mul<f64> for $t {
            type Output = $t;
            #[inline]
            fn mul(self, s: f64) -> $t {
                $t::new(self.ang * s, self.lin * s)
            }
        }
    };
}

pub(crate) use spatial_vector_ops;
