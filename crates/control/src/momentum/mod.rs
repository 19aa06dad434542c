//! Vertical angular momentum compensation, reference and minimisation (thesis ch. 7).
//!
//! - [`jacobian`]: `J_L`, `J_Lz`, `L_z` and its rate (7.1)-(7.2), `I_zz^CoG` (7.11).
//! - [`compensation`]: producing/reducing split and the null-space term (7.3)-(7.9).
//! - [`minimisation`]: the weight `W = delta E + J_Lz^T J_Lz` (7.13)-(7.15).

pub mod compensation;
pub mod error;
pub mod jacobian;
pub mod minimisation;

pub use compensation::{
    Compensation, CompensationLaw, CompensationTerms, LOLA_ARMS, LOLA_ARM_FLEXION,
};
pub use error::MomentumError;
pub use jacobian::{vertical_inertia, vertical_momentum_rate, LzRate, VerticalMomentum};
pub use minimisation::MomentumMinimisation;
