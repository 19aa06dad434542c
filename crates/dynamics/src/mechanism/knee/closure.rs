//! Closed-form knee loop (3.4)-(3.7) and part motions (3.8)-(3.21) written out by hand: the
//! fast path of the kinematics (sines and cosines from [`crate::spatial::sin_cos`], within a
//! few ulp of the library's). The jet evaluation of the parent module (the reference
//! [`crate::mechanism::Coupling::motion`]) is what it is tested against.
//!
//! `r = A_z(q) a - b` (planar), `r_q = e_z x A_z(q) a`, `r_qq = -A_z(q) a`; `l = |r|` with
//! `l_q = r.r_q / l`, `l_qq = (r_q.r_q + r.r_qq - l_q^2) / l` ((3.5), (3.6)). The housing
//! (z along the screw axis, y = `e_z`) turns about its body y axis at `kappa qd` with
//! `kappa = (r x r_q)_z / l^2` ((3.17); zero with the tilt off), so every part's body twist
//! is linear in `qd` with coefficients that are functions of `q` alone, and the zero-`qdd`
//! bias is their `q` derivative times `qd^2`.

use super::{KneeDrive, KneePart, NAME};
use crate::mechanism::{MechanismError, RelativeMotion, MAX_COUPLED};
use crate::spatial::sin_cos;
use nalgebra::{Matrix3, Vector3, Vector6};

/// The knee loop closed at one knee angle: screw length, tilt rate and housing frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct KneeClosure {
    /// Screw length `l` (3.4).
    pub l: f64,
    /// `dl/dq` (3.5).
    pub l_q: f64,
    /// `d2l/dq2` (3.6).
    pub l_qq: f64,
    /// Housing tilt rate per knee rate `kappa` (3.17) (0 with the tilt off).
    pub kappa: f64,
    /// `d kappa / dq`.
    pub kappa_q: f64,
    /// Housing axes (columns x, y, z) in the thigh frame.
    pub rot: Matrix3<f64>,
}

impl KneeDrive {
    /// Closes the loop (3.4) at knee angle `q` (finite).
    pub(crate) fn solve(&self, q: f64) -> Result<KneeClosure, MechanismError> {
        let mut c = KneeClosure::default();
        self.solve_into(q, &mut c)?;
        Ok(c)
    }

    /// [`Self::solve`] written into `out` (a loop-cache slot, no copy); `out` is unspecified
    /// on an error.
    #[inline]
    pub(crate) fn solve_into(&self, q: f64, out: &mut KneeClosure) -> Result<(), MechanismError> {
        let p = &self.params;
        let (s, c) = sin_cos(q);
        let (a, b) = (&p.pin_shank, &p.pivot_thigh);
        let ra = Vector3::new(c * a.x - s * a.y, s * a.x + c * a.y, 0.0);
        let r = ra - Vector3::new(b.x, b.y, 0.0);
        let r_q = Vector3::new(-ra.y, ra.x, 0.0);
        let l = r.norm();
        if l <= 1e-9 * p.pin_shank.norm().max(1e-3) {
            return Err(MechanismError::OutOfRange {
                mechanism: NAME,
                input: vec![q],
                reason: "l_screw = 0 in (3.4)",
            });
        }
        let l_q = r.dot(&r_q) / l;
        let l_qq = (r_q.norm_squared() - r.dot(&ra) - l_q * l_q) / l;
        let (z, kappa, kappa_q) = if p.screw_tilt {
            let kappa = (r.x * r_q.y - r.y * r_q.x) / (l * l);
            let cross_qq = r.y * ra.x - r.x * ra.y; // (r x r_qq)_z
            (r / l, kappa, cross_qq / (l * l) - 2.0 * kappa * l_q / l)
        } else {
            (self.fixed_axis, 0.0, 0.0)
        };
        let x = Vector3::new(-z.y, z.x, 0.0).normalize();
        *out = KneeClosure {
            l,
            l_q,
            l_qq,
            kappa,
            kappa_q,
            rot: Matrix3::from_columns(&[x, z.cross(&x), z]),
        };
        Ok(())
    }

    /// Pose, Jacobian and bias of one part from the closed loop `c` at knee rate `qd`.
    pub(crate) fn part_motion(&self, part: KneePart, c: &KneeClosure, qd: f64) -> RelativeMotion {
        let b = &self.params.pivot_thigh;
        let (ang, lin, ang_q, lin_q, rot, pos) = match part {
            KneePart::Housing => (
                Vector3::new(0.0, c.kappa, 0.0),
                Vector3::zeros(),
                Vector3::new(0.0, c.kappa_q, 0.0),
                Vector3::zeros(),
                c.rot,
                Vector3::zeros(),
            ),
            KneePart::Nut => (
                Vector3::new(0.0, c.kappa, 0.0),
                Vector3::new(c.kappa * c.l, 0.0, c.l_q),
                Vector3::new(0.0, c.kappa_q, 0.0),
                Vector3::new(c.kappa_q * c.l + c.kappa * c.l_q, 0.0, c.l_qq),
                c.rot,
                c.rot.column(2) * c.l,
            ),
            KneePart::Rotor => {
                let n = self.screw_ratio();
                let (s, co) = sin_cos(n * c.l + self.params.motor_offset);
                let (x, y) = (c.rot.column(0), c.rot.column(1));
                let rot = Matrix3::from_columns(&[
                    x * co + y * s,
                    y * co - x * s,
                    c.rot.column(2).into(),
                ]);
                let ang = Vector3::new(s * c.kappa, co * c.kappa, n * c.l_q);
                let spin = n * c.l_q;
                let ang_q = Vector3::new(
                    co * spin * c.kappa + s * c.kappa_q,
                    co * c.kappa_q - s * spin * c.kappa,
                    n * c.l_qq,
                );
                (
                    ang,
                    Vector3::zeros(),
                    ang_q,
                    Vector3::zeros(),
                    rot,
                    Vector3::zeros(),
                )
            }
        };
        let mut jacobian = [Vector6::zeros(); MAX_COUPLED];
        jacobian[0] = Vector6::new(ang.x, ang.y, ang.z, lin.x, lin.y, lin.z);
        let q2 = qd * qd;
        RelativeMotion {
            rot,
            pos: pos + Vector3::new(b.x, b.y, 0.0),
            jacobian,
            bias: Vector6::new(ang_q.x, ang_q.y, ang_q.z, lin_q.x, lin_q.y, lin_q.z) * q2,
        }
    }
}
