//! Rigid multibody kinematics and dynamics (thesis ch. 2, 7.2).
//!
//! Model/data split: an immutable [`Model`] built with the validating [`ModelBuilder`], and a
//! preallocated [`Data`] workspace. Spatial conventions are documented in [`spatial`].
//! Forward dynamics by the O(n) three-pass algorithm ([`dynamics::on`], Algorithms 2.1-2.4),
//! CRBA + dense Cholesky, or CRBA + reverse sparse `L^T L`; inverse dynamics by RNEA.

pub mod centroidal;
mod check;
pub mod configuration;
pub mod data;
pub mod dynamics;
pub mod error;
pub mod jacobian;
pub mod kinematics;
pub mod mechanism;
pub mod model;
pub mod spatial;
pub mod subsystem;

pub mod dill;
pub mod urdf;

pub use centroidal::{center_of_mass, CenterOfMass, Centroidal};
pub use centroidal::{centroidal_momentum, centroidal_momentum_current, CentroidalMomentum};
pub use configuration::{difference, integrate, nearby_state};
pub use data::Data;
pub use dynamics::{
    forward_dynamics, forward_dynamics_kinematics, forward_dynamics_solve, inverse_dynamics,
    mass_matrix, on, Algorithm,
};
pub use error::{DynamicsError, ModelError};
pub use jacobian::{JacobianError, JacobianFrame, Jacobians};
pub use kinematics::{forward_kinematics, update_placements};
pub use model::{
    Body, BodyId, BodySpec, IndexSet, JointInfo, JointModel, Model, ModelBuilder, RotorSpec,
};
pub use spatial::{Force, Motion, RigidInertia, SpatialTransform, Wrench};
pub use subsystem::{Node, NodeKind, Subsystem};
