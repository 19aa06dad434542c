//! Simulation of biped robots with a controller in the loop (thesis 2.1, Fig. 2.1, Table 2.3).
//!
//! A [`plant::Plant`] turns a `biped_dynamics` model into one first-order system
//! `zdot = f(z, u)`: rigid-body dynamics (O(n) with sub-systems), drives (torque, current or
//! voltage commanded, with friction and limits), compliant foot-ground contact and, from a
//! robot description, joint end stops and friction. A [`simulation::Simulation`] closes the
//! loop: every control period it samples the [`sensors::Sensors`] (encoders, foot
//! force/torque, IMU), runs your [`controller::Controller`], holds its commands and integrates
//! the plant to the next period with one of the integrators of [`ode`]. Plants of URDF robots
//! are ready-made ([`plant::urdf_plant`]); other robots plug in through [`plant::Plant::new`]
//! with actuators from [`plant::actuator`] (the Lola-like biped's is
//! `biped_robots::plant::lola_plant`, built that way), and the drop, stand and sway set-ups of
//! [`scenario`] run any of them.
//!
//! # Example
//!
//! A point mass on a massless 0.5 m rod, released at 0.05 rad, under a controller that
//! commands nothing: its period is `2 pi sqrt(l / g) (1 + q0^2 / 16)` to a relative 1e-7.
//!
//! ```
//! use biped_dynamics::{BodySpec, JointModel, ModelBuilder, RigidInertia};
//! use biped_sim::controller::{Commands, Controller};
//! use biped_sim::drive::DriveMode;
//! use biped_sim::plant::{Plant, PlantConfig};
//! use biped_sim::sensors::Sensors;
//! use biped_sim::simulation::Simulation;
//! use biped_sim::{Method, SimError};
//! use nalgebra::{DVector, Isometry3, Matrix3, Vector3};
//!
//! /// A controller without actuators: the pendulum swings freely.
//! struct HandsOff;
//! impl Controller for HandsOff {
//!     fn period(&self) -> f64 { 1e-3 }
//!     fn mode(&self) -> DriveMode { DriveMode::Torque }
//!     fn update(&mut self, _t: f64, _s: &Sensors, _c: &mut Commands) -> Result<(), SimError> {
//!         Ok(())
//!     }
//! }
//!
//! let (l, g, q0) = (0.5, 9.81, 0.05);
//! let bob = RigidInertia::new(1.0, Vector3::new(0.0, 0.0, -l), Matrix3::zeros())?;
//! let hinge = JointModel::Revolute { axis: Vector3::y_axis() };
//! let mut builder = ModelBuilder::new();
//! builder.add_body(BodySpec::named("rod", None, hinge, Isometry3::identity(), bob))?;
//! let plant = Plant::new(builder.build()?, vec![], &[], vec![], PlantConfig::default())?;
//! let z0 = plant.initial_state(&DVector::from_element(1, q0), &DVector::zeros(1))?;
//!
//! let mut sim = Simulation::new(plant, HandsOff, Method::Rk4, z0)?;
//! let (mut last, mut downward) = ((0.0, q0), vec![]);
//! sim.run(2.0, &mut |f| {
//!     let (t, q) = (f.t, f.z[0]);
//!     if last.1 > 0.0 && q <= 0.0 {
//!         downward.push(last.0 + (t - last.0) * last.1 / (last.1 - q)); // interpolated
//!     }
//!     last = (t, q);
//!     Ok(())
//! })?;
//! let period = downward[1] - downward[0];
//! let by_hand = 2.0 * std::f64::consts::PI * (l / g).sqrt() * (1.0 + q0 * q0 / 16.0);
//! assert!((period - by_hand).abs() < 1e-5 * by_hand, "{period} vs {by_hand}");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! A stand of the Lola-like biped with a controller of one's own:
//! `cargo run -p biped_sim --example stand_custom_controller`.
//!
//! # Modules
//!
//! - [`ode`]: the first-order system `zdot = f(z, u)`, explicit and symplectic Euler, RK4 and
//!   adaptive Dormand-Prince 5(4).
//! - [`plant`]: the robot plant (model, drives, contacts, state layout) and ready-made plants.
//! - [`drive`]: motor electrics, gear friction and transmissions; drive modes.
//! - [`contact`]: compliant sole points with regularised Coulomb friction.
//! - [`passive`]: joint end stops and joint damping/friction from a robot description.
//! - [`sensors`]: what the controller sees each period (encoders, F/T sensors, IMU).
//! - [`controller`]: the [`controller::Controller`] trait, joint PD, IMU stance damping,
//!   cascaded current loop.
//! - [`simulation`]: the loop, its observer hook and the run [`simulation::Summary`].
//! - [`scenario`]: drop, stand and sway set-ups with their pass criteria.
//! - [`record`]: named time series to CSV and SVG plots.
//! - [`glob`]: `*` patterns for signal and joint names.
//! - [`error`]: the error type [`SimError`].

pub mod contact;
pub mod controller;
pub mod drive;
pub mod error;
pub mod glob;
pub mod ode;
pub mod passive;
pub mod plant;
pub mod record;
pub mod scenario;
pub mod sensors;
pub mod simulation;

pub use error::SimError;
pub use ode::{IntegrateError, Integrator, Method, OdeSystem, Settings, SplitSystem, StepStats};
pub use record::{RecordError, Recorder};
