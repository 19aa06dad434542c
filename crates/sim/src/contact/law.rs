//! Point-contact force laws: nonlinear spring-damper normal force and regularised Coulomb
//! friction with an elastic tangential (stiction) state per point.

use crate::error::{positive, SimError};
use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

/// Parameters of the compliant point contact with flat ground.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ContactParams {
    /// Normal stiffness `k` of one point \[N/m^e].
    pub stiffness: f64,
    /// Exponent `e >= 1` of the spring `k delta^e` (1 = linear, 1.5 = Hertz-like).
    pub exponent: f64,
    /// Normal damping `d` of one point at full depth \[N s/m].
    pub damping: f64,
    /// Penetration `delta_d` over which the damping fades in linearly \[m] (continuous force at
    /// touch-down, Hunt-Crossley-like).
    pub damping_depth: f64,
    /// Coulomb friction coefficient `mu`.
    pub friction: f64,
    /// Tangential (stiction) spring `k_t` of one point \[N/m].
    pub tangential_stiffness: f64,
    /// Tangential damper `d_t` of one point \[N s/m]; `d_t / k_t` is the bristle relaxation time.
    pub tangential_damping: f64,
    /// Ground height `z_g` \[m] (the ground is the plane `z = z_g`).
    pub ground_height: f64,
}

impl Default for ContactParams {
    /// Defaults for Lola-sized feet (8 points per sole, 13 with the toe) integrated by RK4
    /// at h = 1 ms: linear 2e5 N/m per point (0.1-0.2 mm static penetration standing), damping
    /// near critical for the foot's vertical mode, tangential damper 200 N s/m (bristle
    /// relaxation time 1 ms, `h / tau = 1`, inside RK4's real stability interval 2.78). The
    /// tangential damper sets the fastest mode of the standing robot, the feet's roll about the
    /// ankle adduction joints (the sole 9 cm below the axis): `h |lambda|` = 2.32 at h = 1 ms
    /// with the toe points (2.10 without), 3.46 with a 400 N s/m damper (2.63 without toes).
    fn default() -> Self {
        Self {
            stiffness: 2.0e5,
            exponent: 1.0,
            damping: 400.0,
            damping_depth: 1.0e-4,
            friction: 0.8,
            tangential_stiffness: 2.0e5,
            tangential_damping: 200.0,
            ground_height: 0.0,
        }
    }
}

impl ContactParams {
    /// These parameters with normal and tangential stiffness `k` and damping `d` per point.
    pub fn with_spring_damper(self, k: f64, d: f64) -> Self {
        Self {
            stiffness: k,
            damping: d,
            tangential_stiffness: k,
            tangential_damping: d,
            ..self
        }
    }

    /// Softer points for light feet, e.g. a URDF robot's without rotor inertia (5e4 N/m,
    /// 100 N s/m): the defaults put the damping eigenvalue `8 d / m_foot` of a 0.6 kg foot (the
    /// G1's) at ~5300 1/s, outside RK4's stability region at h = 1 ms.
    pub fn light_feet() -> Self {
        Self::default().with_spring_damper(5e4, 100.0)
    }

    /// Checks every parameter (finite, positive where needed, `e >= 1`).
    pub fn validate(&self) -> Result<(), SimError> {
        positive("contact.stiffness", self.stiffness, false)?;
        positive("contact.damping", self.damping, true)?;
        positive("contact.damping_depth", self.damping_depth, false)?;
        positive("contact.friction", self.friction, true)?;
        positive(
            "contact.tangential_stiffness",
            self.tangential_stiffness,
            false,
        )?;
        positive("contact.tangential_damping", self.tangential_damping, false)?;
        if !(self.exponent.is_finite() && self.exponent >= 1.0) {
            return Err(SimError::InvalidParameter {
                what: "contact.exponent".into(),
                reason: format!("must be finite and >= 1, got {}", self.exponent),
            });
        }
        if !self.ground_height.is_finite() {
            return Err(SimError::InvalidParameter {
                what: "contact.ground_height".into(),
                reason: "must be finite".into(),
            });
        }
        Ok(())
    }

    /// Normal force `F_n = max(0, k delta^e + d min(delta / delta_d, 1) delta_dot)` for the
    /// penetration `delta` and its rate; zero without penetration (unilateral, never pulls).
    #[inline]
    pub fn normal_force(&self, delta: f64, delta_rate: f64) -> f64 {
        if delta <= 0.0 {
            return 0.0;
        }
        let spring = if self.exponent == 1.0 {
            self.stiffness * delta
        } else {
            self.stiffness * delta.powf(self.exponent)
        };
        let fade = (delta / self.damping_depth).min(1.0);
        (spring + self.damping * fade * delta_rate).max(0.0)
    }

    /// Static penetration of one point carrying the normal load `f` (inverse of the spring).
    pub fn static_penetration(&self, f: f64) -> f64 {
        (f.max(0.0) / self.stiffness).powf(1.0 / self.exponent)
    }

    /// Tangential force and bristle rate for the bristle deflection `s`, the point's sliding
    /// velocity `v_t` and the normal force `f_n`: sticking when the trial force
    /// `-(k_t s + d_t v_t)` lies inside the cone `mu f_n` (then `sdot = v_t`); otherwise the
    /// force is projected onto the cone and the bristle relaxes so that
    /// `F_t = -(k_t s + d_t sdot)` still holds. Without contact the bristle relaxes to zero.
    #[inline]
    pub fn tangential(
        &self,
        s: Vector2<f64>,
        v_t: Vector2<f64>,
        f_n: f64,
    ) -> (Vector2<f64>, Vector2<f64>) {
        let (kt, dt) = (self.tangential_stiffness, self.tangential_damping);
        let trial = -(s * kt + v_t * dt);
        let limit = self.friction * f_n;
        let norm = trial.norm();
        if norm <= limit {
            return (trial, v_t);
        }
        let force = trial * (limit / norm);
        let rate = -(force + s * kt) / dt;
        (force, rate)
    }

    /// Sliding velocity of a point in contact with bristle deflection `s`, tangential velocity
    /// `v_t` and tangential force `f_t` (from [`Self::tangential`]): the part of `v_t` its
    /// bristle does not take up, `v_t - sdot = v_t + (f_t + k_t s) / d_t`. Zero while the point
    /// sticks; while it slides, antiparallel to `f_t`, so `-f_t . v_slide` is the power the
    /// friction dissipates.
    #[inline]
    pub fn sliding_velocity(
        &self,
        s: Vector2<f64>,
        v_t: Vector2<f64>,
        f_t: Vector2<f64>,
    ) -> Vector2<f64> {
        v_t + (f_t + s * self.tangential_stiffness) / self.tangential_damping
    }
}
