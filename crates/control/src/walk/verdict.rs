//! Verdicts of a planned walk: did it keep the joint ranges, stay clear of self-collision and
//! inside the friction cone? Each verdict names where and when the walk came closest.

use serde::Serialize;
use std::fmt;

/// The extreme of one checked quantity over a walk.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verdict {
    /// The limit held over the whole walk.
    pub kept: bool,
    /// Where the extreme occurred: joint, segment pair or support.
    pub at: String,
    /// When \[s].
    pub t: f64,
    /// The extreme value (joint margin \[rad or m], segment distance \[m], friction usage).
    pub value: f64,
}

impl Verdict {
    /// No sample yet.
    fn empty(start: f64) -> Self {
        Self {
            kept: true,
            at: String::new(),
            t: 0.0,
            value: start,
        }
    }
}

/// Verdicts of one walk (the `"verdicts"` entry of a method in `summary.json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WalkVerdicts {
    /// Smallest joint-limit margin (kept: `>= 0`).
    pub joint_limits: Verdict,
    /// Smallest SSV segment distance (kept: `> 0`).
    pub self_collision: Verdict,
    /// Largest friction usage of the ground wrench ([`super::friction`]; kept: `<= 1`).
    pub friction: Verdict,
    /// Largest task error of the IK (kept: `<=` [`super::WalkParams::task_tolerance`]); `at`
    /// names the joints the IK held at their limits then.
    pub tracking: Verdict,
    /// Largest height above the ground of a planned contact point of a supporting foot \[m]
    /// ([`super::contact`]; kept: `<=` [`super::WalkParams::contact_tolerance`]); `at` names
    /// the foot and its supporting part.
    pub contact: Verdict,
    /// Coulomb coefficient the friction was checked against.
    pub mu: f64,
}

/// A limit a walk did not keep, as one line for the terminal.
#[derive(Debug, Clone, PartialEq)]
pub struct Violation {
    /// Which check.
    pub quantity: &'static str,
    /// The line.
    pub text: String,
}

impl fmt::Display for Violation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.quantity, self.text)
    }
}

impl WalkVerdicts {
    /// Verdicts before the first cycle.
    pub fn new(mu: f64) -> Self {
        Self {
            joint_limits: Verdict::empty(f64::INFINITY),
            self_collision: Verdict::empty(f64::INFINITY),
            friction: Verdict::empty(0.0),
            tracking: Verdict::empty(0.0),
            contact: Verdict::empty(f64::NEG_INFINITY),
            mu,
        }
    }

    /// Records the joint margin `margin` of `joint` at `t`.
    pub fn joint(&mut self, t: f64, margin: f64, joint: impl FnOnce() -> String) {
        let v = &mut self.joint_limits;
        if margin < v.value {
            (v.value, v.t, v.at, v.kept) = (margin, t, joint(), v.kept && margin >= 0.0);
        }
    }

    /// Records the smallest segment distance `d` (between `pair`) at `t`.
    pub fn distance(&mut self, t: f64, d: f64, pair: impl FnOnce() -> String) {
        let v = &mut self.self_collision;
        if d < v.value {
            (v.value, v.t, v.at, v.kept) = (d, t, pair(), v.kept && d > 0.0);
        }
    }

    /// Records the friction usage `usage` of `support` at `t` (non-finite: no support).
    pub fn friction(&mut self, t: f64, usage: f64, support: impl FnOnce() -> String) {
        let v = &mut self.friction;
        if usage > v.value || (usage.is_nan() && v.kept) {
            (v.value, v.t, v.at, v.kept) = (usage, t, support(), v.kept && usage <= 1.0);
        }
    }

    /// Records the IK's task error `e` at `t` against `tolerance` (`held`: joints at limits).
    pub fn tracking(&mut self, t: f64, e: f64, tolerance: f64, held: impl FnOnce() -> String) {
        let v = &mut self.tracking;
        if e > v.value || (e.is_nan() && v.kept) {
            (v.value, v.t, v.at, v.kept) = (e, t, held(), v.kept && e <= tolerance);
        }
    }

    /// Records the lift `lift` \[m] of the supporting foot part `part` at `t` against
    /// `tolerance` (non-finite: a violation).
    pub fn contact(&mut self, t: f64, lift: f64, tolerance: f64, part: impl FnOnce() -> String) {
        let v = &mut self.contact;
        if lift > v.value || (lift.is_nan() && v.kept) {
            (v.value, v.t, v.at, v.kept) = (lift, t, part(), v.kept && lift <= tolerance);
        }
    }

    /// The limits not kept, one line each naming what, where, when and by how much. A walk
    /// the IK does not track lifts its feet as a consequence: then the tracking line stands
    /// for the contact verdict too (which `summary.json` still reports).
    pub fn violations(&self) -> Vec<Violation> {
        let mut out = Vec::new();
        let (j, c, f) = (&self.joint_limits, &self.self_collision, &self.friction);
        let k = &self.tracking;
        if !k.kept {
            out.push(Violation {
                quantity: "tracking",
                text: format!(
                    "the IK misses its tasks by {:.4} (m or rad) at t = {:.3} s ({})",
                    k.value, k.t, k.at
                ),
            });
        }
        let s = &self.contact;
        if !s.kept && k.kept {
            out.push(Violation {
                quantity: "contact",
                text: format!(
                    "the {} planned on the ground is {:.1} mm above it at t = {:.3} s",
                    s.at,
                    1e3 * s.value,
                    s.t
                ),
            });
        }
        if !j.kept {
            out.push(Violation {
                quantity: "joint limits",
                text: format!(
                    "{} left its range by {:.4} rad at t = {:.3} s",
                    j.at, -j.value, j.t
                ),
            });
        }
        if !c.kept {
            out.push(Violation {
                quantity: "self-collision",
                text: format!(
                    "{} interpenetrate by {:.4} m at t = {:.3} s",
                    c.at, -c.value, c.t
                ),
            });
        }
        if !f.kept {
            let need = match f.value.is_finite() {
                true => format!(
                    "needs {:.2} times the friction mu = {} allows",
                    f.value, self.mu
                ),
                false => "needs the ground to pull (no normal force)".to_string(),
            };
            out.push(Violation {
                quantity: "friction",
                text: format!("the {} {need} at t = {:.3} s", f.at, f.t),
            });
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extremes_keep_place_and_time_and_violations_name_them() {
        let mut v = WalkVerdicts::new(0.8);
        v.joint(0.1, 0.05, || "a".into());
        v.joint(0.2, -0.01, || "knee".into());
        v.joint(0.3, 0.02, || "b".into());
        v.distance(0.4, 0.03, || "x and y".into());
        v.friction(0.5, 0.7, || "left foot".into());
        v.friction(0.6, 1.3, || "right foot".into());
        v.tracking(0.7, 0.001, 0.02, String::new);
        assert_eq!(
            (v.joint_limits.at.as_str(), v.joint_limits.t),
            ("knee", 0.2)
        );
        assert!(!v.joint_limits.kept && v.self_collision.kept && v.tracking.kept);
        assert_eq!(v.friction.value, 1.3);
        let lines: Vec<String> = v.violations().iter().map(|x| x.to_string()).collect();
        assert_eq!(lines.len(), 2, "{lines:?}");
        assert!(
            lines[0].starts_with("joint limits: knee left its range by 0.0100 rad at t = 0.200 s")
        );
        assert!(lines[1].contains("right foot needs 1.30 times the friction mu = 0.8"));
    }

    #[test]
    fn a_lifted_supporting_foot_is_one_line_in_mm() {
        let mut v = WalkVerdicts::new(0.8);
        v.contact(1.0, 0.0004, 0.001, || "left sole".into());
        assert!(v.contact.kept && v.violations().is_empty());
        v.contact(1.715, 0.0045, 0.001, || "right toe".into());
        v.contact(1.8, 0.002, 0.001, || "left sole".into());
        assert!(!v.contact.kept);
        let lines: Vec<String> = v.violations().iter().map(|x| x.to_string()).collect();
        assert_eq!(
            lines,
            ["contact: the right toe planned on the ground is 4.5 mm above it at t = 1.715 s"]
        );
    }

    #[test]
    fn a_non_finite_value_is_a_violation() {
        let mut v = WalkVerdicts::new(0.8);
        v.friction(0.1, f64::INFINITY, || "double support".into());
        v.tracking(0.2, f64::NAN, 0.02, || "?".into());
        assert!(!v.friction.kept && !v.tracking.kept);
        assert!(v.violations()[1].text.contains("needs the ground to pull"));
    }
}
