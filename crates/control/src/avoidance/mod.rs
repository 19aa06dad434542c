//! Self-collision avoidance from SSV segment distances (thesis ch. 5, 5.2).
//!
//! [`CollisionAvoidance`] binds a [`biped_ssv::CollisionModel`] (segments on named bodies,
//! segment pairs, activation distance `d_a`) to a multibody model. Each cycle, after
//! [`biped_dynamics::Jacobians::compute`], [`CollisionAvoidance::gradient`] moves the segments,
//! evaluates only the pairs closer than `d_a` ([`biped_ssv::PairQuery::WithinActivation`]) and
//! adds `grad_q H_C = sum_k -g(d_k) (dd_k/dq)^T` (5.5)-(5.9) to the null-space gradient using
//! `J^T f` products of the two closest points (5.8), never forming a Jacobian.
//!
//! Usage, once at start-up and then every IK cycle:
//!
//! ```
//! use biped_control::avoidance::{AvoidanceParams, CollisionAvoidance, RepulsiveLaw};
//! use biped_dynamics::{Data, Jacobians};
//! use biped_robots::lola::{self, lola_collision_model, LolaType};
//! use nalgebra::DVector;
//!
//! let lola = lola::build(LolaType::Type2)?;
//! let segments = lola_collision_model(&lola)?.model;
//! let params = AvoidanceParams { law: RepulsiveLaw::Blended { s0: 1.0, t: 0.5 } };
//! let mut avoid = CollisionAvoidance::new(&lola.model, segments, params)?;
//! let (mut data, mut jac) = (Data::new(&lola.model), Jacobians::new(&lola.model));
//! let mut grad_h = DVector::zeros(lola.model.nv()); // null-space gradient of (4.12)
//! // each cycle:
//! let q = lola.model.neutral();
//! jac.compute(&lola.model, &mut data, &q)?;
//! grad_h.fill(0.0); // (plus joint-limit and momentum terms)
//! let summary = avoid.gradient(&lola.model, &data, &jac, &mut grad_h)?;
//! assert_eq!(summary.active, 0); // the neutral pose keeps every pair beyond d_a
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Resolved ambiguities:
//! - Sign: (5.10) calls `g = dH/dd` positive and decreasing, which would make the minimising
//!   null-space term of (4.12) pull segments together; we take `dH/dd = -g` (see [`law`]).
//! - Distance and points: `d` is the SSV signed distance `|c*| - r_F - r_T` (negative when
//!   the volumes overlap); the points of (5.4) are the closest points on the underlying
//!   primitives, `r_c / |r_c|` is the SSV unit normal. Both give the same `dd/dq` as the
//!   surface points (the offsets `r n` move along `n` only by rotation, orthogonal to `n`),
//!   and the normal stays defined when the primitives touch (`c* = 0`): no division by `d`.
//!   Where the primitives intersect, `d = -r_F - r_T` is locally flat; the normal direction
//!   is then a separating push rather than the (zero) true gradient.
//! - (5.15) divides by `t^2 - 1`: `t = 1` is allowed and is the linear law on all of
//!   `d < d_a` (the quadratic branch is empty).

mod check;
mod error;
mod gradient;
pub mod law;

pub use error::AvoidanceError;
pub use gradient::{AvoidanceParams, AvoidanceSummary, CollisionAvoidance};
pub use law::RepulsiveLaw;
