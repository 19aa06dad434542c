//! Pass criteria of the scenarios and the per-cycle tracker they need.

use crate::simulation::{Check, Frame, Summary};

/// Extremes of the base position over a run.
#[derive(Debug, Clone, Copy)]
pub struct Tracker {
    base_q: Option<usize>,
    /// Smallest and largest lateral base position \[m].
    pub y_range: (f64, f64),
    /// Smallest base height \[m].
    pub z_min: f64,
}

impl Tracker {
    /// Tracker of the base whose position starts at `q[base_q]`.
    pub fn new(base_q: Option<usize>) -> Self {
        Self {
            base_q,
            y_range: (f64::INFINITY, f64::NEG_INFINITY),
            z_min: f64::INFINITY,
        }
    }

    /// Records one frame.
    pub fn observe(&mut self, f: &Frame) {
        if let Some(qi) = self.base_q {
            let (y, z) = (f.z[qi + 1], f.z[qi + 2]);
            self.y_range = (self.y_range.0.min(y), self.y_range.1.max(y));
            self.z_min = self.z_min.min(z);
        }
    }
}

/// Name of the rest check ([`Criteria::rest_speed`]) in [`Summary::checks`].
pub const REST_CHECK: &str = "final max |v| below";

/// Thresholds; `None` = not checked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Criteria {
    /// At the end, every `|v_i|` below this \[m/s or rad/s].
    pub rest_speed: Option<f64>,
    /// At the end, `|F_z - m g| / (m g)` below this.
    pub force_balance: Option<f64>,
    /// Base height never below this \[m] (the robot did not fall).
    pub min_base_height: Option<f64>,
    /// Lateral base excursion (max - min) at least this \[m].
    pub min_sway: Option<f64>,
}

impl Criteria {
    /// Stand: at rest (1e-3), weight carried within 0.1 %, base within 2 cm of its start.
    pub fn stand(base: f64) -> Self {
        Self {
            rest_speed: Some(1e-3),
            force_balance: Some(1e-3),
            min_base_height: Some(base - 0.02),
            min_sway: None,
        }
    }

    /// Drop: at rest (1e-2), weight carried within 1 %, base no more than 10 cm below start.
    pub fn drop(base: f64) -> Self {
        Self {
            rest_speed: Some(1e-2),
            force_balance: Some(1e-2),
            min_base_height: Some(base - 0.10),
            min_sway: None,
        }
    }

    /// Sway: base sways at least `sway` and stays within 5 cm of its start height.
    pub fn sway(base: f64, sway: f64) -> Self {
        Self {
            rest_speed: None,
            force_balance: None,
            min_base_height: Some(base - 0.05),
            min_sway: Some(sway),
        }
    }

    /// Appends one [`Check`] per criterion to `s.checks`.
    pub fn evaluate(&self, s: &mut Summary, t: &Tracker) {
        let mut push = |name: &str, value: f64, limit: f64, passed: bool| {
            s.checks.push(Check {
                name: name.into(),
                value,
                limit,
                passed,
            });
        };
        if let Some(l) = self.rest_speed {
            push(REST_CHECK, s.final_max_speed, l, s.final_max_speed < l);
        }
        if let Some(l) = self.force_balance {
            let e = (s.final_contact_force - s.weight).abs() / s.weight;
            push("|F_z - m g| / (m g) below", e, l, e < l);
        }
        if let Some(l) = self.min_base_height {
            push("min base height above", t.z_min, l, t.z_min > l);
        }
        if let Some(l) = self.min_sway {
            let d = t.y_range.1 - t.y_range.0;
            push("lateral base excursion above", d, l, d > l);
        }
    }
}
