//! Passive joint forces of the robot description: end stops at the joint ranges ([`stop`]) and
//! joint-side viscous and Coulomb friction ([`friction`]), e.g. a URDF's `<limit>` and
//! `<dynamics>` (the thesis's models have none; the drives' own gear friction is
//! [`crate::drive`]'s).
//!
//! Explicit integrators see these laws as stiff springs and dampers on the joint's inertia, so
//! their constants are scaled by it, as MuJoCo scales its soft constraints: with the free
//! inertia `I = 1 / (M^-1)_jj` of the joint at the neutral configuration (what it moves when
//! everything else moves freely too, the smallest it can see),
//! - an end stop is a spring-damper of natural frequency `omega = 1 / (T zeta)` and damping
//!   ratio `zeta` on `I`: `k = I omega^2`, `d = 2 zeta I omega` (defaults `T = 2 ms`,
//!   `zeta = 1`: `h omega = 0.5` at h = 1 ms; a static torque `tau` presses `tau T^2 / I` into
//!   the stop). MuJoCo's `solref` has the same form with `T = 0.02 s`, but there it sets the
//!   reference acceleration of a constraint that cancels the applied forces; here the stop is a
//!   spring against the actuators, so it must be stiffer than they are (a 40 rad/s joint PD
//!   presses `(40 T)^2 = 0.6 %` of its error into it);
//! - the Coulomb term's smoothing speed is `eps = max(eps_min, f T_f / I)`, so its slope at rest
//!   over `I` stays below `1 / T_f` (default `T_f = 2 ms`, `h / T_f = 0.5` at h = 1 ms).
//!
//! The viscous coefficient is the description's and is not changed: [`PassiveJoints::fastest`]
//! reports the largest rate of the layer for the simulation's step check.

pub mod friction;
pub mod stop;

pub use friction::JointFriction;
pub use stop::EndStop;

use crate::error::{positive, SimError};
use serde::{Deserialize, Serialize};

/// How the passive joint laws are built from a robot description.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PassiveParams {
    /// Apply end stops at the joint ranges.
    pub end_stops: bool,
    /// Apply the description's joint damping and friction.
    pub joint_friction: bool,
    /// End-stop time constant `T` \[s].
    pub stop_time_constant: f64,
    /// End-stop damping ratio `zeta`.
    pub stop_damping_ratio: f64,
    /// Time constant `T_f` bounding the Coulomb term's slope \[s].
    pub friction_time_constant: f64,
    /// Smallest Coulomb smoothing speed `eps_min` \[rad/s or m/s].
    pub min_smoothing: f64,
}

impl Default for PassiveParams {
    /// Both layers on, `T = 2 ms`, `zeta = 1`, `T_f = 2 ms`, `eps_min = 1e-3`.
    fn default() -> Self {
        Self {
            end_stops: true,
            joint_friction: true,
            stop_time_constant: 2.0e-3,
            stop_damping_ratio: 1.0,
            friction_time_constant: 2.0e-3,
            min_smoothing: 1.0e-3,
        }
    }
}

impl PassiveParams {
    /// Checks that every constant is finite and positive.
    pub fn validate(&self) -> Result<(), SimError> {
        positive("passive.stop_time_constant", self.stop_time_constant, false)?;
        positive("passive.stop_damping_ratio", self.stop_damping_ratio, false)?;
        positive(
            "passive.friction_time_constant",
            self.friction_time_constant,
            false,
        )?;
        positive("passive.min_smoothing", self.min_smoothing, false)
    }

    /// Natural frequency `1 / (T zeta)` of the end stops \[1/s].
    pub fn stop_frequency(&self) -> f64 {
        1.0 / (self.stop_time_constant * self.stop_damping_ratio)
    }
}

/// Passive properties of one joint as the robot description gives them.
#[derive(Debug, Clone, PartialEq)]
pub struct JointSpec {
    /// Joint name.
    pub name: String,
    /// Joint coordinate in `q`.
    pub q: usize,
    /// Joint coordinate in `v`.
    pub v: usize,
    /// Range `[lower, upper]` (one side may be infinite), `None` = no end stops.
    pub range: Option<[f64; 2]>,
    /// Viscous damping \[N m s/rad or N s/m].
    pub damping: f64,
    /// Coulomb friction \[N m or N].
    pub friction: f64,
}

/// The fastest rate of the passive layer: which joint, which law, and the rate \[1/s].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PassiveRate {
    /// Joint name.
    pub joint: String,
    /// `"end stop"` or `"damping and friction"`.
    pub law: &'static str,
    /// Largest eigenvalue magnitude of the law on the joint's free inertia \[1/s].
    pub rate: f64,
}

/// The end stops and joint friction of a plant.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PassiveJoints {
    stops: Vec<EndStop>,
    friction: Vec<JointFriction>,
    fastest: Option<PassiveRate>,
}

impl PassiveJoints {
    /// Builds the laws of `specs` with `free(v)`, the free inertia of coordinate `v` (see the
    /// module docs); errors on invalid ranges, coefficients or inertias.
    pub fn new(
        specs: &[JointSpec],
        free: impl Fn(usize) -> f64,
        p: &PassiveParams,
    ) -> Result<Self, SimError> {
        p.validate()?;
        let mut out = Self::default();
        let (omega, zeta) = (p.stop_frequency(), p.stop_damping_ratio);
        for s in specs {
            let what = |field: &str| format!("joint `{}` {field}", s.name);
            positive(&what("damping"), s.damping, true)?;
            positive(&what("friction"), s.friction, true)?;
            let wants_stop = p.end_stops && s.range.is_some();
            let wants_friction = p.joint_friction && (s.damping > 0.0 || s.friction > 0.0);
            if !(wants_stop || wants_friction) {
                continue;
            }
            let inertia = free(s.v);
            positive(&what("free inertia"), inertia, false)?;
            if let (true, Some([lower, upper])) = (p.end_stops, s.range) {
                if lower.is_nan() || upper.is_nan() || lower > upper {
                    return Err(SimError::InvalidParameter {
                        what: what("range"),
                        reason: format!("needs lower <= upper, got [{lower}, {upper}]"),
                    });
                }
                out.stops.push(EndStop {
                    name: s.name.clone(),
                    q: s.q,
                    v: s.v,
                    lower,
                    upper,
                    stiffness: inertia * omega * omega,
                    damping: 2.0 * zeta * inertia * omega,
                });
                let rate = omega * (zeta + (zeta * zeta - 1.0).max(0.0).sqrt());
                out.note(&s.name, "end stop", rate);
            }
            if wants_friction {
                let smoothing =
                    (s.friction * p.friction_time_constant / inertia).max(p.min_smoothing);
                let f = JointFriction {
                    name: s.name.clone(),
                    v: s.v,
                    viscous: s.damping,
                    coulomb: s.friction,
                    smoothing,
                };
                out.note(&s.name, "damping and friction", f.slope() / inertia);
                out.friction.push(f);
            }
        }
        Ok(out)
    }

    /// Keeps `rate` if it is the fastest so far.
    fn note(&mut self, joint: &str, law: &'static str, rate: f64) {
        if self.fastest.as_ref().is_none_or(|f| rate > f.rate) {
            self.fastest = Some(PassiveRate {
                joint: joint.to_string(),
                law,
                rate,
            });
        }
    }

    /// Adds the stop and friction torques at `(q, v)` to `tau`.
    #[inline]
    pub fn apply(&self, q: &[f64], v: &[f64], tau: &mut [f64]) {
        for s in &self.stops {
            let x = q[s.q];
            // Inside the range (the common case) nothing else is read.
            if x > s.upper || x < s.lower {
                tau[s.v] += s.torque(x, v[s.v]);
            }
        }
        for f in &self.friction {
            tau[f.v] += f.torque(v[f.v]);
        }
    }

    /// The end stops.
    pub fn stops(&self) -> &[EndStop] {
        &self.stops
    }

    /// The joint friction laws.
    pub fn friction(&self) -> &[JointFriction] {
        &self.friction
    }

    /// The fastest rate of the layer, `None` when it is empty.
    pub fn fastest(&self) -> Option<&PassiveRate> {
        self.fastest.as_ref()
    }

    /// Whether the layer has no laws.
    pub fn is_empty(&self) -> bool {
        self.stops.is_empty() && self.friction.is_empty()
    }
}
