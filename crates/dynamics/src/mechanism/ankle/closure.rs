//! Closed-form slider-crank loop (3.23)-(3.33) and part motions (3.30)-(3.37) written out
//! by hand: the fast path of the kinematics (sines and cosines from [`crate::spatial::sin_cos`],
//! within a few ulp of the library's). The jet evaluation of the parent module
//! ([`super::AnkleCoupling`]'s [`crate::mechanism::Coupling::motion`]) is the reference it is
//! tested against; both give the same values up to round-off.
//!
//! Foot ball `F = C + A_y(q_0) A_x(q_1) f`: with `rho = F - C`, the partials are
//! `F_0 = e_y x rho`, `F_1 = a_1 x rho` (`a_1 = A_y(q_0) e_x`), the velocity `omega x rho`
//! (`omega = e_y qd_0 + a_1 qd_1`) and the zero-`qdd` acceleration
//! `omegadot x rho + omega x Fdot`, `omegadot = qd_0 qd_1 e_y x a_1`. The loop (3.29):
//! `l = e.r - d`, `d^2 = L^2 - r.r + (e.r)^2`, `r = F - T`, differentiated once per input
//! (3.32) and twice in time (3.33).

use super::{AnklePart, SliderCrank, NAME};
use crate::mechanism::{MechanismError, RelativeMotion};
use crate::spatial::sin_cos;
use nalgebra::{Matrix3, Vector3, Vector6};

/// One slider-crank loop closed at `(q, qd)`: nut travel and foot ball with their partials,
/// velocity and zero-`qdd` acceleration.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Closure {
    /// Nut travel `l` (3.29).
    pub l: f64,
    /// `dl/dq_j` (3.32).
    pub l_q: [f64; 2],
    /// `ldot`.
    pub l_dot: f64,
    /// `lddot` at `qdd = 0` (3.33).
    pub l_acc: f64,
    /// Foot ball centre `F` (shank frame).
    pub foot: Vector3<f64>,
    /// `dF/dq_j`.
    pub foot_q: [Vector3<f64>; 2],
    /// `Fdot`.
    pub foot_dot: Vector3<f64>,
    /// `Fddot` at `qdd = 0`.
    pub foot_acc: Vector3<f64>,
}

/// `(sin q_0, cos q_0, sin q_1, cos q_1)`.
pub(crate) fn trig(q: [f64; 2]) -> [f64; 4] {
    let (s0, c0) = sin_cos(q[0]);
    let (s1, c1) = sin_cos(q[1]);
    [s0, c0, s1, c1]
}

/// `e_y x v`.
#[inline]
fn ey_cross(v: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(v.z, 0.0, -v.x)
}

impl SliderCrank {
    /// Closes the loop at `q` (angles given by `trig = trig(q)`) moving with `qd`.
    pub(crate) fn solve(
        &self,
        q: [f64; 2],
        trig: [f64; 4],
        qd: [f64; 2],
    ) -> Result<Closure, MechanismError> {
        let mut c = Closure::default();
        self.solve_into(q, trig, qd, &mut c)?;
        Ok(c)
    }

    /// [`Self::solve`] written into `out` (a loop-cache slot, no copy); `out` is unspecified
    /// on an error.
    #[inline]
    pub(crate) fn solve_into(
        &self,
        q: [f64; 2],
        trig: [f64; 4],
        qd: [f64; 2],
        out: &mut Closure,
    ) -> Result<(), MechanismError> {
        let [s0, c0, s1, c1] = trig;
        let a = &self.act;
        let (e, f, [w0, w1]) = (&a.screw_axis, &a.foot_ball, qd);
        let g = Vector3::new(f.x, c1 * f.y - s1 * f.z, s1 * f.y + c1 * f.z);
        let rho = Vector3::new(c0 * g.x + s0 * g.z, g.y, c0 * g.z - s0 * g.x);
        let a1 = Vector3::new(c0, 0.0, -s0);
        let foot_q = [ey_cross(&rho), a1.cross(&rho)];
        let foot_dot = foot_q[0] * w0 + foot_q[1] * w1;
        let omega = Vector3::new(a1.x * w1, w0, a1.z * w1);
        let omega_dot = Vector3::new(-s0, 0.0, -c0) * (w0 * w1);
        let foot_acc = omega_dot.cross(&rho) + omega.cross(&foot_dot);
        let foot = self.center + rho;
        let r = foot - a.screw_top;
        let er = e.dot(&r);
        let d2 = a.rod_length * a.rod_length - r.norm_squared() + er * er;
        if d2.is_nan() || d2 <= 0.0 {
            return Err(MechanismError::OutOfRange {
                mechanism: NAME,
                input: q.to_vec(),
                reason: "no real root of (3.25): d^2 <= 0 in (3.29)",
            });
        }
        let d = d2.sqrt();
        let travel_rate = |v: &Vector3<f64>| {
            let ev = e.dot(v);
            (ev, ev - (er * ev - r.dot(v)) / d)
        };
        let l_q = [travel_rate(&foot_q[0]).1, travel_rate(&foot_q[1]).1];
        let (erd, l_dot) = travel_rate(&foot_dot);
        let d_dot = erd - l_dot;
        let era = e.dot(&foot_acc);
        let d_acc =
            (erd * erd + er * era - foot_dot.norm_squared() - r.dot(&foot_acc) - d_dot * d_dot) / d;
        *out = Closure {
            l: er - d,
            l_q,
            l_dot,
            l_acc: era - d_acc,
            foot,
            foot_q,
            foot_dot,
            foot_acc,
        };
        Ok(())
    }

    /// Pose, Jacobian and bias of one part from the closed loop `c` (3.30)-(3.37).
    #[inline]
    pub(crate) fn part_motion(&self, part: AnklePart, c: &Closure) -> RelativeMotion {
        let a = &self.act;
        let z6 = Vector6::zeros();
        let [l0, l1] = c.l_q;
        match part {
            AnklePart::Nut => RelativeMotion {
                rot: self.frame,
                pos: a.screw_top + a.screw_axis * c.l,
                jacobian: [
                    Vector6::new(0.0, 0.0, 0.0, 0.0, 0.0, l0),
                    Vector6::new(0.0, 0.0, 0.0, 0.0, 0.0, l1),
                    z6,
                ],
                bias: Vector6::new(0.0, 0.0, 0.0, 0.0, 0.0, c.l_acc),
            },
            AnklePart::Rotor => {
                let (s, co) = sin_cos(self.ratio * c.l + a.motor_offset);
                let (x, y) = (self.frame.column(0), self.frame.column(1));
                let n = self.ratio;
                RelativeMotion {
                    rot: Matrix3::from_columns(&[
                        x * co + y * s,
                        y * co - x * s,
                        self.frame.column(2).into(),
                    ]),
                    pos: a.screw_top,
                    jacobian: [
                        Vector6::new(0.0, 0.0, n * l0, 0.0, 0.0, 0.0),
                        Vector6::new(0.0, 0.0, n * l1, 0.0, 0.0, 0.0),
                        z6,
                    ],
                    bias: Vector6::new(0.0, 0.0, n * c.l_acc, 0.0, 0.0, 0.0),
                }
            }
            AnklePart::Rod => self.rod_motion(c),
        }
    }

    /// The coupler rod (origin at the nut ball, z along `u = (F - N) / L`,
    /// `x = (e_y x u) / n`, `n = |e_y x u|`, so `x_y = 0`): body angular velocity
    /// `(-y.udot, x.udot, kappa x.udot)` with `kappa = u_y / n` (from `(e_y x udot).y / n`,
    /// `y = u x x`), linear velocity `(x, y, z) . e ldot`, and their component-wise time
    /// derivatives at `qdd = 0` (`ndot = x.(e_y x udot)`, `kappadot = (udot_y - kappa ndot) / n`).
    fn rod_motion(&self, c: &Closure) -> RelativeMotion {
        let a = &self.act;
        let e = &a.screw_axis;
        let inv = 1.0 / a.rod_length;
        let nut = a.screw_top + e * c.l;
        let u = (c.foot - nut) * inv;
        let u_dot = (c.foot_dot - e * c.l_dot) * inv;
        let u_acc = (c.foot_acc - e * c.l_acc) * inv;
        let n_inv = 1.0 / (u.z * u.z + u.x * u.x).sqrt();
        let x = Vector3::new(u.z * n_inv, 0.0, -u.x * n_inv);
        let y = u.cross(&x);
        let kappa = u.y * n_inv;
        let x_dot_v = |v: &Vector3<f64>| x.x * v.x + x.z * v.z;
        let lin = Vector3::new(x_dot_v(e), y.dot(e), u.dot(e));
        let column = |j: usize| {
            let v = (c.foot_q[j] - e * c.l_q[j]) * inv;
            let (wy, l) = (x_dot_v(&v), lin * c.l_q[j]);
            Vector6::new(-y.dot(&v), wy, kappa * wy, l.x, l.y, l.z)
        };
        let (wx, wy) = (-y.dot(&u_dot), x_dot_v(&u_dot));
        let wz = kappa * wy;
        let x_dot = y * wz - u * wy;
        let y_dot = u * wx - x * wz;
        let n_dot = x.x * u_dot.z - x.z * u_dot.x;
        let kappa_dot = (u_dot.y - kappa * n_dot) * n_inv;
        let wy_dot = x_dot.dot(&u_dot) + x_dot_v(&u_acc);
        let lb = Vector3::new(x_dot.dot(e), y_dot.dot(e), u_dot.dot(e)) * c.l_dot + lin * c.l_acc;
        RelativeMotion {
            rot: Matrix3::from_columns(&[x, y, u]),
            pos: nut,
            jacobian: [column(0), column(1), Vector6::zeros()],
            bias: Vector6::new(
                -y_dot.dot(&u_dot) - y.dot(&u_acc),
                wy_dot,
                kappa_dot * wy + kappa * wy_dot,
                lb.x,
                lb.y,
                lb.z,
            ),
        }
    }
}
