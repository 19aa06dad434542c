//! Vertical angular momentum reference `L_ref,z(t)` (thesis 7.4, (7.10)-(7.12)).
//!
//! Per step a cubic `L_ref,z(t) = sum_i a_i (t - t_b)^i` on `[t_b, t_e]` (7.10). Initial
//! values are the reference's own current `L_ref,z(t_b)` and `Ldot_ref,z(t_b)` (so the
//! reference is C^1 across steps); end values are `L_ref,z(t_e) = I_zz^CoG phidot_u(t_e)` with
//! `phidot_u = Delta phi_u / T_step` and `Ldot_ref,z(t_e) = 0` (7.11)-(7.12). Walking straight
//! (`Delta phi_u = 0`) drives the reference to zero. Outside `[t_b, t_e]` the reference holds
//! its boundary value with zero rate (resolved: the thesis only defines it inside the step).

use super::error::{check_finite, positive, MomentumError};

/// Cubic vertical momentum reference of the current step (7.10)-(7.12).
#[derive(Clone, Debug, PartialEq)]
pub struct MomentumReference {
    izz: f64,
    t_b: f64,
    t_e: f64,
    a: [f64; 4],
}

impl MomentumReference {
    /// Zero reference for a robot of vertical inertia `I_zz^CoG(q0) > 0` (see
    /// [`super::vertical_inertia`]).
    pub fn new(izz: f64) -> Result<Self, MomentumError> {
        Ok(Self {
            izz: positive("izz", izz)?,
            t_b: 0.0,
            t_e: 0.0,
            a: [0.0; 4],
        })
    }

    /// The constant vertical inertia `I_zz^CoG`.
    pub fn izz(&self) -> f64 {
        self.izz
    }

    /// Starts a step at `t_b` of duration `t_step > 0` turning the upper body by `delta_phi_u`
    /// (rad): end value `I_zz delta_phi_u / t_step`, zero end rate (7.11)-(7.12).
    pub fn start_step(
        &mut self,
        t_b: f64,
        t_step: f64,
        delta_phi_u: f64,
    ) -> Result<(), MomentumError> {
        let t_step = positive("t_step", t_step)?;
        check_finite("delta_phi_u", [delta_phi_u].iter())?;
        self.start_step_to(t_b, t_step, self.izz * delta_phi_u / t_step, 0.0)
    }

    /// Starts a cubic from the current reference at `t_b` to the end value `l_end` and rate
    /// `ldot_end` at `t_b + t_step` (the general boundary-value form of (7.10)).
    pub fn start_step_to(
        &mut self,
        t_b: f64,
        t_step: f64,
        l_end: f64,
        ldot_end: f64,
    ) -> Result<(), MomentumError> {
        let t = positive("t_step", t_step)?;
        check_finite("t_b, l_end, ldot_end", [t_b, l_end, ldot_end].iter())?;
        let (l0, d0) = self.sample(t_b);
        let dl = l_end - l0;
        self.a = [
            l0,
            d0,
            (3.0 * dl - (2.0 * d0 + ldot_end) * t) / (t * t),
            (-2.0 * dl + (d0 + ldot_end) * t) / (t * t * t),
        ];
        self.t_b = t_b;
        self.t_e = t_b + t;
        Ok(())
    }

    /// `(L_ref,z(t), Ldot_ref,z(t))`; held constant with zero rate outside `[t_b, t_e]`.
    pub fn sample(&self, t: f64) -> (f64, f64) {
        let a = &self.a;
        let s = if t.is_finite() {
            t.clamp(self.t_b, self.t_e) - self.t_b
        } else {
            0.0
        };
        let value = a[0] + s * (a[1] + s * (a[2] + s * a[3]));
        let inside = t >= self.t_b && t <= self.t_e;
        let rate = if inside {
            a[1] + s * (2.0 * a[2] + s * 3.0 * a[3])
        } else {
            0.0
        };
        (value, rate)
    }
}
