//! First-order systems `zdot = f(t, z)` (2.2)-(2.4) and the integrators that advance them
//! (thesis 2.1).
//!
//! Integrators are generic over [`OdeSystem`]; nothing here knows about robots.
//!
//! - [`Integrator`]: explicit Euler, semi-implicit (symplectic) Euler, classic RK4 and
//!   adaptive Dormand-Prince 5(4) with dense output, selected by [`Method`] and configured by
//!   [`Settings`]. One call integrates one control period `[t0, t1]` and never steps past
//!   `t1` (the input is piecewise constant). No heap allocation happens inside a call.
//! - Symplectic Euler needs the position/rate split of [`SplitSystem`]. Rust has no
//!   specialisation, so the split cannot be detected from an `OdeSystem` bound; the
//!   `advance_split*` entry points take a [`SplitSystem`] and serve all four methods, the
//!   plain `advance*` entry points take any [`OdeSystem`] and reject only symplectic Euler.

mod dopri5;
mod error;
mod fixed;
mod integrator;
mod settings;
mod tableau;
mod work;

pub(crate) use work::all_finite;

pub use error::{ConfigError, IntegrateError, Quantity};
pub use integrator::Integrator;
pub use settings::{Method, ParseMethodError, Settings, StepStats};
pub use tableau::{Tableau, TABLEAU};

/// A first-order ODE `zdot = f(t, z)` with a state of fixed dimension (2.2).
pub trait OdeSystem {
    /// Error the right-hand side may report (e.g. a singular mass matrix).
    type Error: std::error::Error + Send + Sync + 'static;

    /// Dimension of the state `z`.
    fn dim(&self) -> usize;

    /// Evaluates `zdot = f(t, z)` into `zdot` (both of length [`Self::dim`]).
    fn rhs(&mut self, t: f64, z: &[f64], zdot: &mut [f64]) -> Result<(), Self::Error>;

    /// Projects an accepted state back onto its manifold (e.g. renormalises quaternions).
    fn project(&self, _z: &mut [f64]) {}
}

/// A system whose state splits into a position block `z[..n]` and a rate block `z[n..]`, for
/// semi-implicit (symplectic) Euler: rates are stepped first, positions with the new rates.
pub trait SplitSystem: OdeSystem {
    /// Length `n` of the position block at the start of `z`.
    fn position_len(&self) -> usize;

    /// Position derivative `xdot(z)` from a state whose rate block is already updated (for
    /// mechanical systems `qdot` from `q` and the new `v`); cheap, no dynamics.
    fn position_rate(&self, z: &[f64], xdot: &mut [f64]);
}
