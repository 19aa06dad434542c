//! Integration method, its settings and per-call statistics.

use super::error::ConfigError;
use std::fmt;
use std::str::FromStr;

/// Integration method for (2.2): the three fixed-step schemes and adaptive Dormand-Prince.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// Explicit Euler, order 1, fixed step.
    Euler,
    /// Semi-implicit (symplectic) Euler on a [`super::SplitSystem`], order 1, fixed step.
    Symplectic,
    /// Classic Runge-Kutta, order 4, fixed step.
    Rk4,
    /// Dormand-Prince 5(4), adaptive step with embedded error control and dense output.
    Dopri5,
}

/// Real root of `1 - x + x^2/2 - x^3/6 + x^4/24 = 1` (RK4's real stability interval).
const RK4_DECAY_BOUND: f64 = 2.785_293_563_405_282;

impl Method {
    /// All methods, in declaration order.
    pub const ALL: [Method; 4] = [
        Method::Euler,
        Method::Symplectic,
        Method::Rk4,
        Method::Dopri5,
    ];

    /// Lower-case name accepted by [`FromStr`].
    pub fn name(self) -> &'static str {
        match self {
            Method::Euler => "euler",
            Method::Symplectic => "symplectic",
            Method::Rk4 => "rk4",
            Method::Dopri5 => "dopri5",
        }
    }

    /// Whether the method steps with the fixed step [`Settings::h`].
    pub fn is_fixed_step(self) -> bool {
        !matches!(self, Method::Dopri5)
    }

    /// Largest `h lambda` for which a fixed-step method's solution of the decay `y' = -lambda y`
    /// does not grow (the real stability interval: `|1 - x| <= 1` for Euler, whose update the
    /// symplectic scheme's velocity shares, and `|1 - x + x^2/2 - x^3/6 + x^4/24| <= 1`, i.e.
    /// `x <= 2.785`, for RK4); `None` for adaptive Dopri5.
    pub fn decay_stability_bound(self) -> Option<f64> {
        match self {
            Method::Euler | Method::Symplectic => Some(2.0),
            Method::Rk4 => Some(RK4_DECAY_BOUND),
            Method::Dopri5 => None,
        }
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Unknown method name given to [`Method::from_str`].
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown integration method {0:?}: expected euler, symplectic, rk4 or dopri5")]
pub struct ParseMethodError(pub String);

impl FromStr for Method {
    type Err = ParseMethodError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Method::ALL
            .into_iter()
            .find(|m| m.name().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| ParseMethodError(s.to_string()))
    }
}

/// Settings of an [`super::Integrator`]; fixed-step methods use only `h` and `max_steps`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Fixed step size of Euler, symplectic Euler and RK4 (upper bound; the interval is split
    /// into `ceil((t1 - t0) / h)` equal sub-steps).
    pub h: f64,
    /// Initial trial step of Dopri5; `0` selects it automatically on the first call.
    pub h_init: f64,
    /// Relative tolerance of Dopri5.
    pub rtol: f64,
    /// Absolute tolerance of Dopri5.
    pub atol: f64,
    /// Minimum Dopri5 step; smaller proposals fail with step size underflow.
    pub h_min: f64,
    /// Maximum Dopri5 step.
    pub h_max: f64,
    /// Maximum number of steps (accepted and rejected) per `advance` call.
    pub max_steps: usize,
    /// Safety factor of the step-size controller.
    pub safety: f64,
    /// Smallest step-size ratio per step.
    pub fac_min: f64,
    /// Largest step-size ratio per step.
    pub fac_max: f64,
    /// PI-controller coefficient beta (0 = standard controller, 0.04 recommended).
    pub beta: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            h: 1e-3,
            h_init: 0.0,
            rtol: 1e-6,
            atol: 1e-9,
            h_min: 1e-14,
            h_max: f64::INFINITY,
            max_steps: 100_000,
            safety: 0.9,
            fac_min: 0.2,
            fac_max: 10.0,
            beta: 0.04,
        }
    }
}

impl Settings {
    /// Default settings with fixed step `h`.
    pub fn fixed(h: f64) -> Self {
        Settings {
            h,
            ..Self::default()
        }
    }

    /// Default settings with Dopri5 tolerances `rtol`, `atol`.
    pub fn tolerances(rtol: f64, atol: f64) -> Self {
        Settings {
            rtol,
            atol,
            ..Self::default()
        }
    }

    /// Checks every field is in range.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let bad = |name, value, reason| {
            Err(ConfigError::Setting {
                name,
                value,
                reason,
            })
        };
        let pos = |x: f64| x.is_finite() && x > 0.0;
        if !pos(self.h) {
            return bad("h", self.h, "must be finite and > 0");
        }
        if !(self.h_init.is_finite() && self.h_init >= 0.0) {
            return bad("h_init", self.h_init, "must be finite and >= 0");
        }
        if !(self.rtol.is_finite() && self.rtol >= 0.0) {
            return bad("rtol", self.rtol, "must be finite and >= 0");
        }
        if !(self.atol.is_finite() && self.atol >= 0.0) || self.atol + self.rtol <= 0.0 {
            return bad(
                "atol",
                self.atol,
                "must be finite, >= 0, and rtol + atol > 0",
            );
        }
        if !(self.h_min.is_finite() && self.h_min >= 0.0) {
            return bad("h_min", self.h_min, "must be finite and >= 0");
        }
        if self.h_max.is_nan() || self.h_max <= self.h_min {
            return bad("h_max", self.h_max, "must be > h_min");
        }
        if self.max_steps == 0 {
            return bad("max_steps", 0.0, "must be >= 1");
        }
        if !(self.safety > 0.0 && self.safety <= 1.0) {
            return bad("safety", self.safety, "must be in (0, 1]");
        }
        if !(self.fac_min > 0.0 && self.fac_min < 1.0) {
            return bad("fac_min", self.fac_min, "must be in (0, 1)");
        }
        if !(self.fac_max > 1.0 && self.fac_max.is_finite()) {
            return bad("fac_max", self.fac_max, "must be finite and > 1");
        }
        if !(0.0..0.2).contains(&self.beta) {
            return bad("beta", self.beta, "must be in [0, 0.2)");
        }
        Ok(())
    }
}

/// Work done by one `advance` call.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct StepStats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps (Dopri5 only).
    pub rejected: usize,
    /// Right-hand side evaluations.
    pub rhs_evals: usize,
}

impl std::ops::AddAssign for StepStats {
    fn add_assign(&mut self, o: Self) {
        self.steps += o.steps;
        self.rejected += o.rejected;
        self.rhs_evals += o.rhs_evals;
    }
}
