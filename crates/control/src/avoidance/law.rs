//! Repulsive laws `g(d)` of the collision cost (5.10)-(5.15) and their potentials.
//!
//! Sign convention (resolving the sign left open by (5.10)): every law returns the thesis's
//! positive, decreasing `g(d) >= 0` (zero for `d >= d_a`), and the cost is the potential
//! `H(d) = int_d^{d_a} g(s) ds >= 0`, so `dH/dd = -g(d) <= 0`. With (5.10) taken literally
//! (`dH/dd = +g`), minimising `H` by the null-space term `-alpha W^-1 grad H` of (4.12) would
//! *decrease* distances; with `dH/dd = -g` the term becomes `+alpha g W^-1 (dd/dq)^T`, which
//! increases `d` at the rate `alpha g (dd/dq) W^-1 (dd/dq)^T >= 0`.

/// A repulsive law `g(d)` for `d < d_a` (zero beyond), eqs. (5.11), (5.12), (5.15).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RepulsiveLaw {
    /// Linear law `g_l(d) = m (d - d_a)` with slope `m < 0`, eq. (5.11).
    Linear {
        /// Slope `m < 0`.
        m: f64,
    },
    /// Quadratic law `g_q(d) = s (d - d_a)^2` with `s > 0`, eq. (5.12).
    Quadratic {
        /// Scale `s > 0`.
        s: f64,
    },
    /// Blended law `g_m(d)` of (5.15): linear with `g(0) = s0` below `t d_a`, quadratic above,
    /// C^1 at `t d_a`; `t = 0` is the quadratic law with `s = s0 / d_a^2` on `[0, d_a]`,
    /// `t = 1` the linear law with `m = -s0 / d_a`.
    Blended {
        /// Value `s0 > 0` at `d = 0` (intersection with the y axis).
        s0: f64,
        /// Blending position `t` in `[0, 1]` (thesis: 0.4 to 0.6).
        t: f64,
    },
}

impl Default for RepulsiveLaw {
    /// The blended law with `s0 = 1`, `t = 0.5`.
    fn default() -> Self {
        RepulsiveLaw::Blended { s0: 1.0, t: 0.5 }
    }
}

impl RepulsiveLaw {
    /// `g(d) >= 0` for `d < d_a`, zero for `d >= d_a` (5.10); `d_a > 0`.
    #[inline]
    pub fn g(&self, d: f64, d_a: f64) -> f64 {
        if d >= d_a {
            return 0.0;
        }
        let e = d_a - d;
        match *self {
            RepulsiveLaw::Linear { m } => -m * e,
            RepulsiveLaw::Quadratic { s } => s * e * e,
            RepulsiveLaw::Blended { s0, t } => {
                if d < t * d_a {
                    s0 - blend_slope(s0, t, d_a) * d
                } else {
                    // t < 1 here, since d < d_a <= t d_a otherwise.
                    s0 * e * e / (d_a * d_a * (1.0 - t * t))
                }
            }
        }
    }

    /// Potential `H(d) = int_d^{d_a} g(s) ds >= 0` (zero for `d >= d_a`), so `dH/dd = -g(d)`.
    #[inline]
    pub fn potential(&self, d: f64, d_a: f64) -> f64 {
        if d >= d_a {
            return 0.0;
        }
        let e = d_a - d;
        match *self {
            RepulsiveLaw::Linear { m } => -0.5 * m * e * e,
            RepulsiveLaw::Quadratic { s } => s * e * e * e / 3.0,
            RepulsiveLaw::Blended { s0, t } => {
                let d_t = t * d_a;
                if d < d_t {
                    // H(t d_a) plus the integral of the linear branch from d to t d_a.
                    let h_t = s0 * d_a * (1.0 - t) * (1.0 - t) / (3.0 * (1.0 + t));
                    let k = blend_slope(s0, t, d_a);
                    h_t + s0 * (d_t - d) - 0.5 * k * (d_t * d_t - d * d)
                } else {
                    s0 * e * e * e / (3.0 * d_a * d_a * (1.0 - t * t))
                }
            }
        }
    }
}

/// Magnitude `2 s0 / (d_a (t + 1))` of the slope of the linear branch of (5.15).
#[inline]
fn blend_slope(s0: f64, t: f64, d_a: f64) -> f64 {
    2.0 * s0 / (d_a * (t + 1.0))
}
