//! Closed-form mechanisms that couple a body's relative motion to generalized coordinates of
//! other joints (thesis ch. 3): the interface between drive-train kinematics and the
//! multibody algorithms with sub-systems (2.6-2.9).
//!
//! A mechanism *part* (a screw nut, a push rod, a motor rotor, ...) moves relative to its
//! parent body as a nonlinear function of up to [`MAX_COUPLED`] input coordinates `q_in`
//! (joint coordinates of other bodies). [`Coupling::motion`] returns, at `(q_in, qd_in)`:
//! - the pose of the part's frame in the parent's frame (`A_pk`, `r_PO`);
//! - the relative Jacobian `J`: columns `d/dqd_j` of the relative twist
//!   `[omega_rel; v_rel]`, where `skew(omega_rel) = A_pk^T dA_pk/dt` and `v_rel = A_pk^T dr_PO/dt`
//!   (both in **part-frame** coordinates, angular part first like [`crate::spatial::Motion`]);
//! - the bias `Jdot qd`: the component-wise time derivative of `J(q_in(t))` times `qd_in`, so
//!   that `d/dt [omega_rel; v_rel] = J qdd_in + bias` (component-wise derivative of the
//!   part-frame components).
//!
//! These definitions are operational: every implementation is checked against central finite
//! differences of `pose` and `J` along `q_in + qd_in t`.
//!
//! The ankle and knee drives have two evaluations: [`Coupling::motion`] propagates jets
//! ([`jet`]) and is the reference; `relative_cached` (used by the kinematics) is the same
//! algebra written out in closed form, solves each drive's loop once per kinematics pass into
//! a small cache ([`cache`]) shared by the drive's parts, and [`crate::Data::coupled_spin_row`]
//! ([`rows`]) reads the motor rows back from it. Both are tested against each other and
//! against finite differences.

pub mod ankle;
pub mod cache;
pub mod harmonic_drive;
pub mod jet;
pub mod knee;
pub mod rows;
pub mod vergence;

use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3, Vector6};
use thiserror::Error;

/// Largest number of input coordinates a coupled part may depend on.
pub const MAX_COUPLED: usize = 3;

/// Relative kinematics of one coupled part at `(q_in, qd_in)` (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoupledMotion {
    /// Pose of the part frame in the parent body's frame.
    pub pose: Isometry3<f64>,
    /// Relative-twist Jacobian columns (part frame, `[angular; linear]`); unused columns zero.
    pub jacobian: [Vector6<f64>; MAX_COUPLED],
    /// Relative-acceleration bias `Jdot qd_in` (part frame, `[angular; linear]`).
    pub bias: Vector6<f64>,
}

/// [`CoupledMotion`] with the pose as a rotation matrix and origin: the quaternion-free form
/// the kinematics consumes (no matrix -> quaternion -> matrix round trip on the hot path).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RelativeMotion {
    /// Rotation `A_pk`: the part axes as columns, in parent coordinates.
    pub rot: Matrix3<f64>,
    /// Origin of the part frame in parent coordinates.
    pub pos: Vector3<f64>,
    /// Relative-twist Jacobian columns (as in [`CoupledMotion::jacobian`]).
    pub jacobian: [Vector6<f64>; MAX_COUPLED],
    /// Relative-acceleration bias (as in [`CoupledMotion::bias`]).
    pub bias: Vector6<f64>,
}

impl RelativeMotion {
    /// The same motion with the pose as an isometry (rotation converted to a quaternion).
    pub fn to_coupled(&self) -> CoupledMotion {
        let rot = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(self.rot));
        CoupledMotion {
            pose: Isometry3::from_parts(Translation3::from(self.pos), rot),
            jacobian: self.jacobian,
            bias: self.bias,
        }
    }

    /// The motion of a [`CoupledMotion`] (quaternion converted to a rotation matrix).
    pub fn from_coupled(m: &CoupledMotion) -> Self {
        Self {
            rot: m.pose.rotation.to_rotation_matrix().into_inner(),
            pos: m.pose.translation.vector,
            jacobian: m.jacobian,
            bias: m.bias,
        }
    }
}

/// Motion of a part about or along an axis fixed in its carrier at a configuration-dependent
/// rate (a roller-screw rotor's spin or its nut's travel, (3.22), (3.29), (3.32)-(3.33)).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AxialMotion {
    /// Spin angle or travel `x` along the axis.
    pub travel: f64,
    /// `d x / d q_in` per input (unused entries zero).
    pub row: [f64; MAX_COUPLED],
    /// `x_dot = row . qd_in`.
    pub speed: f64,
    /// `x_ddot` at `qdd_in = 0`: `qd_in^T (d row / d q_in) qd_in`.
    pub bias: f64,
}

/// Why a mechanism cannot be evaluated at the given input.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum MechanismError {
    /// The input lies outside the mechanism's assembly range (no real solution of the loop).
    #[error("{mechanism}: input {input:?} outside the assembly range ({reason})")]
    OutOfRange {
        /// Mechanism name.
        mechanism: &'static str,
        /// The offending input coordinates.
        input: Vec<f64>,
        /// What failed, e.g. "discriminant < 0 in (3.31)".
        reason: &'static str,
    },
    /// Wrong number of inputs or a non-finite value.
    #[error("{mechanism}: {reason}")]
    BadInput {
        /// Mechanism name.
        mechanism: &'static str,
        /// What is wrong.
        reason: String,
    },
    /// A Newton-Raphson inversion did not converge.
    #[error("{mechanism}: Newton-Raphson did not converge after {iterations} iterations (residual {residual:e})")]
    NoConvergence {
        /// Mechanism name.
        mechanism: &'static str,
        /// Iterations performed.
        iterations: usize,
        /// Final residual norm.
        residual: f64,
    },
}

/// How a part moves, as far as the lumped members of a sub-system need to know (the axial
/// kinds of the O(n) sub-system step, (2.76)): parts that only spin about or slide along one
/// axis are lumped into the body that carries them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AxialRole {
    /// None of the below: the general member kinematics.
    General,
    /// Spins about the constant twist `column` (part frame) at its single input's rate: a
    /// geared rotor.
    Geared(crate::spatial::Motion),
    /// Spins about its frame's z axis (a screw's rotor).
    Spins,
    /// Slides along its frame's z axis (a screw's nut).
    Slides,
    /// Spins about (`slides: false`) or slides along the z axis of its drive's carrier part
    /// (the part of the same drive and inputs that [`AxialRole::Carries`], see
    /// [`Coupling::same_drive`]), in that part's frame.
    Rides {
        /// Slides rather than spins.
        slides: bool,
    },
    /// Carries the riders of its drive.
    Carries,
}

/// A closed-form mechanism part whose relative motion depends on input coordinates.
pub trait Coupling {
    /// Number of input coordinates (`<= MAX_COUPLED`).
    fn n_inputs(&self) -> usize;
    /// Relative pose, Jacobian and bias at `(q_in, qd_in)` (slices of length `n_inputs`).
    fn motion(&self, q_in: &[f64], qd_in: &[f64]) -> Result<CoupledMotion, MechanismError>;
    /// How the part moves for the sub-system step ([`AxialRole::General`] unless told).
    fn axial_role(&self) -> AxialRole {
        AxialRole::General
    }
    /// Whether `other` is a part of the same drive (a rider's carrier is found by it).
    fn same_drive(&self, _other: &Self) -> bool
    where
        Self: Sized,
    {
        false
    }
}
