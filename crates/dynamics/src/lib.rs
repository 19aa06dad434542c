//! Rigid multibody kinematics and dynamics for robots with drive trains (thesis ch. 2, 7.2).
//!
//! Build a [`Model`] (with the validating [`ModelBuilder`], from a URDF file with
//! [`urdf::load_file`], or the Dill(n) benchmark tree of [`dill`]), give it a preallocated
//! [`Data`] workspace, and ask for forward dynamics ([`forward_dynamics`]: the O(n) three-pass
//! algorithm, CRBA + dense Cholesky, or CRBA + sparse `L^T L`, see [`Algorithm`]), inverse
//! dynamics ([`inverse_dynamics`], RNEA), the mass matrix ([`mass_matrix`], CRBA), body poses
//! ([`forward_kinematics`]), Jacobians ([`Jacobians`]) and centroidal quantities
//! ([`center_of_mass`], [`Centroidal`]). Small kinematic loops of real drives (Harmonic Drive
//! rotors, roller screws, slider-cranks) are modelled as coupled bodies and grouped into
//! sub-systems automatically, so the O(n) algorithm stays O(n) with them. Spatial conventions
//! (motion vectors `[angular; linear]`, gravity `(0, 0, -9.81)`) are in [`spatial`].
//!
//! # Example
//!
//! A point mass `m` on a massless rod of length `l` swinging about `y`: by hand,
//! `qdd = -g sin(q) / l`, `M = m l^2`, and the torque holding it still is `m g l sin(q)`.
//!
//! ```
//! use biped_dynamics::{
//!     forward_dynamics, inverse_dynamics, mass_matrix, Algorithm, BodySpec, Data, JointModel,
//!     ModelBuilder, RigidInertia,
//! };
//! use nalgebra::{DVector, Isometry3, Matrix3, Vector3};
//!
//! let (m, l, g) = (2.0, 0.5, 9.81);
//! let mut builder = ModelBuilder::new();
//! let bob = RigidInertia::new(m, Vector3::new(0.0, 0.0, -l), Matrix3::zeros())?;
//! let axis = JointModel::Revolute { axis: Vector3::y_axis() };
//! builder.add_body(BodySpec::named("rod", None, axis, Isometry3::identity(), bob))?;
//! let model = builder.build()?;
//! let mut data = Data::new(&model);
//!
//! let (q, v) = (DVector::from_element(1, 0.3), DVector::zeros(1));
//! let tau = DVector::zeros(1);
//! for algo in [Algorithm::On, Algorithm::Crba, Algorithm::Sparse] {
//!     let qdd = forward_dynamics(&model, &mut data, &q, &v, &tau, None, algo)?;
//!     assert!((qdd[0] + g * 0.3_f64.sin() / l).abs() < 1e-12);
//! }
//! let mass = mass_matrix(&model, &mut data, &q)?;
//! assert!((mass[(0, 0)] - m * l * l).abs() < 1e-12);
//! let hold = inverse_dynamics(&model, &mut data, &q, &v, &DVector::zeros(1), None)?;
//! assert!((hold[0] - m * g * l * 0.3_f64.sin()).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! A runnable comparison of the three forward-dynamics methods on the bundled Unitree G1 URDF:
//! `cargo run -p biped_dynamics --example g1_dynamics`.
//!
//! # Modules
//!
//! - [`centroidal`]: centre of mass, its Jacobian, centroidal momentum and the matrix `A_G`.
//! - [`configuration`]: `q (+) v dt` and its inverse on free (quaternion) joints.
//! - [`data`]: the preallocated workspace [`Data`]; kinematic results are public fields.
//! - [`dill`]: the Dill(n) benchmark tree and its mass-matrix sparsity.
//! - [`dynamics`]: forward dynamics (three methods), mass matrix, inverse dynamics.
//! - [`error`]: [`ModelError`] (model input) and [`DynamicsError`] (algorithm input, results).
//! - [`jacobian`]: body, frame and point Jacobians and their time derivatives.
//! - [`kinematics`]: body poses, velocities and accelerations.
//! - [`mechanism`]: closed-form drive mechanisms (Harmonic Drive, knee and ankle drives).
//! - [`model`]: [`Model`], [`ModelBuilder`], joints, coupled parts, rotors.
//! - [`spatial`]: 6-D motion/force vectors, transforms and inertias, with the conventions.
//! - [`subsystem`]: sub-systems formed from bodies that share coordinates.
//! - [`urdf`]: URDF (and SRDF) import.

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
    Body, BodyId, BodySpec, ElasticGear, IndexSet, JointInfo, JointModel, Model, ModelBuilder,
    RotorSpec,
};
pub use spatial::{Force, Motion, RigidInertia, SpatialTransform, Wrench};
pub use subsystem::{Node, NodeKind, Subsystem};
