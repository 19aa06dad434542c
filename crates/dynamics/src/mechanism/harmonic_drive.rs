//! Harmonic Drive gear rotor (thesis 3.1, eqs. (3.1)-(3.2)).
//!
//! The motor rotor of a joint with gear ratio `N` turns by `N q` about its own z axis while
//! the joint turns by `q`. Its frame `k` sits at a fixed point `r_0` of the parent body `p` with
//! initial orientation `A_pk'` (the constant `A_k'p` of (3.2), stored here in the
//! part-to-parent direction used by [`super::CoupledMotion`]); hence
//! `A_pk = A_pk' A_z(N q)`, the relative twist is `[0, 0, N, 0, 0, 0]^T qd` in the rotor frame
//! (3.1), constant, so the bias is zero. An optional constant `offset` is added to the rotor
//! angle (encoder zero).

use super::jet::bad_param;
use super::{CoupledMotion, Coupling, MechanismError, MAX_COUPLED};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3, Vector6};

const NAME: &str = "harmonic drive rotor";

/// Parameters of a Harmonic Drive rotor, eqs. (3.1)-(3.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HarmonicDriveParams {
    /// Gear ratio `N` (rotor turns per joint turn; sign gives the direction), Lola-like ~100.
    pub ratio: f64,
    /// Initial rotor orientation `A_pk'` (rotor frame -> parent frame); the rotor spins about its z.
    pub orientation: UnitQuaternion<f64>,
    /// Rotor origin in the parent frame \[m].
    pub position: Vector3<f64>,
    /// Rotor angle at `q = 0` \[rad].
    pub offset: f64,
}

impl Default for HarmonicDriveParams {
    /// Gear ratio 100, rotor coaxial with the parent's z axis at the parent origin.
    fn default() -> Self {
        Self {
            ratio: 100.0,
            orientation: UnitQuaternion::identity(),
            position: Vector3::zeros(),
            offset: 0.0,
        }
    }
}

/// A validated Harmonic Drive rotor: a [`Coupling`] with one input (the joint angle), (3.1)-(3.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HarmonicDriveRotor {
    params: HarmonicDriveParams,
}

impl HarmonicDriveRotor {
    /// Validates the parameters (finite, non-zero ratio).
    pub fn new(params: HarmonicDriveParams) -> Result<Self, MechanismError> {
        let finite = params.ratio.is_finite()
            && params.offset.is_finite()
            && params.position.iter().all(|x| x.is_finite())
            && params.orientation.coords.iter().all(|x| x.is_finite());
        if !finite || params.ratio == 0.0 {
            return Err(bad_param(
                NAME,
                "ratio must be finite and non-zero, all values finite",
            ));
        }
        Ok(Self { params })
    }

    /// The parameters.
    pub fn params(&self) -> &HarmonicDriveParams {
        &self.params
    }

    /// Rotor (motor) angle `N q + offset` for joint angle `q`.
    pub fn rotor_angle(&self, q: f64) -> f64 {
        self.params.ratio * q + self.params.offset
    }

    /// Joint angle from a rotor angle (exact inverse of [`Self::rotor_angle`]).
    pub fn joint_angle(&self, rotor_angle: f64) -> f64 {
        (rotor_angle - self.params.offset) / self.params.ratio
    }
}

impl Coupling for HarmonicDriveRotor {
    fn n_inputs(&self) -> usize {
        1
    }

    /// Spins about its z axis at `N` times the joint rate (3.1).
    fn axial_role(&self) -> super::AxialRole {
        super::AxialRole::Geared(crate::spatial::Motion::new(
            Vector3::new(0.0, 0.0, self.params.ratio),
            Vector3::zeros(),
        ))
    }

    /// Pose `A_pk' A_z(N q + offset)` (3.2), Jacobian `[0 0 N 0 0 0]^T` and zero bias (3.1).
    fn motion(&self, q_in: &[f64], qd_in: &[f64]) -> Result<CoupledMotion, MechanismError> {
        super::jet::seed_inputs::<1>(NAME, q_in, qd_in)?;
        let p = &self.params;
        let spin = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), self.rotor_angle(q_in[0]));
        let mut jacobian = [Vector6::zeros(); MAX_COUPLED];
        jacobian[0][2] = p.ratio;
        Ok(CoupledMotion {
            pose: Isometry3::from_parts(Translation3::from(p.position), p.orientation * spin),
            jacobian,
            bias: Vector6::zeros(),
        })
    }
}
