//! Statically dispatched mechanisms of coupled bodies: an enum over the
//! concrete [`Coupling`] types, plus two closed-form test mechanisms (a linear gear and a
//! planar four-bar coupler). Adding a mechanism type is one line in `mechanisms!`.

use crate::mechanism::{AxialRole, CoupledMotion, Coupling, MechanismError, MAX_COUPLED};
use nalgebra::{Isometry3, Translation3, Unit, UnitQuaternion, Vector3, Vector6};

/// Declares [`Mechanism`] with one variant per concrete coupling type and its dispatch.
macro_rules! mechanisms {
    ($($(#[$doc:meta])* $variant:ident($ty:ty),)*) => {
        /// A coupled body's mechanism, one variant per concrete [`Coupling`] type (no `dyn`).
        // Stored once per body and read in place on the hot path: variant sizes do not matter,
        // boxing would only add an indirection.
        #[allow(clippy::large_enum_variant)]
        #[derive(Clone, Debug, PartialEq)]
        pub enum Mechanism {
            $($(#[$doc])* $variant($ty),)*
        }

        impl Coupling for Mechanism {
            fn n_inputs(&self) -> usize {
                match self {
                    $(Mechanism::$variant(m) => m.n_inputs(),)*
                }
            }
            #[inline]
            fn motion(&self, q: &[f64], qd: &[f64]) -> Result<CoupledMotion, MechanismError> {
                match self {
                    $(Mechanism::$variant(m) => m.motion(q, qd),)*
                }
            }
            fn axial_role(&self) -> AxialRole {
                match self {
                    $(Mechanism::$variant(m) => m.axial_role(),)*
                }
            }
            fn same_drive(&self, other: &Self) -> bool {
                match (self, other) {
                    $((Mechanism::$variant(a), Mechanism::$variant(b)) => a.same_drive(b),)*
                    _ => false,
                }
            }
        }
    };
}

mechanisms! {
    /// Rotation about a fixed axis by a linear combination of the inputs (generic gear).
    Linear(LinearCoupling),
    /// Coupler link of a planar four-bar driven by its crank angle (test mechanism).
    FourBar(FourBar),
    /// Harmonic Drive motor rotor (3.1)-(3.2).
    HarmonicDrive(crate::mechanism::harmonic_drive::HarmonicDriveRotor),
    /// Part of the knee roller-screw drive (3.3)-(3.21).
    Knee(crate::mechanism::knee::KneeCoupling),
    /// Part of the ankle drive with two spatial slider-cranks (3.22)-(3.37).
    Ankle(crate::mechanism::ankle::AnkleCoupling),
}

/// Rotation about `axis` by `sum_k ratios[k] q_k`; with one input this is the geared rotor
/// of (3.1)-(3.2).
#[derive(Clone, Debug, PartialEq)]
pub struct LinearCoupling {
    /// Rotation axis (part frame = parent frame at zero angle).
    pub axis: Unit<Vector3<f64>>,
    /// Ratios `N_k` of the inputs (length = number of inputs, at most [`MAX_COUPLED`]).
    pub ratios: Vec<f64>,
}

impl Coupling for LinearCoupling {
    fn n_inputs(&self) -> usize {
        self.ratios.len()
    }
    fn motion(&self, q: &[f64], _qd: &[f64]) -> Result<CoupledMotion, MechanismError> {
        let angle: f64 = self.ratios.iter().zip(q).map(|(r, x)| r * x).sum();
        let mut jacobian = [Vector6::zeros(); MAX_COUPLED];
        for (col, r) in jacobian.iter_mut().zip(&self.ratios) {
            col.fixed_rows_mut::<3>(0)
                .copy_from(&(self.axis.as_ref() * *r));
        }
        Ok(CoupledMotion {
            pose: Isometry3::from_parts(
                Translation3::identity(),
                UnitQuaternion::from_axis_angle(&self.axis, angle),
            ),
            jacobian,
            bias: Vector6::zeros(),
        })
    }
}

/// Planar four-bar in the parent's x-y plane: ground pivots `O_A = 0` and `O_B = (ground, 0)`,
/// crank `O_A A` of length `crank` at angle `q` (the input), coupler `A B` of length
/// `coupler`, rocker `O_B B` of length `rocker`. The part is the coupler: frame origin at `A`,
/// x axis along `A -> B`. Closed form: `B` is the intersection of two circles (branch
/// `elbow = +-1`), so there is no constraint drift.
#[derive(Clone, Debug, PartialEq)]
pub struct FourBar {
    /// Crank length `|O_A A|`.
    pub crank: f64,
    /// Coupler length `|A B|`.
    pub coupler: f64,
    /// Rocker length `|O_B B|`.
    pub rocker: f64,
    /// Ground length `|O_A O_B|`.
    pub ground: f64,
    /// Assembly branch, `+1` or `-1`.
    pub elbow: f64,
}

impl FourBar {
    /// Coupler angle `phi` with `d phi/dq`, `d^2 phi/dq^2` at crank angle `q`, in closed form (implicit differentiation of
    /// the loop closure `A(q) + L_c e(phi) = B` with `|B - O_B| = L_r`).
    pub fn angle_at(&self, q: f64) -> Result<(f64, f64, f64), MechanismError> {
        let (s, c) = q.sin_cos();
        let a = Vector3::new(self.crank * c, self.crank * s, 0.0);
        let d = Vector3::new(self.ground, 0.0, 0.0) - a;
        let dist = d.norm();
        let (lc, lr) = (self.coupler, self.rocker);
        let cos_beta = (lc * lc + dist * dist - lr * lr) / (2.0 * lc * dist);
        if !(-1.0..=1.0).contains(&cos_beta) || dist < 1e-12 {
            return Err(MechanismError::OutOfRange {
                mechanism: "four-bar",
                input: vec![q],
                reason: "the coupler and rocker circles do not intersect",
            });
        }
        let phi = d.y.atan2(d.x) + self.elbow * cos_beta.acos();
        // Loop closure g(q, phi) = |O_B - A(q) - L_c e(phi)|^2 - L_r^2 = 0.
        let e = Vector3::new(phi.cos(), phi.sin(), 0.0);
        let en = Vector3::new(-phi.sin(), phi.cos(), 0.0);
        let at = Vector3::new(-self.crank * s, self.crank * c, 0.0);
        let att = -a;
        let w = d - e * lc; // B - O_B reversed: w = O_B - B
        let g_phi = -2.0 * lc * w.dot(&en);
        let g_q = -2.0 * w.dot(&at);
        if g_phi.abs() < 1e-12 {
            return Err(MechanismError::OutOfRange {
                mechanism: "four-bar",
                input: vec![q],
                reason: "singular (dead-centre) position",
            });
        }
        let dphi = -g_q / g_phi;
        // Second derivative: differentiate w(q, phi(q)) twice; g = w.w - L_r^2.
        let wd = -at - en * (lc * dphi);
        // d/dq of g' = 2 (w'.w' + w.w'') = 0 with w'' = -att - en lc phi'' + e lc phi'^2.
        let known = wd.dot(&wd) + w.dot(&(-att + e * (lc * dphi * dphi)));
        let ddphi = known / (lc * w.dot(&en));
        Ok((phi, dphi, ddphi))
    }
}

impl Coupling for FourBar {
    fn n_inputs(&self) -> usize {
        1
    }
    fn motion(&self, q: &[f64], qd: &[f64]) -> Result<CoupledMotion, MechanismError> {
        let (q, qd) = (q[0], qd[0]);
        let (phi, dphi, ddphi) = self.angle_at(q)?;
        let (s, c) = q.sin_cos();
        let rot = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi);
        let pos = Vector3::new(self.crank * c, self.crank * s, 0.0);
        // Part-frame twist column: omega = dphi e_z; v = R^T dA/dq.
        let rt = rot.inverse();
        let da = Vector3::new(-self.crank * s, self.crank * c, 0.0);
        let dda = Vector3::new(-self.crank * c, -self.crank * s, 0.0);
        let mut jacobian = [Vector6::zeros(); MAX_COUPLED];
        let lin = rt * da;
        jacobian[0] = Vector6::new(0.0, 0.0, dphi, lin.x, lin.y, lin.z);
        // Component-wise d/dt of J qd: angular ddphi qd^2; linear d/dt(R^T da) qd
        //   = (R^T dda - omega x R^T da) qd^2 with omega = dphi e_z (part frame).
        let om = Vector3::new(0.0, 0.0, dphi);
        let lin_rate = rt * dda - om.cross(&lin);
        let bias = Vector6::new(
            0.0,
            0.0,
            ddphi * qd * qd,
            lin_rate.x * qd * qd,
            lin_rate.y * qd * qd,
            lin_rate.z * qd * qd,
        );
        Ok(CoupledMotion {
            pose: Isometry3::from_parts(Translation3::from(pos), rot),
            jacobian,
            bias,
        })
    }
}
