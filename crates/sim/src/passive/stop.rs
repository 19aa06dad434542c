//! Joint end stops: a one-sided spring-damper at each finite end of a joint range.

/// The end stops of one joint: spring `k` and damper `d` acting beyond `lower` / `upper`.
#[derive(Debug, Clone, PartialEq)]
pub struct EndStop {
    /// Joint name.
    pub name: String,
    /// Joint coordinate in `q`.
    pub q: usize,
    /// Joint coordinate in `v`.
    pub v: usize,
    /// Lower end of the range (may be `-inf`) \[rad or m].
    pub lower: f64,
    /// Upper end of the range (may be `+inf`) \[rad or m].
    pub upper: f64,
    /// Stop stiffness `k` \[N m/rad or N/m].
    pub stiffness: f64,
    /// Stop damping `d` \[N m s/rad or N s/m].
    pub damping: f64,
}

impl EndStop {
    /// Stop torque at joint position `q` and rate `qdot`: beyond the upper end
    /// `-max(0, k (q - upper) + d qdot)`, below the lower end `max(0, k (lower - q) - d qdot)`,
    /// else 0. It pushes back only (never holds the joint at the stop while it leaves).
    #[inline]
    pub fn torque(&self, q: f64, qdot: f64) -> f64 {
        if q > self.upper {
            -(self.stiffness * (q - self.upper) + self.damping * qdot).max(0.0)
        } else if q < self.lower {
            (self.stiffness * (self.lower - q) - self.damping * qdot).max(0.0)
        } else {
            0.0
        }
    }
}
