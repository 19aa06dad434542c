//! Spatial (6-D) algebra in the thesis' notation (section 2.4.4, eqs. (2.32)-(2.36)).
//!
//! Convention, fixed for the whole crate:
//! - **Motion vectors** ([`Motion`]) stack the angular part first, then the linear part:
//!   `v = [omega; rdot_O]` (2.32), where `rdot_O` is the absolute velocity of the body-frame
//!   origin `O`. Accelerations `a = [omegadot; rddot_O]` are the *conventional* ones of the
//!   thesis: absolute acceleration of the origin, not Featherstone's spatial acceleration.
//!   Both are expressed in the body-fixed frame `k` of the body they belong to.
//! - **Force vectors** ([`Force`], alias [`Wrench`]) stack the moment about `O` first, then the
//!   force: `f = [T + r x F; F]`, as in (2.22) and (2.56).
//! - **Transforms** ([`SpatialTransform`]) are the matrices `C_i = C_kp` of (2.36), mapping a
//!   motion vector of the parent frame `p` to the child frame `k`; they store only the rotation
//!   `A_kp` and the vector `r_PO` (parent coordinates) and never form 6x6 matrices.
//! - **Rigid-body inertia** ([`RigidInertia`]) is the 6x6 matrix of (2.22)
//!   `M = [I_O, m r~_OC; m r~_OC^T, m E]` in compact form; [`ArticulatedInertia`] is a general
//!   symmetric 6x6 inertia kept as three 3x3 blocks.
//! - **Zero pruning** (end of 2.4.4): one-DoF joint subspaces are a coordinate axis or a general
//!   direction ([`Axis`]); products with `S` then pick columns instead of multiplying by zeros.

mod articulated;
mod axis;
mod composite;
mod force;
mod inertia;
mod motion;
pub(crate) mod plane;
mod transform;
mod trig;
mod vector;

pub use articulated::{sym_congruence, ArticulatedInertia};
pub use axis::{Axis, JointAxis, SubspaceKind};
pub use composite::CompositeInertia;
pub use force::{Force, Wrench};
pub use inertia::RigidInertia;
pub use motion::Motion;
pub use transform::SpatialTransform;
pub use trig::sin_cos;

use nalgebra::{Matrix3, Vector3};

/// Skew-symmetric cross-product matrix `a~` with `a~ b = a x b` (notation of (2.13)).
#[inline]
pub fn skew(a: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -a.z, a.y, a.z, 0.0, -a.x, -a.y, a.x, 0.0)
}
