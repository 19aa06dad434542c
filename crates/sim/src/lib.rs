//! Simulation of mechatronic biped models with a controller in the loop (thesis 2.1, Fig. 2.1,
//! Table 2.3).
//!
//! - [`ode`]: the first-order system `zdot = f(z, u)` (2.2) and integrators generic over it.
//! - [`record`]: time series of named signals to CSV and SVG.

pub mod ode;
pub mod record;
