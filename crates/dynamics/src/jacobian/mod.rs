//! Body and point Jacobians (2.33), (5.7) and their time derivatives.
//!
//! [`Jacobians`] runs the kinematics once for `q` (and `v`) and maps every column of every
//! relative Jacobian `J_j` to world axes about the world origin. A body Jacobian is then the
//! sum of its ancestors' columns, shifted to the body origin and rotated into the requested
//! [`JacobianFrame`]; a geared rotor's column (3.1) adds into its driver's coordinate.
//! All extraction methods write into caller-provided matrices without allocating.

mod columns;
mod error;
mod extract;

pub use columns::Jacobians;
pub use error::JacobianError;
pub use extract::JacobianFrame;

pub(crate) use error::shape;
