//! Robot models built on `biped_dynamics`: the Lola-like biped of the thesis (Fig. 1.1,
//! Table 2.3) with its drive trains and SSV collision model, and kinematic calibration of
//! joint encoders (3.5).
//!
//! [`lola::build`] turns the bundled parameter file (`data/lola.toml`, plausible values for a
//! 1.8 m, 60 kg robot, not Lola's real data) into a floating-base [`biped_dynamics::Model`]
//! with 25 actuated joints, either with rigid drives ([`lola::LolaType::Type2`]: Harmonic
//! Drive rotors, knee roller screw and ankle slider-cranks as coupled parts, grouped into
//! sub-systems) or with elastic Harmonic Drive gears ([`lola::LolaType::Type3`]: one more
//! motor coordinate per gear). [`lola::lola_collision_model`] binds the bundled SSV model
//! (`data/lola_ssv.toml`) to its bodies. [`calibration`] estimates encoder offsets from jig
//! poses of any URDF robot.
//!
//! # Example
//!
//! Type 2 has the 6 base coordinates and one per actuated joint; Type 3 adds one motor
//! coordinate per elastic gear. On both, the O(n) algorithm with sub-systems and the CRBA give
//! the same accelerations.
//!
//! ```
//! use biped_dynamics::{forward_dynamics, Algorithm, Data};
//! use biped_robots::lola::{build, LolaType};
//! use nalgebra::DVector;
//!
//! let type2 = build(LolaType::Type2)?;
//! assert_eq!(type2.limits.len(), 25);
//! assert_eq!(type2.model.nv(), 6 + 25);
//! assert!(!type2.model.subsystems().is_empty()); // the drive loops
//! let type3 = build(LolaType::Type3)?;
//! assert_eq!(type3.gears.len(), 16);
//! assert_eq!(type3.model.nv(), 6 + 25 + 16);
//!
//! // a deterministic "random" state inside the joint ranges
//! let mut x = 0.0_f64;
//! let mut uniform = |a: f64, b: f64| { x = (x + 0.618_034) % 1.0; a + (b - a) * x };
//! for lola in [&type2, &type3] {
//!     let (q, v) = lola.random_state(&mut uniform);
//!     let tau = DVector::zeros(lola.model.nv());
//!     let mut data = Data::new(&lola.model);
//!     let on = forward_dynamics(&lola.model, &mut data, &q, &v, &tau, None, Algorithm::On)?.clone();
//!     let crba = forward_dynamics(&lola.model, &mut data, &q, &v, &tau, None, Algorithm::Crba)?;
//!     assert!((crba - &on).amax() < 1e-8 * on.amax());
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Modules
//!
//! - [`description`]: robot description files (TOML) that make any URDF humanoid a walking
//!   robot: feet, joint groups, momentum DoFs, comfort pose, collision model, drives.
//! - [`lola`]: the Lola-like biped: parameters, model assembly, collision model, sparsity.
//! - [`calibration`]: encoder offsets from jig poses (Levenberg-Marquardt), encoder counts of
//!   the knee and ankle drives.

pub mod calibration;
pub mod description;
pub mod lola;
pub mod plant;
