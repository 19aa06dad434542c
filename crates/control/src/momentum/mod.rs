//! Vertical angular momentum compensation, reference and minimisation (thesis ch. 7).
//!
//! - [`jacobian`]: `J_L`, `J_Lz`, `L_z` and its rate (7.1)-(7.2), `I_zz^CoG` (7.11).
//! - [`compensation`]: producing/reducing split and the null-space term (7.3)-(7.9).
//! - [`reference`](mod@reference): the cubic per-step reference `L_ref,z` (7.10)-(7.12).
//! - [`minimisation`]: the weight `W = delta E + J_Lz^T J_Lz` (7.13)-(7.15).
//! - [`arm_swing`]: the reference method's arm CoG targets from the opposite leg (7.3.1).
//!
//! One IK cycle (1 kHz) with compensation (7.3.2): after the centroidal computation the CoM
//! task needs anyway (`Centroidal::compute_matrix`), `VerticalMomentum::update(&centroidal)`;
//! then `Compensation::add_to(J_Lz, qdot_prev, L_ref,z(t), &mut y)` on top of the cost
//! gradient `y = grad H` and `ik::RmrcProblem::null_space = Some((&y, alpha_N))`. `y` has
//! the sign of a gradient (RMRC applies `-alpha_N N W^-1 y`); to get (7.8) exactly,
//! `y = alpha (dH/dq)^T + qdot_r` with unit null-space gain, set the compensation gain to
//! `1 / alpha_N`. With minimisation (7.5) instead: `MomentumMinimisation::update(J_Lz, &mut W)`
//! and pass `W` as the RMRC weight. `L_ref,z(t)` comes from [`MomentumReference::sample`].

pub mod arm_swing;
pub mod compensation;
pub mod error;
pub mod jacobian;
pub mod minimisation;
pub mod reference;

pub use arm_swing::{ArmSwing, ArmSwingNominal, ArmTargets, PointTarget};
pub use compensation::{
    Compensation, CompensationLaw, CompensationTerms, LOLA_ARMS, LOLA_ARM_FLEXION,
};
pub use error::MomentumError;
pub use jacobian::{vertical_inertia, vertical_momentum_rate, LzRate, VerticalMomentum};
pub use minimisation::MomentumMinimisation;
pub use reference::MomentumReference;
