//! Camera vergence drive, kinematics only (thesis 3.4, eqs. (3.38)-(3.45)).
//!
//! Geometry of the left half (Fig. 3.3 is not in the extracted text; our reading of (3.38)):
//! - frame `t` is the tilt segment; the actuator turns a double lever about the axis through
//!   `A' = (r_a,x, 0, 0)` parallel to `t_x`; the lever end is `A = (r_a,x, l_lever sin phi,
//!   l_lever cos phi)` (3.38), `phi = phi_lever`;
//! - the camera receptacle `k` turns about the axis through `r_k` parallel to `t_y`:
//!   `A_tk = A_y(q_verg / 2)` — the vergence angle `q_verg` is the angle between the two viewing
//!   directions and the mechanism is symmetric, so each camera turns by half of it (our choice:
//!   the text does not say how `q_verg` splits);
//! - the receptacle's coupler joint is `B = r_k + A_tk k_r_b`, with `r_k` and `k_r_b` in the
//!   `x-z` plane so `r_b,y = 0`; the coupler `|A - B| = l_coupler` closes the loop (3.39),
//!   giving (3.40)-(3.42): `phi_lever = acos(s / (2 l_lever r_b,z))`,
//!   `s = (r_a,x - r_b,x)^2 + l_lever^2 - l_coupler^2 + r_b,z^2`; `acos` picks the branch
//!   `phi in [0, pi]`.
//! - motor angle `N_verg (phi_lever - phi_0)` with `phi_0 = phi_lever(0)` (3.43).
//!
//! The derivative (3.44)-(3.45) (and the second derivative) are exact, via [`super::jet`].
//! Differentiating (3.41) by hand gives the numerator
//! `2 r_b,z (r_a,x - r_b,x) (grad r_b)_x + (s - 2 r_b,z^2) (grad r_b)_z`; the extracted (3.44)
//! shows `- s (grad r_b)_z` instead (it drops `ds/dq`'s `r_b,z` term and the sign). The tests
//! check the hand-derived form and finite differences.

use super::jet::{bad_param, seed_inputs, SJet, VJet};
use super::MechanismError;
use nalgebra::{Vector2, Vector3};
use std::ops::{Add, Mul, Sub};

const NAME: &str = "camera vergence drive";

/// Samples of the working range checked by [`VergenceDrive::new`].
const RANGE_SAMPLES: usize = 256;

/// Parameters of the camera vergence drive, eqs. (3.38)-(3.45).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VergenceParams {
    /// `r_a,x`: x coordinate of the lever axis point `A'` in the tilt frame \[m].
    pub lever_axis_x: f64,
    /// Lever arm length `l_lever` \[m].
    pub lever_length: f64,
    /// Coupler link length `l_coupler` \[m].
    pub coupler_length: f64,
    /// Receptacle pivot `t_r_k` (x, z) in the tilt frame \[m].
    pub receptacle_pivot: Vector2<f64>,
    /// Coupler joint `k_r_b` (x, z) in the receptacle frame \[m].
    pub receptacle_joint: Vector2<f64>,
    /// Gear ratio `N_verg` from the motor to the lever (3.43).
    pub ratio: f64,
    /// Lower end of the vergence working range \[rad].
    pub q_min: f64,
    /// Upper end of the vergence working range \[rad].
    pub q_max: f64,
}

impl Default for VergenceParams {
    /// Plausible small camera-head geometry: 20 mm lever, ~44 mm coupler (lever at 90 deg for
    /// `q_verg = 0`), receptacle pivot 50 mm ahead of the lever axis, ratio 100, vergence
    /// -0.3..0.6 rad. Not Lola's real data.
    fn default() -> Self {
        Self {
            lever_axis_x: 0.0,
            lever_length: 0.02,
            coupler_length: (0.03f64.powi(2) + 0.02f64.powi(2) + 0.025f64.powi(2)).sqrt(),
            receptacle_pivot: Vector2::new(0.05, 0.0),
            receptacle_joint: Vector2::new(-0.02, 0.025),
            ratio: 100.0,
            q_min: -0.3,
            q_max: 0.6,
        }
    }
}

/// Lever angle and its derivatives at one vergence angle, (3.41)-(3.44).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeverKinematics {
    /// `phi_lever` \[rad] (3.41).
    pub phi: f64,
    /// Jacobian `d phi_lever / d q_verg` (3.44).
    pub jacobian: f64,
    /// `d2 phi_lever / d q_verg^2` (Jacobian derivative per unit rate squared).
    pub djacobian: f64,
    /// Motor angle `N_verg (phi_lever - phi_0)` \[rad] (3.43).
    pub motor_angle: f64,
}

/// A validated camera vergence drive, (3.38)-(3.45).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VergenceDrive {
    params: VergenceParams,
    /// Lever angle at `q_verg = 0` (3.43).
    phi0: f64,
}

impl VergenceDrive {
    /// Validates the parameters: finite, positive lengths, non-zero ratio, `q_min < q_max` and
    /// a real, non-singular solution of (3.41) over the working range (and at `q_verg = 0`).
    pub fn new(params: VergenceParams) -> Result<Self, MechanismError> {
        let p = &params;
        let finite = [
            p.lever_axis_x,
            p.lever_length,
            p.coupler_length,
            p.ratio,
            p.q_min,
            p.q_max,
        ]
        .iter()
        .chain(p.receptacle_pivot.iter())
        .chain(p.receptacle_joint.iter())
        .all(|x| x.is_finite());
        if !finite || p.lever_length <= 0.0 || p.coupler_length <= 0.0 || p.ratio == 0.0 {
            return Err(bad_param(
                NAME,
                "finite values, positive lengths, non-zero ratio",
            ));
        }
        if p.q_min >= p.q_max {
            return Err(bad_param(NAME, "q_min < q_max"));
        }
        let mut drive = Self { params, phi0: 0.0 };
        drive.phi0 = drive.lever(0.0)?.phi;
        for i in 0..=RANGE_SAMPLES {
            let q = p.q_min + (p.q_max - p.q_min) * i as f64 / RANGE_SAMPLES as f64;
            drive.lever(q)?;
        }
        Ok(drive)
    }

    /// The parameters.
    pub fn params(&self) -> &VergenceParams {
        &self.params
    }

    /// `phi_lever(q_verg)`, its Jacobian (3.44), second derivative and the motor angle (3.43);
    /// `OutOfRange` where (3.41) has no real, non-singular solution.
    pub fn lever(&self, q_verg: f64) -> Result<LeverKinematics, MechanismError> {
        let [q] = seed_inputs::<1>(NAME, &[q_verg], &[1.0])?;
        let p = &self.params;
        let kb = Vector3::new(p.receptacle_joint.x, 0.0, p.receptacle_joint.y);
        let rk = Vector3::new(p.receptacle_pivot.x, 0.0, p.receptacle_pivot.y);
        let rb = VJet::constant(kb)
            .rotate(&Vector3::y_axis(), q.scale(0.5))
            .offset(&rk);
        let (rbx, rbz) = (rb.dot_const(&Vector3::x()), rb.dot_const(&Vector3::z()));
        let dx = SJet::constant(p.lever_axis_x).sub(rbx);
        let ll = p.lever_length;
        let s = dx
            .mul(dx)
            .add(rbz.mul(rbz))
            .add(SJet::constant(ll * ll - p.coupler_length.powi(2)));
        let out = |reason| MechanismError::OutOfRange {
            mechanism: NAME,
            input: vec![q_verg],
            reason,
        };
        if rbz.v.abs() <= 1e-12 * ll {
            return Err(out("r_b,z = 0 in (3.41)"));
        }
        let c = s.mul(rbz.scale(2.0 * ll).recip());
        if c.v.abs() >= 1.0 - 1e-12 {
            return Err(out("|s / (2 l_lever r_b,z)| >= 1 in (3.41)"));
        }
        let phi = c.acos();
        Ok(LeverKinematics {
            phi: phi.v,
            jacobian: phi.d[0],
            djacobian: phi.acc,
            motor_angle: p.ratio * (phi.v - self.phi0),
        })
    }

    /// `phi_lever(q_verg)` (3.41).
    pub fn phi_lever(&self, q_verg: f64) -> Result<f64, MechanismError> {
        Ok(self.lever(q_verg)?.phi)
    }

    /// Lever end `A` and coupler joint `B` in the tilt frame (loop-closure check, (3.38)).
    pub fn joint_points(
        &self,
        q_verg: f64,
    ) -> Result<(Vector3<f64>, Vector3<f64>), MechanismError> {
        let phi = self.phi_lever(q_verg)?;
        let p = &self.params;
        let a = Vector3::new(
            p.lever_axis_x,
            p.lever_length * phi.sin(),
            p.lever_length * phi.cos(),
        );
        let kb = Vector3::new(p.receptacle_joint.x, 0.0, p.receptacle_joint.y);
        let rk = Vector3::new(p.receptacle_pivot.x, 0.0, p.receptacle_pivot.y);
        let rot = nalgebra::Rotation3::from_axis_angle(&Vector3::y_axis(), 0.5 * q_verg);
        Ok((a, rk + rot * kb))
    }
}
