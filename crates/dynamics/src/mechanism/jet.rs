//! Second-order forward differentiation along a motion `q(t)` with `qdd = 0` ("jets"), the
//! closed-form engine behind every mechanism part of ch. 3.
//!
//! A jet of a quantity `f(q)` carries its value, the partial derivatives `df/dq_j`
//! (the Jacobian columns), the first time derivative `fdot = sum_j df/dq_j qd_j` and the second
//! time derivative at zero input acceleration `fddot_0 = sum_jk d2f/dq_j dq_k qd_j qd_k` (the
//! "bias" term `Jdot qd`). Sums, products, cross products, norms and elementary functions
//! propagate all four exactly (product and chain rules), so the derivative formulas of
//! (3.5)-(3.7), (3.10)-(3.14), (3.17)-(3.21), (3.30)-(3.37) and (3.44) are evaluated in closed
//! form without writing each one out by hand. Everything is fixed-size and allocation-free.
//! [`FrameJet::motion`] turns jets of a part frame's axes and origin into a [`CoupledMotion`].

use super::{CoupledMotion, MechanismError, RelativeMotion, MAX_COUPLED};
use nalgebra::{Matrix3, Rotation3, Unit, Vector3, Vector6};
use std::ops::{Add, Sub};

/// Scalar jet: value, partials, first and (zero-`qdd`) second time derivative.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SJet<const N: usize> {
    /// Value `f`.
    pub v: f64,
    /// Partial derivatives `df/dq_j`.
    pub d: [f64; N],
    /// `fdot = sum_j df/dq_j qd_j`.
    pub vel: f64,
    /// `fddot` at `qdd = 0`.
    pub acc: f64,
}

/// Vector jet (3-vectors): value, partials, first and (zero-`qdd`) second time derivative.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VJet<const N: usize> {
    /// Value.
    pub v: Vector3<f64>,
    /// Partial derivatives.
    pub d: [Vector3<f64>; N],
    /// First time derivative.
    pub vel: Vector3<f64>,
    /// Second time derivative at `qdd = 0`.
    pub acc: Vector3<f64>,
}

impl<const N: usize> SJet<N> {
    /// A constant (all derivatives zero).
    pub fn constant(v: f64) -> Self {
        Self {
            v,
            d: [0.0; N],
            vel: 0.0,
            acc: 0.0,
        }
    }

    /// The input coordinate `q_j` moving with rate `qd_j` (seed of the differentiation).
    pub fn input(j: usize, q: f64, qd: f64) -> Self {
        let mut d = [0.0; N];
        d[j] = 1.0;
        Self {
            v: q,
            d,
            vel: qd,
            acc: 0.0,
        }
    }

    /// Chain rule for `h(f)` given `h(f)`, `h'(f)` and `h''(f)`.
    fn chain(self, h: f64, h1: f64, h2: f64) -> Self {
        Self {
            v: h,
            d: self.d.map(|x| h1 * x),
            vel: h1 * self.vel,
            acc: h1 * self.acc + h2 * self.vel * self.vel,
        }
    }

    /// `c * self` for a constant `c`.
    pub fn scale(self, c: f64) -> Self {
        Self {
            v: c * self.v,
            d: self.d.map(|x| c * x),
            vel: c * self.vel,
            acc: c * self.acc,
        }
    }

    /// `1 / self` (caller guarantees `self.v != 0`).
    pub fn recip(self) -> Self {
        let r = 1.0 / self.v;
        self.chain(r, -r * r, 2.0 * r * r * r)
    }

    /// `sqrt(self)` (caller guarantees `self.v > 0`).
    pub fn sqrt(self) -> Self {
        let s = self.v.sqrt();
        self.chain(s, 0.5 / s, -0.25 / (s * s * s))
    }

    /// `sin(self)`.
    pub fn sin(self) -> Self {
        let (s, c) = self.v.sin_cos();
        self.chain(s, c, -s)
    }

    /// `cos(self)`.
    pub fn cos(self) -> Self {
        let (s, c) = self.v.sin_cos();
        self.chain(c, -s, -c)
    }

    /// `(sin(self), cos(self))` from one evaluation of the sine and cosine.
    pub fn sin_cos(self) -> (Self, Self) {
        let (s, c) = self.v.sin_cos();
        (self.chain(s, c, -s), self.chain(c, -s, -c))
    }

    /// `acos(self)` (caller guarantees `|self.v| < 1`).
    pub fn acos(self) -> Self {
        let x = self.v;
        let w = 1.0 - x * x;
        let sw = w.sqrt();
        self.chain(x.acos(), -1.0 / sw, -x / (w * sw))
    }
}

impl<const N: usize> VJet<N> {
    /// A constant vector.
    pub fn constant(v: Vector3<f64>) -> Self {
        Self {
            v,
            d: [Vector3::zeros(); N],
            vel: Vector3::zeros(),
            acc: Vector3::zeros(),
        }
    }

    /// `self + c` for a constant vector `c`.
    pub fn offset(mut self, c: &Vector3<f64>) -> Self {
        self.v += c;
        self
    }

    /// `m * self` for a constant matrix `m`.
    pub fn transform(self, m: &Matrix3<f64>) -> Self {
        Self {
            v: m * self.v,
            d: self.d.map(|x| m * x),
            vel: m * self.vel,
            acc: m * self.acc,
        }
    }

    /// `s * self` for a scalar jet `s` (product rule).
    pub fn scale(self, s: SJet<N>) -> Self {
        Self {
            v: self.v * s.v,
            d: std::array::from_fn(|j| self.d[j] * s.v + self.v * s.d[j]),
            vel: self.vel * s.v + self.v * s.vel,
            acc: self.acc * s.v + 2.0 * self.vel * s.vel + self.v * s.acc,
        }
    }

    /// `self . other`.
    pub fn dot(&self, o: &Self) -> SJet<N> {
        SJet {
            v: self.v.dot(&o.v),
            d: std::array::from_fn(|j| self.d[j].dot(&o.v) + self.v.dot(&o.d[j])),
            vel: self.vel.dot(&o.v) + self.v.dot(&o.vel),
            acc: self.acc.dot(&o.v) + 2.0 * self.vel.dot(&o.vel) + self.v.dot(&o.acc),
        }
    }

    /// `c . self` for a constant vector `c`.
    pub fn dot_const(&self, c: &Vector3<f64>) -> SJet<N> {
        SJet {
            v: c.dot(&self.v),
            d: self.d.map(|x| c.dot(&x)),
            vel: c.dot(&self.vel),
            acc: c.dot(&self.acc),
        }
    }

    /// `self x other`.
    pub fn cross(&self, o: &Self) -> Self {
        Self {
            v: self.v.cross(&o.v),
            d: std::array::from_fn(|j| self.d[j].cross(&o.v) + self.v.cross(&o.d[j])),
            vel: self.vel.cross(&o.v) + self.v.cross(&o.vel),
            acc: self.acc.cross(&o.v) + 2.0 * self.vel.cross(&o.vel) + self.v.cross(&o.acc),
        }
    }

    /// Euclidean norm (caller guarantees a non-zero value).
    pub fn norm(&self) -> SJet<N> {
        self.dot(self).sqrt()
    }

    /// `self / |self|` (caller guarantees a non-zero value).
    pub fn normalize(&self) -> Self {
        self.scale(self.norm().recip())
    }

    /// `Rot(axis, angle) * self`: rotation by a scalar-jet angle about a fixed unit axis.
    pub fn rotate(&self, axis: &Unit<Vector3<f64>>, angle: SJet<N>) -> Self {
        let rot = Rotation3::from_axis_angle(axis, angle.v);
        let k = axis.into_inner();
        let rv = rot * self.v;
        let krv = k.cross(&rv);
        let rvel = rot * self.vel;
        Self {
            v: rv,
            d: std::array::from_fn(|j| krv * angle.d[j] + rot * self.d[j]),
            vel: krv * angle.vel + rvel,
            acc: krv * angle.acc
                + k.cross(&krv) * (angle.vel * angle.vel)
                + k.cross(&rvel) * (2.0 * angle.vel)
                + rot * self.acc,
        }
    }

    /// `Rot(axis, angle) * c` for a constant vector `c`: [`Self::rotate`] of
    /// `VJet::constant(c)` without the products of zero derivatives (Rodrigues' formula).
    pub fn rotate_constant(c: &Vector3<f64>, axis: &Unit<Vector3<f64>>, angle: SJet<N>) -> Self {
        let k = axis.as_ref();
        let (s, co) = angle.v.sin_cos();
        let kc = k.cross(c);
        let rv = c * co + kc * s + k * (k.dot(c) * (1.0 - co));
        let krv = k.cross(&rv);
        Self {
            v: rv,
            d: std::array::from_fn(|j| krv * angle.d[j]),
            vel: krv * angle.vel,
            acc: krv * angle.acc + k.cross(&krv) * (angle.vel * angle.vel),
        }
    }
}

/// Component-wise `+` and `-` of a jet type (exact derivative propagation).
macro_rules! jet_linear_ops {
    ($jet:ident) => {
        impl<const N: usize> std::ops::Add for $jet<N> {
            type Output = Self;
            fn add(self, o: Self) -> Self {
                Self {
                    v: self.v + o.v,
                    d: std::array::from_fn(|j| self.d[j] + o.d[j]),
                    vel: self.vel + o.vel,
                    acc: self.acc + o.acc,
                }
            }
        }

        impl<const N: usize> std::ops::Sub for $jet<N> {
            type Output = Self;
            fn sub(self, o: Self) -> Self {
                Self {
                    v: self.v - o.v,
                    d: std::array::from_fn(|j| self.d[j] - o.d[j]),
                    vel: self.vel - o.vel,
                    acc: self.acc - o.acc,
                }
            }
        }
    };
}

jet_linear_ops!(SJet);
jet_linear_ops!(VJet);

/// `SJet mul` (exact derivative propagation).
impl<const N: usize> std::ops::Mul for SJet<N> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Self {
            v: self.v * o.v,
            d: std::array::from_fn(|j| self.d[j] * o.v + self.v * o.d[j]),
            vel: self.vel * o.v + self.v * o.vel,
            acc: self.acc * o.v + 2.0 * self.vel * o.vel + self.v * o.acc,
        }
    }
}

/// Jets of a part frame: its three unit axes and its origin, all in parent coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameJet<const N: usize> {
    /// Unit x axis of the part frame.
    pub x: VJet<N>,
    /// Unit y axis of the part frame.
    pub y: VJet<N>,
    /// Unit z axis of the part frame.
    pub z: VJet<N>,
    /// Origin of the part frame.
    pub p: VJet<N>,
}

impl<const N: usize> FrameJet<N> {
    /// A frame with constant axes (columns of `rot`) and a moving origin `p`.
    pub fn fixed_axes(rot: &Matrix3<f64>, p: VJet<N>) -> Self {
        let c = |i: usize| VJet::constant(rot.column(i).into_owned());
        Self {
            x: c(0),
            y: c(1),
            z: c(2),
            p,
        }
    }

    /// The frame whose z axis is the unit vector `u` and whose x axis is `normalize(m x u)` for
    /// a fixed reference direction `m` (`y = z x x`): the roll convention of rods and screws.
    pub fn from_direction(u: VJet<N>, m: &Vector3<f64>, p: VJet<N>) -> Self {
        let x = VJet::constant(*m).cross(&u).normalize();
        let y = u.cross(&x);
        Self { x, y, z: u, p }
    }

    /// This frame rotated about its own z axis by the scalar-jet angle `phi` (a spinning rotor).
    pub fn spin_z(&self, phi: SJet<N>) -> Self {
        let (s, c) = phi.sin_cos();
        let x = self.x.scale(c).add(self.y.scale(s));
        let y = self.y.scale(c).sub(self.x.scale(s));
        Self {
            x,
            y,
            z: self.z,
            p: self.p,
        }
    }

    /// Pose, relative-twist Jacobian and bias (module doc of [`super`]) of this frame.
    pub fn motion(&self) -> CoupledMotion {
        self.relative().to_coupled()
    }

    /// [`Self::motion`] with the pose as a rotation matrix (columns x, y, z) and origin.
    ///
    /// Body angular velocity components are `(ydot.z, zdot.x, xdot.y)` and the body linear
    /// velocity components `(x.pdot, y.pdot, z.pdot)`; their partials give the Jacobian columns
    /// and their time derivatives at `qdd = 0` the bias.
    pub fn relative(&self) -> RelativeMotion {
        let (x, y, z, p) = (&self.x, &self.y, &self.z, &self.p);
        let ang = |a: &VJet<N>, b: &VJet<N>, j: usize| a.d[j].dot(&b.v);
        let lin = |a: &VJet<N>, j: usize| a.v.dot(&p.d[j]);
        const { assert!(N <= MAX_COUPLED) };
        let jacobian = std::array::from_fn(|j| {
            if j >= N {
                return Vector6::zeros();
            }
            Vector6::new(
                ang(y, z, j),
                ang(z, x, j),
                ang(x, y, j),
                lin(x, j),
                lin(y, j),
                lin(z, j),
            )
        });
        let bang = |a: &VJet<N>, b: &VJet<N>| a.acc.dot(&b.v) + a.vel.dot(&b.vel);
        let blin = |a: &VJet<N>| a.vel.dot(&p.vel) + a.v.dot(&p.acc);
        let bias = Vector6::new(
            bang(y, z),
            bang(z, x),
            bang(x, y),
            blin(x),
            blin(y),
            blin(z),
        );
        RelativeMotion {
            rot: Matrix3::from_columns(&[x.v, y.v, z.v]),
            pos: p.v,
            jacobian,
            bias,
        }
    }
}

/// Checks `q_in`, `qd_in` (length `N`, finite) and seeds one input jet per coordinate.
pub fn seed_inputs<const N: usize>(
    mechanism: &'static str,
    q: &[f64],
    qd: &[f64],
) -> Result<[SJet<N>; N], MechanismError> {
    let (q, qd) = input_arrays::<N>(mechanism, q, qd)?;
    Ok(std::array::from_fn(|j| SJet::input(j, q[j], qd[j])))
}

/// Checks `q_in`, `qd_in` (length `N`, finite) and returns them as arrays.
#[inline]
pub fn input_arrays<const N: usize>(
    mechanism: &'static str,
    q: &[f64],
    qd: &[f64],
) -> Result<([f64; N], [f64; N]), MechanismError> {
    match (<[f64; N]>::try_from(q), <[f64; N]>::try_from(qd)) {
        // Non-short-circuit `&`: no branch per input.
        (Ok(qa), Ok(qda)) if qa.iter().chain(&qda).fold(true, |ok, x| ok & x.is_finite()) => {
            Ok((qa, qda))
        }
        _ => Err(bad_inputs(mechanism, N, q, qd)),
    }
}

/// The error of [`input_arrays`] (wrong lengths or a non-finite value).
#[cold]
fn bad_inputs(mechanism: &'static str, n: usize, q: &[f64], qd: &[f64]) -> MechanismError {
    let reason = if q.len() != n || qd.len() != n {
        format!("expected {n} inputs, got q {} / qd {}", q.len(), qd.len())
    } else {
        "non-finite input".into()
    };
    MechanismError::BadInput { mechanism, reason }
}

/// Error for a non-finite or non-positive geometric parameter.
pub fn bad_param(mechanism: &'static str, what: &str) -> MechanismError {
    MechanismError::BadInput {
        mechanism,
        reason: format!("invalid parameter: {what}"),
    }
}

#[cfg(test)]
mod tests;
