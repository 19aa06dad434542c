//! Joint-limit avoidance and comfort-pose cost `H_J = H_limit + H_cmf` (thesis Fig. 4.2) with
//! its analytic gradient, the usual null-space objective of (4.12).
//!
//! Fig. 4.2 is only schematic, so the exact form is our choice: per joint with range
//! `[lo, hi]` and width `r = hi - lo`,
//! - comfort: `H_cmf = w_c/2 ((q - q_cmf) / r)^2` (quadratic around the comfort pose);
//! - limits: zero in the middle, active within `margin r` of a limit. With the normalised
//!   penetration `s` in `[0, 1)` (0 at the activation threshold, 1 at the limit),
//!   `h(s) = w_l (1/(1-s) - 1 - s)`, which is C2 at `s = 0` (`h = h' = h'' = 0`) and grows
//!   without bound towards the limit (steep walls). Beyond `s_max = 0.95` (and past the limit)
//!   `h` continues as its second-order Taylor polynomial, so H_J stays finite, C1 and convex
//!   for any input (never NaN).

use crate::error::IkError;
use nalgebra::DVector;

/// Largest normalised penetration before the Taylor continuation.
const S_MAX: f64 = 0.95;

/// Cost terms of one joint.
#[derive(Debug, Clone, PartialEq)]
pub struct JointCostEntry {
    /// Index into q.
    pub q_index: usize,
    /// Index into v (gradient entry).
    pub v_index: usize,
    /// Lower limit.
    pub lower: f64,
    /// Upper limit.
    pub upper: f64,
    /// Comfort position `q_cmf`.
    pub comfort: f64,
    /// Comfort weight `w_c`.
    pub w_comfort: f64,
}

/// Joint-limit and comfort cost `H_J` (Fig. 4.2) over a set of joints.
#[derive(Debug, Clone, PartialEq)]
pub struct JointCost {
    /// Joints with their ranges and comfort poses.
    pub joints: Vec<JointCostEntry>,
    /// Limit weight `w_l`.
    pub w_limit: f64,
    /// Activation margin as a fraction of the range (0 < margin < 0.5).
    pub margin: f64,
}

impl JointCost {
    /// Validated cost; errors on empty ranges, bad margins or non-finite data.
    pub fn new(joints: Vec<JointCostEntry>, w_limit: f64, margin: f64) -> Result<Self, IkError> {
        if !(margin > 0.0 && margin < 0.5) {
            return Err(IkError::InvalidParameter {
                name: "margin",
                reason: "need 0 < margin < 0.5",
            });
        }
        if !(w_limit >= 0.0 && w_limit.is_finite()) {
            return Err(IkError::InvalidParameter {
                name: "w_limit",
                reason: "need finite >= 0",
            });
        }
        for j in &joints {
            let ok = j.lower.is_finite() && j.upper.is_finite() && j.upper > j.lower;
            let weight_ok = j.comfort.is_finite() && j.w_comfort >= 0.0 && j.w_comfort.is_finite();
            if !(ok && weight_ok) {
                return Err(IkError::InvalidParameter {
                    name: "joint cost entry",
                    reason: "need finite lower < upper, finite comfort, w_comfort >= 0",
                });
            }
        }
        Ok(Self {
            joints,
            w_limit,
            margin,
        })
    }

    /// `H_J(q)`.
    pub fn value(&self, q: &DVector<f64>) -> Result<f64, IkError> {
        self.check(q)?;
        Ok(self
            .joints
            .iter()
            .map(|j| self.terms(j, q[j.q_index]).0)
            .sum())
    }

    /// `grad_out = (dH_J/dq)^T` over v (entries of other coordinates are set to 0).
    pub fn gradient_into(
        &self,
        q: &DVector<f64>,
        grad_out: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        self.check(q)?;
        grad_out.fill(0.0);
        for j in &self.joints {
            if j.v_index >= grad_out.len() {
                return Err(IkError::Dimension {
                    what: "gradient",
                    expected: j.v_index + 1,
                    got: grad_out.len(),
                });
            }
            grad_out[j.v_index] += self.terms(j, q[j.q_index]).1;
        }
        Ok(())
    }

    /// `(H, dH/dq)` of one joint at position `x`.
    fn terms(&self, j: &JointCostEntry, x: f64) -> (f64, f64) {
        let r = j.upper - j.lower;
        let e = (x - j.comfort) / r;
        let (mut h, mut g) = (0.5 * j.w_comfort * e * e, j.w_comfort * e / r);
        let width = self.margin * r;
        let s_lo = (j.lower + width - x) / width;
        let s_hi = (x - (j.upper - width)) / width;
        for (s, sign) in [(s_lo, -1.0), (s_hi, 1.0)] {
            if s > 0.0 {
                let (hs, dhs) = limit_term(s);
                h += self.w_limit * hs;
                g += self.w_limit * dhs * sign / width;
            }
        }
        (h, g)
    }

    /// Errors if an index is out of range or q is not finite.
    fn check(&self, q: &DVector<f64>) -> Result<(), IkError> {
        for j in &self.joints {
            let x = q.get(j.q_index).ok_or(IkError::Dimension {
                what: "q (joint cost index)",
                expected: j.q_index + 1,
                got: q.len(),
            })?;
            if !x.is_finite() {
                return Err(IkError::NonFinite("q"));
            }
        }
        Ok(())
    }
}

/// `(h(s), h'(s))` of the limit wall for penetration `s > 0`, Taylor-continued past S_MAX.
fn limit_term(s: f64) -> (f64, f64) {
    let wall = |s: f64| (1.0 / (1.0 - s) - 1.0 - s, 1.0 / (1.0 - s).powi(2) - 1.0);
    if s <= S_MAX {
        return wall(s);
    }
    let (h0, h1) = wall(S_MAX);
    let h2 = 2.0 / (1.0 - S_MAX).powi(3);
    let d = s - S_MAX;
    (h0 + h1 * d + 0.5 * h2 * d * d, h1 + h2 * d)
}
