//! Hard joint limits in RMRC by saturation in the null space (SNS, after Flacco, De Luca and
//! Khatib 2012, without task scaling): the joint velocities of (4.12) are kept inside the box
//! of [`super::limits`].
//!
//! Loop (an active-set iteration, warm-started with the joints held in the previous call so
//! that constraints switch only where the solution crosses the box edge, which keeps `qd`
//! continuous in time): solve (4.12) by Algorithm 4.3; while a joint leaves its box, take
//! the one furthest out, fix its velocity at the box edge, remove it from the solve and solve
//! again for the remaining joints; release a held joint whose multiplier shows it would move
//! back inside. With joints `s` fixed at `qd_s` the remaining problem is
//! `min 1/2 qd_f^T W_ff qd_f + (alpha_N grad_H_f + W_fs qd_s)^T qd_f` subject to
//! `J_f qd_f = xd - J_s qd_s`: the fixed columns of `J` are zeroed (so `B = J_f W_ff^-1 J_f^T`),
//! their entries of `grad_H` and of the rank-one vector of `W = D + u u^T` are zeroed (which
//! leaves `W_ff` and decouples the fixed joints) and `W_fs qd_s = u_f (u_s^T qd_s)` is added to
//! the gradient. Once joints are fixed, `B` is damped by `lambda^2 = rho mean(diag B)` of
//! the full problem (`rho` = `LimitSettings::regularisation`; damped least squares, 4.4): when the fixed
//! joints take rank from the tasks (a leg joint of a non-redundant leg task), the tasks then
//! yield in the least-squares sense instead of the remaining joints racing to satisfy a
//! nearly singular system; the limits never yield. After `max_iterations` the
//! remaining joints are clamped into the box. Everything is preallocated (no allocation per
//! call once the weight buffer has the shape of the weight in use). Trailing soft unit rows
//! ([`SaturatedRmrc::set_unit_rows`]) are folded by the inner solve; a held joint's unit row is
//! a zero row of the restricted problem there and folds nothing, so the damping, the restricted
//! solves and the release test are those of the stacked problem.

mod multipliers;
mod restrict;

use super::limits::JointLimits;
use super::rmrc::{Rmrc, RmrcProblem};
use super::weight::Weight;
use crate::error::IkError;
use nalgebra::{DMatrix, DVector};

/// What the last saturated solve did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SaturationReport {
    /// Joints fixed at a box edge and removed from the solve.
    pub fixed: usize,
    /// Joints clamped after the last iteration (0 unless `max_iterations` ran out).
    pub clamped: usize,
}

/// RMRC (Algorithm 4.3) with hard joint position and velocity limits (SNS).
#[derive(Debug, Clone)]
pub struct SaturatedRmrc {
    rmrc: Rmrc,
    limits: JointLimits,
    lo: DVector<f64>,
    hi: DVector<f64>,
    fixed: Vec<bool>,
    upper: Vec<bool>,
    pinned: Vec<bool>,
    value: DVector<f64>,
    jac: DMatrix<f64>,
    xdot: DVector<f64>,
    grad: DVector<f64>,
    weight: Weight,
    report: SaturationReport,
    /// `D^-1` and `D^-1 u` of the weight (for `diag W^-1`).
    parts: DVector<f64>,
    /// `lambda^2` of the last restricted solve.
    damping: f64,
    /// Largest number of joints fixed per solve.
    pub max_iterations: usize,
}

impl SaturatedRmrc {
    /// Solver for at most `m_max` rows and `n` joint velocities keeping `limits`.
    pub fn new(m_max: usize, n: usize, limits: JointLimits) -> Result<Self, IkError> {
        if let Some(r) = limits.ranges().iter().find(|r| r.v_index >= n) {
            return Err(IkError::Dimension {
                what: "joint range v index",
                expected: n,
                got: r.v_index,
            });
        }
        Ok(Self {
            rmrc: Rmrc::new(m_max, n),
            max_iterations: limits.ranges().len(),
            limits,
            lo: DVector::zeros(n),
            hi: DVector::zeros(n),
            fixed: vec![false; n],
            upper: vec![false; n],
            pinned: vec![false; n],
            value: DVector::zeros(n),
            jac: DMatrix::zeros(m_max, n),
            xdot: DVector::zeros(m_max),
            grad: DVector::zeros(n),
            weight: Weight::Identity,
            report: SaturationReport::default(),
            parts: DVector::zeros(2 * n),
            damping: 0.0,
        })
    }

    /// The limits kept.
    pub fn limits(&self) -> &JointLimits {
        &self.limits
    }

    /// Velocity box `(lo, hi)` of the last solve.
    pub fn velocity_box(&self) -> (&DVector<f64>, &DVector<f64>) {
        (&self.lo, &self.hi)
    }

    /// Which joints (by v index) the last solve fixed at their box edge.
    pub fn fixed(&self) -> &[bool] {
        &self.fixed
    }

    /// Report of the last solve.
    pub fn report(&self) -> SaturationReport {
        self.report
    }

    /// `qdot` of (4.12) for the step `dt` at `q`, inside the box of the limits (see the
    /// module docs).
    pub fn solve(
        &mut self,
        p: &RmrcProblem<'_>,
        q: &DVector<f64>,
        dt: f64,
        qdot: &mut DVector<f64>,
    ) -> Result<SaturationReport, IkError> {
        if !(dt > 0.0 && dt.is_finite()) {
            return Err(IkError::InvalidParameter {
                name: "dt",
                reason: "must be finite and > 0",
            });
        }
        self.limits.velocity_box(q, dt, &mut self.lo, &mut self.hi);
        self.pinned.fill(false);
        // warm start: the joints held in the last solve stay held at their (moved) box edge
        for i in 0..self.fixed.len() {
            if self.fixed[i] {
                self.value[i] = if self.upper[i] {
                    self.hi[i]
                } else {
                    self.lo[i]
                };
            }
        }
        self.report = SaturationReport {
            fixed: self.fixed.iter().filter(|f| **f).count(),
            clamped: 0,
        };
        self.saturate(p, qdot)
    }

    /// Declares the trailing unit rows of the following problems ([`Rmrc::set_unit_rows`]).
    pub fn set_unit_rows(&mut self, columns: &[usize]) -> Result<(), IkError> {
        self.rmrc.set_unit_rows(columns)
    }

    /// Forgets the joints held so far (the next [`Self::solve`] starts from the free problem).
    pub fn reset(&mut self) {
        self.fixed.fill(false);
        self.report = SaturationReport::default();
    }

    /// Solves `p` with the joints held so far (by the last [`Self::solve`] or [`Self::hold`]),
    /// holding more while any leaves the box and releasing a held joint whose multiplier
    /// says it would move inside (active-set iteration, one joint per step).
    pub fn saturate(
        &mut self,
        p: &RmrcProblem<'_>,
        qdot: &mut DVector<f64>,
    ) -> Result<SaturationReport, IkError> {
        self.report.clamped = 0;
        self.solve_held(p, qdot)?;
        for _ in 0..2 * self.max_iterations {
            if let Some(i) = self.worst(qdot) {
                self.hold_at(i, qdot[i]);
            } else if let Some(i) = self.releasable(p, qdot) {
                self.fixed[i] = false;
                self.report.fixed -= 1;
            } else {
                return Ok(self.report);
            }
            self.solve_held(p, qdot)?;
        }
        for r in self.limits.ranges() {
            let i = r.v_index;
            let v = qdot[i].clamp(self.lo[i], self.hi[i]);
            self.report.clamped += (v != qdot[i]) as usize;
            qdot[i] = v;
        }
        Ok(self.report)
    }

    /// Response to `p` (same rows, Jacobian, weight and softness as the last [`Self::solve`],
    /// other `xdot` / null-space term) with the joints fixed there held still: reuses the
    /// factorisation (as [`Rmrc::resolve`]); fixed entries of `qdot` are 0.
    pub fn resolve(&mut self, p: &RmrcProblem<'_>, qdot: &mut DVector<f64>) -> Result<(), IkError> {
        if self.report.fixed == 0 {
            let damped = RmrcProblem {
                damping: p.damping + self.damping,
                ..*p
            };
            return self.rmrc.resolve(&damped, qdot);
        }
        let m = p.rows;
        self.xdot.rows_mut(0, m).copy_from(&p.xdot.rows(0, m));
        self.restrict_gradient(p, false);
        self.run_restricted(p, qdot, false)
    }

    /// Holds joint `i` (v index) at the box edge nearer to `value` in the next
    /// [`Self::saturate`] calls until the next [`Self::solve`] (not released in between).
    pub fn hold(&mut self, i: usize, value: f64) {
        self.hold_at(i, value);
        self.pinned[i] = true;
    }

    /// Holds joint `i` at the box edge nearer to `value`.
    fn hold_at(&mut self, i: usize, value: f64) {
        if !self.fixed[i] {
            self.fixed[i] = true;
            self.report.fixed += 1;
        }
        self.upper[i] = value >= 0.5 * (self.lo[i] + self.hi[i]);
        self.value[i] = if self.upper[i] {
            self.hi[i]
        } else {
            self.lo[i]
        };
    }

    /// Solves with the held joints removed (or the whole problem when none is held), damped
    /// alike in both cases so that holding and releasing a joint solve the same problem.
    fn solve_held(&mut self, p: &RmrcProblem<'_>, qdot: &mut DVector<f64>) -> Result<(), IkError> {
        self.damping = self.regularisation(p.jacobian, p.weight, p.rows);
        match self.report.fixed {
            0 => {
                let damped = RmrcProblem {
                    damping: p.damping + self.damping,
                    ..*p
                };
                self.rmrc.solve(&damped, qdot)
            }
            _ => self.solve_restricted(p, qdot),
        }
    }

    /// Free joint furthest outside the box in `base + f extra`, with that value.
    pub fn worst_outside(
        &self,
        base: &DVector<f64>,
        extra: &DVector<f64>,
        f: f64,
    ) -> Option<(usize, f64)> {
        let mut best = (None, 1e-12);
        for r in self.limits.ranges() {
            let i = r.v_index;
            let v = base[i] + f * extra[i];
            let excess = (v - self.hi[i]).max(self.lo[i] - v);
            if !self.fixed[i] && excess > best.1 {
                best = (Some((i, v)), excess);
            }
        }
        best.0
    }

    /// Largest `f'` between 0 and `f` with `base + f' extra` inside the box of the last solve
    /// (`base` inside it).
    pub fn box_fraction(&self, base: &DVector<f64>, extra: &DVector<f64>, f: f64) -> f64 {
        let mut t: f64 = 1.0;
        for r in self.limits.ranges() {
            let i = r.v_index;
            let d = f * extra[i];
            let room = if d > 0.0 {
                self.hi[i] - base[i]
            } else {
                self.lo[i] - base[i]
            };
            if d != 0.0 {
                t = t.min((room / d).max(0.0));
            }
        }
        t * f
    }

    /// Free joint furthest outside its box, if any.
    fn worst(&self, qdot: &DVector<f64>) -> Option<usize> {
        self.worst_outside(qdot, qdot, 0.0).map(|(i, _)| i)
    }
}
