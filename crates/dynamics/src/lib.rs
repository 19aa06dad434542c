//! Rigid multibody kinematics and dynamics (thesis ch. 2, 7.2).

pub mod dill;
pub mod urdf;
