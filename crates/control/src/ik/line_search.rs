//! Inexact line search satisfying the strong Wolfe conditions (thesis 4.2: "Wolfe conditions
//! (with alpha_0 = 1) are superior to Armijo's rule").
//!
//! Bracketing phase followed by a zoom phase (the classical scheme, e.g. Nocedal-Wright
//! ch. 3); the zoom uses safeguarded cubic-free bisection, which is robust and sufficient for
//! the smooth IK residual. Conditions for `phi(alpha)` with `phi'(0) < 0`:
//! sufficient decrease `phi(a) <= phi(0) + c1 a phi'(0)` and curvature
//! `|phi'(a)| <= c2 |phi'(0)|`.

use crate::error::IkError;

/// Parameters of the Wolfe line search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WolfeParams {
    /// Sufficient-decrease constant `c1` in (0, 1).
    pub c1: f64,
    /// Curvature constant `c2` in (c1, 1).
    pub c2: f64,
    /// First trial step `alpha_0` (1 as in the thesis).
    pub alpha0: f64,
    /// Largest step considered.
    pub alpha_max: f64,
    /// Maximum number of function evaluations.
    pub max_evals: usize,
}

impl Default for WolfeParams {
    fn default() -> Self {
        Self {
            c1: 1e-4,
            c2: 0.9,
            alpha0: 1.0,
            alpha_max: 8.0,
            max_evals: 30,
        }
    }
}

/// Result of a line search: the step and whether both Wolfe conditions hold there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineSearchResult {
    /// Accepted step length.
    pub alpha: f64,
    /// `phi(alpha)`.
    pub value: f64,
    /// True if sufficient decrease and curvature hold (else best decrease found).
    pub wolfe: bool,
    /// Number of evaluations of `phi`.
    pub evals: usize,
}

/// Finds a step satisfying the strong Wolfe conditions; `eval(a)` returns `(phi(a), phi'(a))`
/// and must leave its state at the last evaluated `a` (the caller re-evaluates if needed).
pub fn wolfe_search(
    p: &WolfeParams,
    phi0: f64,
    dphi0: f64,
    mut eval: impl FnMut(f64) -> Result<(f64, f64), IkError>,
) -> Result<LineSearchResult, IkError> {
    validate(p, phi0, dphi0)?;
    let sufficient = |a: f64, f: f64| f <= phi0 + p.c1 * a * dphi0;
    let curvature = |d: f64| d.abs() <= -p.c2 * dphi0;
    let (mut lo, mut f_lo, mut hi) = (0.0, phi0, f64::NAN);
    let mut best = LineSearchResult {
        alpha: 0.0,
        value: phi0,
        wolfe: false,
        evals: 0,
    };
    let mut a = p.alpha0.min(p.alpha_max);
    for evals in 1..=p.max_evals {
        let (f, d) = eval(a)?;
        if f.is_finite() && f < best.value {
            best = LineSearchResult {
                alpha: a,
                value: f,
                wolfe: false,
                evals,
            };
        }
        best.evals = evals;
        if !f.is_finite() || !sufficient(a, f) || f >= f_lo {
            hi = a;
        } else if curvature(d) {
            return Ok(LineSearchResult {
                alpha: a,
                value: f,
                wolfe: true,
                evals,
            });
        } else if d * (if hi.is_nan() { 1.0 } else { hi - lo }) >= 0.0 {
            hi = lo;
            (lo, f_lo) = (a, f);
        } else {
            (lo, f_lo) = (a, f);
        }
        a = if hi.is_nan() {
            (2.0 * a).min(p.alpha_max)
        } else {
            0.5 * (lo + hi)
        };
        if !hi.is_nan() && (hi - lo).abs() < 1e-12 {
            break;
        }
    }
    Ok(best)
}

/// Checks the parameters and that the direction is a descent direction.
fn validate(p: &WolfeParams, phi0: f64, dphi0: f64) -> Result<(), IkError> {
    if !(p.c1 > 0.0 && p.c1 < p.c2 && p.c2 < 1.0) {
        return Err(IkError::InvalidParameter {
            name: "wolfe",
            reason: "need 0 < c1 < c2 < 1",
        });
    }
    if !(p.alpha0 > 0.0 && p.alpha_max >= p.alpha0 && p.max_evals > 0) {
        return Err(IkError::InvalidParameter {
            name: "wolfe",
            reason: "need 0 < alpha0 <= alpha_max and max_evals > 0",
        });
    }
    if !(phi0.is_finite() && dphi0.is_finite()) {
        return Err(IkError::NonFinite("line search start"));
    }
    if dphi0 >= 0.0 {
        return Err(IkError::InvalidParameter {
            name: "direction",
            reason: "not a descent direction (phi'(0) >= 0)",
        });
    }
    Ok(())
}
