//! Position-based IK (thesis 4.2): Newton-Raphson root finding (Algorithm 4.1) and the
//! optimisation form (Algorithm 4.2) with a Wolfe line search, stopped by the criteria of
//! Table 4.1.
//!
//! Table 4.1 says the criteria are "combined via disjunction" but writes `sigma_1 ^ sigma_2`;
//! we stop as soon as ANY criterion holds (disjunction) and report which one. Newton steps
//! use the minimum-norm generalized inverse (4.3) through [`Rmrc`] (W = E), so no `J#` is
//! formed. The optimisation direction (4.5) with `B_k = J^T J + delta E` (footnote 1) equals
//! `d = (J^T J + delta E)^-1 J^T Delta x = J^T (J J^T + delta E)^-1 Delta x` (push-through
//! identity), i.e. a damped least squares step: again an m x m solve.
//! "Progress too small" (sigma_3) compares successive task errors `Delta x`, which for
//! position tasks equals `|f(q_k+1) - f(q_k)|`.

use super::line_search::{wolfe_search, WolfeParams};
use super::rmrc::{Rmrc, RmrcProblem};
use super::task_map::{TaskBuffers, TaskMap};
use super::weight::Weight;
use crate::error::IkError;
pub use crate::error::StopReason;
use nalgebra::DVector;

/// Tolerances of Table 4.1 and solver parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IkSettings {
    /// `k_max` (sigma_1).
    pub max_iterations: usize,
    /// `eps_c` on `|Delta x|` (sigma_2).
    pub eps_converged: f64,
    /// `eps_p` on the change of `Delta x` per iteration (sigma_3).
    pub eps_progress: f64,
    /// `eps_g` on `|J^T Delta x|` (sigma_4).
    pub eps_gradient: f64,
    /// `delta` of `B_k = J^T J + delta E` (Algorithm 4.2; 0 for plain Newton steps).
    pub delta: f64,
    /// Line search parameters (Algorithm 4.2).
    pub wolfe: WolfeParams,
}

impl Default for IkSettings {
    fn default() -> Self {
        Self {
            max_iterations: 100,
            eps_converged: 1e-10,
            eps_progress: 1e-14,
            eps_gradient: 1e-12,
            delta: 1e-6,
            wolfe: WolfeParams::default(),
        }
    }
}

/// Outcome of a position IK run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IkReport {
    /// Criterion that stopped the iteration.
    pub stop: StopReason,
    /// Iterations performed.
    pub iterations: usize,
    /// `|Delta x|` at the returned q.
    pub error_norm: f64,
}

impl IkReport {
    /// True if the target was reached (sigma_2).
    pub fn reached(&self) -> bool {
        self.stop == StopReason::Converged
    }

    /// `Ok(self)` if reached, else [`IkError::Unreachable`] with the stopping reason.
    pub fn require_reached(self) -> Result<Self, IkError> {
        if self.reached() {
            Ok(self)
        } else {
            Err(IkError::Unreachable {
                stop: self.stop,
                error_norm: self.error_norm,
            })
        }
    }
}

/// Preallocated position-based IK solver for one task map size.
#[derive(Debug, Clone)]
pub struct PositionIk {
    /// Settings (Table 4.1 tolerances).
    pub settings: IkSettings,
    rmrc: Rmrc,
    cur: TaskBuffers,
    trial: TaskBuffers,
    step: DVector<f64>,
    grad: DVector<f64>,
    q_trial: DVector<f64>,
}

impl PositionIk {
    /// Solver sized for `task`.
    pub fn new(task: &impl TaskMap, settings: IkSettings) -> Self {
        Self {
            settings,
            rmrc: Rmrc::new(task.max_rows(), task.nv()),
            cur: TaskBuffers::new(task),
            trial: TaskBuffers::new(task),
            step: DVector::zeros(task.nv()),
            grad: DVector::zeros(task.nv()),
            q_trial: DVector::zeros(task.nq()),
        }
    }

    /// Newton-Raphson (Algorithm 4.1): `q_k+1 = q_k - J#_k r_k` until a criterion holds;
    /// `q` is the start (last solution) and receives the result.
    pub fn newton_raphson(
        &mut self,
        task: &mut impl TaskMap,
        q: &mut DVector<f64>,
    ) -> Result<IkReport, IkError> {
        self.iterate(task, q, false)
    }

    /// Optimisation form (Algorithm 4.2): direction (4.5) with `B_k = J^T J + delta E` and a
    /// strong-Wolfe step size, minimising (4.4); `q` is the start and receives the result.
    pub fn optimize(
        &mut self,
        task: &mut impl TaskMap,
        q: &mut DVector<f64>,
    ) -> Result<IkReport, IkError> {
        if !(self.settings.delta > 0.0 && self.settings.delta.is_finite()) {
            return Err(IkError::InvalidParameter {
                name: "delta",
                reason: "must be > 0",
            });
        }
        self.iterate(task, q, true)
    }

    /// Shared iteration of Algorithms 4.1 and 4.2.
    fn iterate(
        &mut self,
        task: &mut impl TaskMap,
        q: &mut DVector<f64>,
        line_search: bool,
    ) -> Result<IkReport, IkError> {
        self.check(task, q)?;
        self.cur.evaluate(task, q)?;
        let s = self.settings;
        let mut k = 0;
        let stop = loop {
            if let Some(stop) = self.stationary(k) {
                break stop;
            }
            let damping = if line_search { s.delta } else { 0.0 };
            let mut p = RmrcProblem::new(
                &self.cur.jac,
                self.cur.rows,
                &self.cur.err,
                &Weight::Identity,
            );
            p.damping = damping;
            match self.rmrc.solve(&p, &mut self.step) {
                Err(IkError::NotPositiveDefinite) => break StopReason::Singular,
                r => r?,
            }
            let accepted = if line_search {
                self.line_search_step(task, q)?
            } else {
                task.retract(q, &self.step, 1.0, &mut self.q_trial)?;
                self.trial.evaluate(task, &self.q_trial)?;
                true
            };
            if !accepted {
                break StopReason::NoDecrease;
            }
            let progress = progress(&self.cur, &self.trial);
            std::mem::swap(&mut self.cur, &mut self.trial);
            q.copy_from(&self.q_trial);
            k += 1;
            if self.cur.error_norm() >= s.eps_converged && progress < s.eps_progress {
                break StopReason::SmallProgress;
            }
        };
        Ok(IkReport {
            stop,
            iterations: k,
            error_norm: self.cur.error_norm(),
        })
    }

    /// sigma_2, sigma_4 and sigma_1 at the current iterate (in this order).
    fn stationary(&mut self, k: usize) -> Option<StopReason> {
        let s = &self.settings;
        if self.cur.error_norm() < s.eps_converged {
            return Some(StopReason::Converged);
        }
        self.cur.jt_err(&mut self.grad);
        if self.grad.norm() < s.eps_gradient {
            return Some(StopReason::SmallGradient);
        }
        (k >= s.max_iterations).then_some(StopReason::IterationLimit)
    }

    /// Wolfe line search along `self.step`; leaves `q_trial`/`trial` at the accepted point.
    fn line_search_step(
        &mut self,
        task: &mut impl TaskMap,
        q: &DVector<f64>,
    ) -> Result<bool, IkError> {
        let phi0 = 0.5 * self.cur.error_norm().powi(2);
        // phi'(0) = grad phi . d = -(J^T Delta x) . d
        let dphi0 = -self.grad.dot(&self.step);
        if dphi0 >= 0.0 {
            return Ok(false);
        }
        let (step, q_trial, trial) = (&self.step, &mut self.q_trial, &mut self.trial);
        let mut jd = 0.0;
        let mut eval = |a: f64| -> Result<(f64, f64), IkError> {
            task.retract(q, step, a, q_trial)?;
            trial.evaluate(task, q_trial)?;
            jd = (0..trial.rows)
                .map(|i| {
                    trial.err[i]
                        * (0..step.len())
                            .map(|c| trial.jac[(i, c)] * step[c])
                            .sum::<f64>()
                })
                .sum();
            Ok((0.5 * trial.error_norm().powi(2), -jd))
        };
        let r = wolfe_search(&self.settings.wolfe, phi0, dphi0, &mut eval)?;
        if r.alpha <= 0.0 {
            return Ok(false);
        }
        eval(r.alpha)?;
        Ok(true)
    }

    /// Validates the start configuration against the task map.
    fn check(&self, task: &impl TaskMap, q: &DVector<f64>) -> Result<(), IkError> {
        super::linalg::check_dim("q", task.nq(), q.len())?;
        super::linalg::check_dim("task nv", self.step.len(), task.nv())?;
        super::linalg::check_finite("q", q.as_slice())
    }
}

/// `|Delta x_k+1 - Delta x_k|` over the common rows (sigma_3).
fn progress(cur: &TaskBuffers, next: &TaskBuffers) -> f64 {
    let m = cur.rows.min(next.rows);
    (0..m)
        .map(|i| (next.err[i] - cur.err[i]).powi(2))
        .sum::<f64>()
        .sqrt()
}
