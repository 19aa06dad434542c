//! First-order systems `zdot = f(t, z)` (2.2)-(2.4) and the integrators that advance them.
//!
//! Integrators are generic over [`OdeSystem`]; nothing here knows about robots.

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
