//! The compensation of [`super::compensation`] solved within the IK cycle and inside the
//! joint limits: after the cycle's solve, the response `qd_r` to the reducing direction
//! `y_r = J_{L,r,z}^T` and `qd += f qd_r` with `f = k (L_d - J_Lz qd) / (J_Lz qd_r)` (7.5),
//! the arm speed of the term capped. A joint the sum would take out of its box is held at the
//! box edge, the cycle's solve repeated without it and the term computed again (saturation in
//! the null space, [`crate::ik::saturation`]); after [`MAX_HOLDS`] such joints the term is
//! shortened to stay in the box.

use super::compensation::Compensation;
use crate::error::IkError;
use crate::ik::{RmrcProblem, SaturatedRmrc};
use nalgebra::DVector;

/// Joints the compensating term may still hold at their limit box before it is shortened.
pub const MAX_HOLDS: usize = 4;

/// `|J_Lz qd_r|` below which the reducing joints cannot change `L_z` (no term is added).
const NO_EFFECT: f64 = 1e-12;

/// Preallocated in-cycle compensation (module docs) for task maps of up to `max_rows` rows.
#[derive(Debug, Clone)]
pub struct InCycleCompensation {
    comp: Compensation,
    max_speed: f64,
    dir: DVector<f64>,
    zero_x: DVector<f64>,
    qdot_r: DVector<f64>,
}

impl InCycleCompensation {
    /// `comp` with the largest joint speed `max_speed` of the compensating term \[rad/s].
    pub fn new(comp: Compensation, max_rows: usize, max_speed: f64) -> Result<Self, IkError> {
        if !(max_speed > 0.0 && max_speed.is_finite()) {
            return Err(IkError::InvalidParameter {
                name: "compensation max speed",
                reason: "must be finite and > 0",
            });
        }
        let nv = comp.nv();
        Ok(Self {
            dir: DVector::zeros(nv),
            zero_x: DVector::zeros(max_rows),
            qdot_r: DVector::zeros(nv),
            comp,
            max_speed,
        })
    }

    /// The reducing set and gain.
    pub fn compensation(&self) -> &Compensation {
        &self.comp
    }

    /// Adds the compensating term towards `l_desired` to `qdot`, the solution of `main` by
    /// `sns` (its factorisation and held joints are reused), with `jlz = J_Lz^T` at the
    /// cycle's configuration.
    pub fn apply(
        &mut self,
        sns: &mut SaturatedRmrc,
        main: &RmrcProblem<'_>,
        jlz: &DVector<f64>,
        l_desired: f64,
        qdot: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        self.check(main, jlz, qdot)?;
        for _ in 0..=MAX_HOLDS {
            let f = self.factor(sns, main, jlz, l_desired, qdot)?;
            match sns.worst_outside(qdot, &self.qdot_r, f) {
                None => {
                    qdot.axpy(f, &self.qdot_r, 1.0);
                    return Ok(());
                }
                Some((i, v)) => {
                    sns.hold(i, v);
                    sns.saturate(main, qdot)?;
                }
            }
        }
        let f = self.factor(sns, main, jlz, l_desired, qdot)?;
        let f = sns.box_fraction(qdot, &self.qdot_r, f);
        qdot.axpy(f, &self.qdot_r, 1.0);
        Ok(())
    }

    /// `qd_r` for the reducing direction and the factor `f` of the compensating term.
    fn factor(
        &mut self,
        sns: &mut SaturatedRmrc,
        main: &RmrcProblem<'_>,
        jlz: &DVector<f64>,
        l_desired: f64,
        qdot: &DVector<f64>,
    ) -> Result<f64, IkError> {
        self.dir.fill(0.0);
        for &i in self.comp.reducing() {
            self.dir[i] = jlz[i];
        }
        let p = RmrcProblem {
            xdot: &self.zero_x,
            null_space: Some((&self.dir, 1.0)),
            ..*main
        };
        sns.resolve(&p, &mut self.qdot_r)?;
        let effect = jlz.dot(&self.qdot_r);
        if effect.abs() < NO_EFFECT {
            return Ok(0.0);
        }
        let mut f = self.comp.gain() * (l_desired - jlz.dot(qdot)) / effect;
        let peak = self.qdot_r.amax() * f.abs();
        if peak > self.max_speed {
            f *= self.max_speed / peak;
        }
        Ok(f)
    }

    /// Sizes of `jlz` and `qdot` against the reducing set's model; the zero task velocity
    /// grows (once) to a task map with more rows than `max_rows`.
    fn check(
        &mut self,
        main: &RmrcProblem<'_>,
        jlz: &DVector<f64>,
        qdot: &DVector<f64>,
    ) -> Result<(), IkError> {
        if main.rows > self.zero_x.len() {
            self.zero_x = DVector::zeros(main.rows);
        }
        let n = self.dir.len();
        for (what, got) in [("J_Lz", jlz.len()), ("qdot", qdot.len())] {
            if got != n {
                return Err(IkError::Dimension {
                    what,
                    expected: n,
                    got,
                });
            }
        }
        Ok(())
    }
}
