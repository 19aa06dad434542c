//! Simulation of mechatronic biped models with a controller in the loop (thesis 2.1, Fig. 2.1,
//! Table 2.3).
//!
//! - [`ode`]: the first-order system `zdot = f(z, u)` (2.2) and integrators generic over it.
//! - [`record`]: time series of named signals to CSV and SVG.
//! - [`plant`]: the robot plant (model layers of Table 2.3) as one [`ode::OdeSystem`], with
//!   [`drive`] models and the [`contact`] layer; [`sensors`] and [`controller`] close the loop
//!   of Fig. 2.1 in [`simulation`]; [`passive`] adds a robot description's end stops and joint
//!   friction; [`scenario`] gives the drop / stand / sway set-ups.

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
