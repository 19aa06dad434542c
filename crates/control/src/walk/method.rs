//! Arm-motion methods compared in thesis ch. 7 and the tuning parameters of the walk IK.

use super::error::WalkError;
use crate::ik::LimitSettings;
use std::fmt;
use std::str::FromStr;

/// How the arms (and the redundancy they give) are used during walking (thesis 7.3-7.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// Arms held still: arm CoG tasks off, arm joints locked by a large RMRC weight.
    None,
    /// Arm CoG tasks follow the scaled opposite leg (7.3.1).
    Reference,
    /// Arm CoG tasks off; null-space compensation of `L_z` (7.3.2, (7.3)-(7.9)).
    Compensation,
    /// Arm CoG tasks off; weight `W = delta E + J_Lz^T J_Lz` (7.5, (7.13)-(7.15)).
    Minimization,
}

impl Method {
    /// All methods in report order.
    pub const ALL: [Method; 4] = [
        Method::None,
        Method::Reference,
        Method::Compensation,
        Method::Minimization,
    ];

    /// Lower-case name used on the command line and in `summary.json`.
    pub fn name(self) -> &'static str {
        match self {
            Method::None => "none",
            Method::Reference => "reference",
            Method::Compensation => "compensation",
            Method::Minimization => "minimization",
        }
    }

    /// What the method does with the arms, in one phrase for reports.
    pub fn description(self) -> &'static str {
        match self {
            Method::None => "arms held still",
            Method::Reference => "arms swing with the opposite legs (reference arm method, 7.3.1)",
            Method::Compensation => {
                "arms move to cancel the legs' vertical angular momentum (compensation, 7.3.2)"
            }
            Method::Minimization => "the IK minimises the vertical angular momentum (7.5)",
        }
    }

    /// True if the arm CoG tasks of Table 4.2 are active.
    pub fn arm_tasks(self) -> bool {
        self == Method::Reference
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Method {
    type Err = WalkError;
    fn from_str(s: &str) -> Result<Self, WalkError> {
        Method::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| WalkError::InvalidParameter {
                name: "method",
                reason: format!("`{s}` is not one of none, reference, compensation, minimization"),
            })
    }
}

/// Tuning of the walk IK (defaults are the values used for all reported numbers).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WalkParams {
    /// Task-space feedback gain `K_x` \[1/s] (4.14b), `K_x dt < 2`.
    pub gain: f64,
    /// Null-space step `alpha_N` applied to `grad H = grad H_J + grad H_C` (4.12).
    pub alpha_n: f64,
    /// Comfort weight `w_c` of `H_J` (Fig. 4.2).
    pub comfort_weight: f64,
    /// Joint-limit weight `w_l` of `H_J`.
    pub limit_weight: f64,
    /// Joint-limit activation margin (fraction of the range).
    pub limit_margin: f64,
    /// Self-collision avoidance `H_C` (ch. 5) on or off.
    pub avoidance: bool,
    /// Null-space step applied to `grad H_C` (separate from `alpha_n`: the repulsion must
    /// dominate the comfort and momentum terms near contact).
    pub avoidance_gain: f64,
    /// Reference method: scale of the opposite leg's fore-aft motion (7.3.1).
    pub arm_swing_scale: f64,
    /// Compensation: fraction `k` of `L_z - L_d` the arms cancel each cycle (7.7).
    pub compensation_gain: f64,
    /// Compensation: cap on the arm joint speed of the compensating motion \[rad/s].
    pub compensation_max_speed: f64,
    /// Minimisation: `delta` of `W = delta E + J_Lz^T J_Lz` (7.13); the null-space steps are
    /// scaled by `delta` with this method so that `W^-1 grad H` keeps its size.
    pub minimization_delta: f64,
    /// `none`: RMRC weight of the arm joints (others 1) that keeps them still.
    pub arm_lock_weight: f64,
    /// Start and comfort posture of the arms: shoulder flexion, upper-arm abduction (left
    /// arm; mirrored for the right), elbow \[rad].
    pub arm_pose: [f64; 3],
    /// Time the IK runs on the first pattern sample before the walk starts \[s].
    pub settle_time: f64,
    /// Hard joint limits kept by the IK (margin, velocity, deceleration; [`crate::ik::limits`]).
    pub limits: LimitSettings,
    /// Coulomb coefficient of the ground the friction verdict checks the planned ground
    /// wrench against ([`super::friction`]; default: the contact simulation's ground).
    pub friction: f64,
    /// Largest norm of the IK's task error (m for positions, rad for orientations) with which
    /// the walk still counts as the planned one (the tracking verdict).
    pub task_tolerance: f64,
    /// Largest height \[m] above the ground of a planned contact point of a foot the
    /// pattern has on the ground, with which the walk still keeps its contacts (the contact
    /// verdict, [`super::contact`]). Default 5 mm: the double supports of the default walk
    /// still lift a supporting foot by up to 3.7 mm, the IK lagging its foot tasks under the
    /// solve's regularisation ([`crate::ik::LimitSettings::regularisation`]; 0.5 mm at 1e-4).
    pub contact_tolerance: f64,
}

impl Default for WalkParams {
    fn default() -> Self {
        Self {
            gain: 50.0,
            alpha_n: 0.02,
            comfort_weight: 1.0,
            limit_weight: 0.01,
            limit_margin: 0.1,
            avoidance: true,
            avoidance_gain: 10.0,
            arm_swing_scale: 0.2,
            compensation_gain: 0.9,
            compensation_max_speed: 30.0,
            minimization_delta: 0.003,
            arm_lock_weight: 1e6,
            settle_time: 0.3,
            limits: LimitSettings::default(),
            friction: biped_sim::contact::ContactParams::default().friction,
            task_tolerance: 0.02,
            contact_tolerance: 5e-3,
            arm_pose: [0.0, 0.1, super::WALK_ELBOW],
        }
    }
}

impl WalkParams {
    /// Checks ranges (finite, positive where needed, `gain dt < 2` for `dt = 1e-3`).
    pub fn validate(&self, dt: f64) -> Result<(), WalkError> {
        let bad = |name: &'static str, reason: &str| {
            Err(WalkError::InvalidParameter {
                name,
                reason: reason.to_string(),
            })
        };
        let pos = [
            ("gain", self.gain),
            ("minimization_delta", self.minimization_delta),
            ("arm_lock_weight", self.arm_lock_weight),
            ("friction", self.friction),
            ("task_tolerance", self.task_tolerance),
            ("contact_tolerance", self.contact_tolerance),
            ("dt", dt),
        ];
        for (name, v) in pos {
            if !(v.is_finite() && v > 0.0) {
                return bad(name, "must be finite and > 0");
            }
        }
        let nonneg = [
            ("alpha_n", self.alpha_n),
            ("comfort_weight", self.comfort_weight),
            ("limit_weight", self.limit_weight),
            ("limit_margin", self.limit_margin),
            ("compensation_gain", self.compensation_gain),
            ("compensation_max_speed", self.compensation_max_speed),
            ("avoidance_gain", self.avoidance_gain),
            ("settle_time", self.settle_time),
        ];
        for (name, v) in nonneg {
            if !(v.is_finite() && v >= 0.0) {
                return bad(name, "must be finite and >= 0");
            }
        }
        if !self.arm_swing_scale.is_finite() || self.arm_pose.iter().any(|a| !a.is_finite()) {
            return bad("arm_swing_scale", "must be finite");
        }
        if self.gain * dt >= 2.0 {
            return bad("gain", "K_x dt must be < 2");
        }
        Ok(())
    }
}
