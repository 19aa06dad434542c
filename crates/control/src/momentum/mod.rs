//! Vertical angular momentum compensation, reference and minimisation (thesis ch. 7).
//!
//! - [`jacobian`]: `J_L`, `J_Lz`, `L_z` and its rate (7.1)-(7.2), `I_zz^CoG` (7.11).
//! - [`compensation`]: producing/reducing split and gain of the compensation (7.3)-(7.9).
//! - [`in_cycle`]: the compensation solved within the IK cycle, inside the joint limits.
//! - [`reference`](mod@reference): the cubic per-step reference `L_ref,z` (7.10)-(7.12).
//! - [`minimisation`]: the weight `W = delta E + J_Lz^T J_Lz` (7.13)-(7.15).
//! - [`arm_swing`]: the reference method's arm CoG targets from the opposite leg (7.3.1).
//!
//! One IK cycle (1 kHz) with compensation (7.3.2): after the centroidal computation the CoM
//! task needs anyway (`Centroidal::compute_matrix`), `VerticalMomentum::update(&centroidal)`;
//! the cycle's solve by [`crate::ik::SaturatedRmrc`], then
//! `InCycleCompensation::apply(&mut sns, &problem, J_Lz, L_ref,z(t), &mut qdot)`. With
//! minimisation (7.5) instead: `MomentumMinimisation::update(J_Lz, &mut W)` and pass `W` as
//! the RMRC weight. `L_ref,z(t)` comes from [`MomentumReference::sample`].

pub mod arm_swing;
pub mod compensation;
pub mod error;
pub mod in_cycle;
pub mod jacobian;
pub mod minimisation;
pub mod reference;

pub use arm_swing::{ArmSwing, ArmSwingNominal, ArmTargets, PointTarget};
pub use compensation::{Compensation, LOLA_ARMS, LOLA_ARM_FLEXION};
pub use error::MomentumError;
pub use in_cycle::InCycleCompensation;
pub use jacobian::{vertical_inertia, vertical_momentum_rate, LzRate, VerticalMomentum};
pub use minimisation::MomentumMinimisation;
pub use reference::MomentumReference;
