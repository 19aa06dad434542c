//! Lola's knee drive: roller screw in a slider-crank / four-bar (thesis 3.2, eqs. (3.3)-(3.21)).
//!
//! Geometry (planar, all points in the plane `z = 0` of the thigh frame `t`; Fig. 3.1 is not in
//! the extracted text, this is our reading of (3.4)):
//! - the knee axis is the thigh's z axis through the thigh origin; the shank frame `s` is
//!   `A_ts = A_z(q_knee)` (positive `q` rotates the shank about `+t_z`);
//! - the screw housing (motor stator + screw bearing) is hinged to the thigh at pivot `B`
//!   (`pivot_thigh`, thigh coordinates; the thesis's `t_r_b` is `-B`);
//! - the nut's rod end is pinned to the shank lever at `A` (`pin_shank`, shank coordinates,
//!   the thesis's `s_r_a`);
//! - loop (3.4): `r_screw = A_ts s_r_a - B`, `l_screw = |r_screw|` is the nut travel measured
//!   from the pivot, and the screw (rotor) turns by `phi = N_screw l_screw + offset` (3.3),
//!   `N_screw = 2 pi / lead`.
//!
//! The thesis has no separate push rod: the nut's rod end itself is pinned at `A`. The part that
//! closes the loop is the tilting screw housing, whose axis passes through `A`.
//!
//! Parts ([`KneePart`], each a [`Coupling`] with the knee angle as its single input, relative to
//! the thigh): the housing (frame at `B`), the nut (housing axes, origin at the nut pin) and the
//! rotor/screw (housing frame spun by `phi` about the screw axis, origin at `B`). Part frames:
//! z along the screw axis from `B` towards `A`, y along the knee axis `t_z`, `x = y x z`.
//!
//! `screw_tilt` switches the tilt terms (3.15)-(3.21): when on, the screw axis is the exact
//! unit vector `r_screw / l_screw` (tilt angle `alpha` of (3.15) about `t_z`, rates (3.17)-(3.18),
//! rotor twist (3.19)-(3.21)); when off (the thesis's simplification `e_z = const`), the axis is
//! frozen at its direction for `q = q_ref`, the nut moves along that fixed axis by `l_screw`
//! (so it meets `A` exactly only at `q_ref`), and the rotor twist is the pure spin (3.8)-(3.11).
//! The housing's body y component of the angular velocity is `d theta / dt`, `theta` the angle
//! of `r_screw` about `+t_z`; the thesis's `alpha = atan(r_x / r_y)` (3.15) is measured the
//! other way (`alpha_dot = -theta_dot` for `r_y < 0`), while (3.17) `r x rdot / l^2` is `theta_dot`.
//! Derivatives are exact: from [`super::jet`] in the reference [`Coupling::motion`], in closed
//! form (`closure.rs`) in [`KneeCoupling::relative_cached`], [`KneeDrive::transmission`] and
//! the spin rows (tested equal to round-off); (3.6)'s numerator is read as
//! `rdot.rdot + r.rddot - ldot^2` (the extracted text drops the square).

mod cached;
mod closure;

pub use cached::KneeLoopCache;

use super::cache::instance_id;
use super::jet::{bad_param, input_arrays, seed_inputs, FrameJet, SJet, VJet};
use super::{CoupledMotion, Coupling, MechanismError};
use nalgebra::{Vector2, Vector3};
use std::f64::consts::PI;
use std::ops::Add;

const NAME: &str = "knee drive";

/// Samples of the working range checked by [`KneeDrive::new`].
const RANGE_SAMPLES: usize = 256;

/// Parameters of the knee roller-screw drive, eqs. (3.3)-(3.21).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KneeDriveParams {
    /// Screw-housing pivot `B` in the thigh frame (x, y) \[m].
    pub pivot_thigh: Vector2<f64>,
    /// Nut pin `A` on the shank lever in the shank frame (x, y) \[m].
    pub pin_shank: Vector2<f64>,
    /// Roller-screw lead `P_lead` \[m/rev]; `N_screw = 2 pi / P_lead` (3.3).
    pub lead: f64,
    /// Motor (screw) angle at zero nut travel \[rad].
    pub motor_offset: f64,
    /// Model the screw-axis tilt (3.15)-(3.21); off: fixed axis (3.8)-(3.11).
    pub screw_tilt: bool,
    /// Knee angle at which the fixed screw axis (tilt off) is taken \[rad].
    pub q_ref: f64,
    /// Lower end of the knee working range \[rad].
    pub q_min: f64,
    /// Upper end of the knee working range \[rad].
    pub q_max: f64,
}

impl Default for KneeDriveParams {
    /// Lola-like guess: 5 mm lead (`N_screw ~ 1256.6 1/m`), pivot 0.30 m up the thigh, a 57 mm
    /// lever behind the knee, range -0.05..2.0 rad (stroke ~ 75 mm). Not Lola's real data.
    fn default() -> Self {
        Self {
            pivot_thigh: Vector2::new(-0.04, 0.30),
            pin_shank: Vector2::new(-0.045, 0.035),
            lead: 0.005,
            motor_offset: 0.0,
            screw_tilt: true,
            q_ref: 0.0,
            q_min: -0.05,
            q_max: 2.0,
        }
    }
}

/// Scalar transmission of the knee drive at one knee angle, (3.4)-(3.7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KneeTransmission {
    /// Nut travel `x = l_screw` from the pivot \[m] (3.4).
    pub travel: f64,
    /// `dx/dq_knee` \[m/rad] (3.5).
    pub dtravel: f64,
    /// `d2x/dq_knee^2` \[m/rad^2] (3.6).
    pub ddtravel: f64,
    /// Motor angle `N_screw x + offset` \[rad] (3.3).
    pub motor_angle: f64,
}

/// The parts of the knee drive that move relative to the thigh.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KneePart {
    /// Screw housing hinged at `B` (tilts with `screw_tilt`; fixed otherwise).
    Housing,
    /// Roller-screw nut (housing axes, origin at the nut pin).
    Nut,
    /// Motor rotor and screw (housing frame spun by `phi_screw`).
    Rotor,
}

/// A validated knee drive, (3.3)-(3.21).
#[derive(Debug, Clone, Copy)]
pub struct KneeDrive {
    /// Construction identity ([`super::cache::instance_id`]), the cache key; ignored by `==`.
    id: u64,
    params: KneeDriveParams,
    /// Screw axis used when `screw_tilt` is off.
    fixed_axis: Vector3<f64>,
    /// Sign of `dl/dq` over the working range (+1 or -1).
    sign: f64,
}

impl PartialEq for KneeDrive {
    /// Equal parameters (the construction identity is not compared).
    fn eq(&self, o: &Self) -> bool {
        (self.params, self.fixed_axis, self.sign) == (o.params, o.fixed_axis, o.sign)
    }
}

impl KneeDrive {
    /// Validates the parameters: finite, positive lead, `q_min <= q_ref <= q_max`, and a
    /// strictly monotone, non-degenerate transmission over the working range.
    pub fn new(params: KneeDriveParams) -> Result<Self, MechanismError> {
        let p = &params;
        let finite = [p.lead, p.motor_offset, p.q_ref, p.q_min, p.q_max]
            .iter()
            .chain(p.pivot_thigh.iter())
            .chain(p.pin_shank.iter())
            .all(|x| x.is_finite());
        if !finite || p.lead <= 0.0 {
            return Err(bad_param(NAME, "all values finite, lead > 0"));
        }
        if !(p.q_min < p.q_max && (p.q_min..=p.q_max).contains(&p.q_ref)) {
            return Err(bad_param(
                NAME,
                "q_min < q_max and q_ref within [q_min, q_max]",
            ));
        }
        let mut drive = Self {
            id: instance_id(),
            params,
            fixed_axis: Vector3::zeros(),
            sign: 1.0,
        };
        let r_ref = drive.screw_vector(SJet::constant(p.q_ref)).v;
        if r_ref.norm() <= 0.0 {
            return Err(bad_param(NAME, "pin A coincides with pivot B"));
        }
        drive.fixed_axis = r_ref.normalize();
        drive.sign = drive.transmission(p.q_min)?.dtravel.signum();
        let scale = p.pin_shank.norm();
        for i in 0..=RANGE_SAMPLES {
            let q = p.q_min + (p.q_max - p.q_min) * i as f64 / RANGE_SAMPLES as f64;
            if drive.transmission(q)?.dtravel * drive.sign <= 1e-6 * scale {
                return Err(bad_param(
                    NAME,
                    "transmission not monotone over [q_min, q_max]",
                ));
            }
        }
        Ok(drive)
    }

    /// The parameters.
    pub fn params(&self) -> &KneeDriveParams {
        &self.params
    }

    /// Screw ratio `N_screw = 2 pi / P_lead` \[rad/m] (3.3).
    pub fn screw_ratio(&self) -> f64 {
        2.0 * PI / self.params.lead
    }

    /// `r_screw = A_ts s_r_a - B` (3.4) as a jet of the knee angle.
    fn screw_vector(&self, q: SJet<1>) -> VJet<1> {
        let a = &self.params.pin_shank;
        let b = &self.params.pivot_thigh;
        VJet::rotate_constant(&Vector3::new(a.x, a.y, 0.0), &Vector3::z_axis(), q)
            .offset(&Vector3::new(-b.x, -b.y, 0.0))
    }

    /// `l_screw` as a jet, `OutOfRange` when the pin meets the pivot.
    fn screw_length(&self, r: &VJet<1>, q: f64) -> Result<SJet<1>, MechanismError> {
        if r.v.norm() <= 1e-9 * self.params.pin_shank.norm().max(1e-3) {
            return Err(MechanismError::OutOfRange {
                mechanism: NAME,
                input: vec![q],
                reason: "l_screw = 0 in (3.4)",
            });
        }
        Ok(r.norm())
    }

    /// Nut travel, its first and second derivative and the motor angle, (3.3)-(3.7).
    pub fn transmission(&self, q: f64) -> Result<KneeTransmission, MechanismError> {
        let ([q], _) = input_arrays::<1>(NAME, &[q], &[0.0])?;
        let c = self.solve(q)?;
        Ok(KneeTransmission {
            travel: c.l,
            dtravel: c.l_q,
            ddtravel: c.l_qq,
            motor_angle: self.screw_ratio() * c.l + self.params.motor_offset,
        })
    }

    /// Motor angle `N_screw l_screw(q) + offset` for a knee angle (3.3).
    pub fn motor_angle(&self, q: f64) -> Result<f64, MechanismError> {
        Ok(self.transmission(q)?.motor_angle)
    }

    /// Knee angle from a motor angle by safeguarded Newton-Raphson on (3.3) over the working
    /// range (footnote 5 of ch. 3); `OutOfRange` if the motor angle is not reached in range.
    pub fn knee_angle(&self, motor_angle: f64) -> Result<f64, MechanismError> {
        let p = &self.params;
        let out = |reason| MechanismError::OutOfRange {
            mechanism: NAME,
            input: vec![motor_angle],
            reason,
        };
        if !motor_angle.is_finite() {
            return Err(MechanismError::BadInput {
                mechanism: NAME,
                reason: "non-finite motor angle".into(),
            });
        }
        let target = (motor_angle - p.motor_offset) / self.screw_ratio();
        let residual = |q: f64| -> Result<(f64, f64), MechanismError> {
            let t = self.transmission(q)?;
            Ok(((t.travel - target) * self.sign, t.dtravel * self.sign))
        };
        let (mut lo, mut hi) = (p.q_min, p.q_max);
        let (f_lo, f_hi) = (residual(lo)?.0, residual(hi)?.0);
        if f_lo > 0.0 || f_hi < 0.0 {
            return Err(out(
                "motor angle outside the range of (3.3) over [q_min, q_max]",
            ));
        }
        let mut q = 0.5 * (lo + hi);
        let mut f = f64::INFINITY;
        for _ in 0..100 {
            let (fq, dfq) = residual(q)?;
            f = fq;
            if fq == 0.0 {
                return Ok(q);
            }
            if fq < 0.0 {
                lo = q
            } else {
                hi = q
            }
            let newton = q - fq / dfq;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if (next - q).abs() <= 1e-15 * (1.0 + q.abs()) || hi - lo <= 1e-15 * (1.0 + q.abs()) {
                return Ok(next);
            }
            q = next;
        }
        Err(MechanismError::NoConvergence {
            mechanism: NAME,
            iterations: 100,
            residual: f.abs(),
        })
    }

    /// The [`Coupling`] of one part of this drive.
    pub fn part(&self, part: KneePart) -> KneeCoupling {
        KneeCoupling { drive: *self, part }
    }

    /// Frame jets of a part at the knee-angle jet `q`.
    fn frame(&self, part: KneePart, q: SJet<1>) -> Result<FrameJet<1>, MechanismError> {
        Ok(self.frame_of(part, &self.close_loop(q)?))
    }

    /// Closes the loop (3.4) at `q`: the housing frame and the screw length, shared by all parts.
    fn close_loop(&self, q: SJet<1>) -> Result<KneeLoop, MechanismError> {
        let r = self.screw_vector(q);
        let length = self.screw_length(&r, q.v)?;
        let axis = if self.params.screw_tilt {
            r.scale(length.recip())
        } else {
            VJet::constant(self.fixed_axis)
        };
        let b = &self.params.pivot_thigh;
        let pivot = VJet::constant(Vector3::new(b.x, b.y, 0.0));
        let housing = FrameJet::from_direction(axis, &Vector3::z(), pivot);
        Ok(KneeLoop { housing, length })
    }

    /// Frame jets of a part from the closed loop (3.8)-(3.21).
    fn frame_of(&self, part: KneePart, lp: &KneeLoop) -> FrameJet<1> {
        let (housing, l) = (lp.housing, lp.length);
        match part {
            KneePart::Housing => housing,
            KneePart::Nut => FrameJet {
                p: housing.p.add(housing.z.scale(l)),
                ..housing
            },
            KneePart::Rotor => {
                let phi = l
                    .scale(self.screw_ratio())
                    .add(SJet::constant(self.params.motor_offset));
                housing.spin_z(phi)
            }
        }
    }
}

/// The knee loop (3.4) closed at one input: housing frame jets and screw length `l_screw`.
#[derive(Debug, Clone, Copy)]
struct KneeLoop {
    housing: FrameJet<1>,
    length: SJet<1>,
}

/// One part of a [`KneeDrive`] as a [`Coupling`] (input: the knee angle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KneeCoupling {
    /// The drive.
    pub drive: KneeDrive,
    /// Which part.
    pub part: KneePart,
}

impl Coupling for KneeCoupling {
    fn n_inputs(&self) -> usize {
        1
    }

    /// The housing carries the rotor (spinning about its z axis) and the nut (sliding along
    /// it).
    fn axial_role(&self) -> super::AxialRole {
        match self.part {
            KneePart::Housing => super::AxialRole::Carries,
            KneePart::Rotor => super::AxialRole::Rides { slides: false },
            KneePart::Nut => super::AxialRole::Rides { slides: true },
        }
    }

    /// Parts of the same drive (equal drive parameters; the inputs tell two knees apart).
    fn same_drive(&self, other: &Self) -> bool {
        self.drive == other.drive
    }

    /// Pose, Jacobian and bias of the part relative to the thigh, (3.8)-(3.21).
    fn motion(&self, q_in: &[f64], qd_in: &[f64]) -> Result<CoupledMotion, MechanismError> {
        let [q] = seed_inputs::<1>(NAME, q_in, qd_in)?;
        Ok(self.drive.frame(self.part, q)?.motion())
    }
}
