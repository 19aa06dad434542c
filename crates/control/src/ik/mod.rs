//! Position-based and differential inverse kinematics (thesis 4.2-4.4).

pub mod weight;

pub use weight::Weight;
