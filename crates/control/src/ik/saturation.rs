//! Hard joint limits in RMRC by saturation in the null space (SNS, after Flacco, De Luca and
//! Khatib 2012, without task scaling): the joint velocities of (4.12) are kept inside the box
//! of [`super::limits`].
//!
//! Loop: solve (4.12) by Algorithm 4.3; while a joint leaves its box, take the one furthest
//! out, fix its velocity at the box edge, remove it from the solve and solve again for the
//! remaining joints. With joints `s` fixed at `qd_s` the remaining problem is
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
//! call once the weight buffer has the shape of the weight in use).

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
        self.fixed.fill(false);
        self.value.fill(0.0);
        self.report = SaturationReport::default();
        self.saturate(p, qdot)
    }

    /// Solves `p` with the joints fixed so far (by [`Self::solve`] or [`Self::hold`]) held,
    /// fixing more while any leaves the box of the last [`Self::solve`].
    pub fn saturate(
        &mut self,
        p: &RmrcProblem<'_>,
        qdot: &mut DVector<f64>,
    ) -> Result<SaturationReport, IkError> {
        self.report.clamped = 0;
        match self.report.fixed {
            0 => self.rmrc.solve(p, qdot)?,
            _ => self.solve_restricted(p, qdot)?,
        }
        for _ in 0..self.max_iterations {
            let Some(i) = self.worst(qdot) else {
                return Ok(self.report);
            };
            self.hold(i, qdot[i]);
            self.solve_restricted(p, qdot)?;
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
            return self.rmrc.resolve(p, qdot);
        }
        let m = p.rows;
        self.xdot.rows_mut(0, m).copy_from(&p.xdot.rows(0, m));
        self.restrict_gradient(p, false);
        let q = RmrcProblem {
            jacobian: &self.jac,
            rows: m,
            xdot: &self.xdot,
            weight: restricted(p.weight, &self.weight),
            null_space: Some((&self.grad, 1.0)),
            damping: p.damping + self.damping,
            softness: p.softness,
        };
        self.rmrc.resolve(&q, qdot)?;
        for (v, f) in qdot.iter_mut().zip(&self.fixed) {
            if *f {
                *v = 0.0;
            }
        }
        Ok(())
    }

    /// Holds joint `i` (v index) at `value` clamped into its box in the next
    /// [`Self::saturate`].
    pub fn hold(&mut self, i: usize, value: f64) {
        if !self.fixed[i] {
            self.fixed[i] = true;
            self.report.fixed += 1;
        }
        self.value[i] = value.clamp(self.lo[i], self.hi[i]);
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

    /// Solves the problem without the fixed joints (module docs) and sets their velocities.
    fn solve_restricted(
        &mut self,
        p: &RmrcProblem<'_>,
        qdot: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        let m = p.rows;
        let nr = p.jacobian.nrows();
        let src = p.jacobian.as_slice();
        let mm = self.jac.nrows();
        let dst = self.jac.as_mut_slice();
        self.xdot.rows_mut(0, m).copy_from(&p.xdot.rows(0, m));
        for (c, fixed) in self.fixed.iter().enumerate() {
            let (a, b) = (&src[c * nr..c * nr + m], &mut dst[c * mm..c * mm + m]);
            if *fixed {
                b.fill(0.0);
                let s = self.value[c];
                for (x, j) in self.xdot.iter_mut().zip(a) {
                    *x -= j * s;
                }
            } else {
                b.copy_from_slice(a);
            }
        }
        self.restrict_weight(p.weight);
        self.restrict_gradient(p, true);
        self.damping = self.regularisation(p.jacobian, p.weight, m);
        let q = RmrcProblem {
            jacobian: &self.jac,
            rows: m,
            xdot: &self.xdot,
            weight: restricted(p.weight, &self.weight),
            null_space: Some((&self.grad, 1.0)),
            damping: p.damping + self.damping,
            softness: p.softness,
        };
        self.rmrc.solve(&q, qdot)?;
        for (i, f) in self.fixed.iter().enumerate() {
            if *f {
                qdot[i] = self.value[i];
            }
        }
        Ok(())
    }

    /// `lambda^2 = (rho + 1e-12) mean(diag(J W^-1 J^T))` over the first `m` rows of the full
    /// Jacobian `j`, with `diag W^-1 = D^-1 - (D^-1 u)^2 / c` (7.14); the floor keeps `B`
    /// positive definite when the fixed joints take all rank (`rho = 0`: practically exact).
    fn regularisation(&mut self, j: &DMatrix<f64>, w: &Weight, m: usize) -> f64 {
        let n = self.fixed.len();
        let (dinv, du) = self.parts.as_mut_slice().split_at_mut(n);
        let c = w.inverse_parts(dinv, du);
        let columns = j.as_slice().chunks_exact(j.nrows().max(1));
        let mut trace = 0.0;
        for (col, (d, e)) in columns.zip(dinv.iter().zip(du.iter())) {
            let winv = if c > 0.0 { d - e * e / c } else { *d };
            trace += winv * col[..m].iter().map(|x| x * x).sum::<f64>();
        }
        (self.limits.settings().regularisation + 1e-12) * trace / m.max(1) as f64
    }

    /// `grad = alpha_N grad_H` zeroed at the fixed joints, plus `W_fs qd_s` if `coupled`.
    fn restrict_gradient(&mut self, p: &RmrcProblem<'_>, coupled: bool) {
        match p.null_space {
            Some((g, alpha)) => {
                self.grad.copy_from(g);
                self.grad *= alpha;
            }
            None => self.grad.fill(0.0),
        }
        let cross = match p.weight {
            Weight::DiagonalRankOne { u, .. } if coupled => {
                let us: f64 = (0..u.len())
                    .filter(|&i| self.fixed[i])
                    .map(|i| u[i] * self.value[i])
                    .sum();
                Some((u, us))
            }
            _ => None,
        };
        for i in 0..self.grad.len() {
            if self.fixed[i] {
                self.grad[i] = 0.0;
            } else if let Some((u, us)) = cross {
                self.grad[i] += u[i] * us;
            }
        }
    }

    /// Copies a rank-one weight with the fixed joints' entries of `u` zeroed into the buffer.
    fn restrict_weight(&mut self, w: &Weight) {
        if let Weight::DiagonalRankOne { diag, u } = w {
            match &mut self.weight {
                Weight::DiagonalRankOne { diag: d, u: v } if v.len() == u.len() => {
                    d.copy_from(diag);
                    v.copy_from(u);
                }
                buf => *buf = w.clone(),
            }
            if let Weight::DiagonalRankOne { u: v, .. } = &mut self.weight {
                for (x, f) in v.iter_mut().zip(&self.fixed) {
                    if *f {
                        *x = 0.0;
                    }
                }
            }
        }
    }
}

/// The weight of a restricted solve: the buffer for a rank-one weight, else the weight itself
/// (a diagonal weight needs no change once the fixed columns and gradient entries are 0).
fn restricted<'a>(w: &'a Weight, buf: &'a Weight) -> &'a Weight {
    match w {
        Weight::DiagonalRankOne { .. } => buf,
        _ => w,
    }
}
