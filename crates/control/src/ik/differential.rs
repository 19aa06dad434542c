//! Differential IK loops (thesis 4.3): closed-loop RMRC tracking (4.13)-(4.16), the Jacobian
//! transpose method (4.17) and resolved acceleration control (4.18)-(4.21).
//!
//! `Jdot qd` for (4.20) is obtained generically from the task map by a central difference of
//! `J(q) qd` along the motion: `Jdot qd ~ (J(q (+) h qd) qd - J(q (+) -h qd) qd) / (2h)`,
//! O(h^2) accurate (Lola's coupled mechanisms provide no `Jdot`). Configurations move only
//! through [`TaskMap::retract`] (quaternion base), the trapezoidal rule (4.21) becomes
//! `q_i+1 = q_i (+) (qd_i + qd_i+1)/2 dt`.

use super::limits::JointLimits;
use super::linalg::{check_dim, check_finite};
use super::rmrc::{Rmrc, RmrcProblem};
use super::saturation::SaturatedRmrc;
use super::task_map::{TaskBuffers, TaskMap};
use super::weight::Weight;
use crate::error::IkError;
use nalgebra::{DMatrix, DVector};

/// Inputs of one closed-loop RMRC cycle beyond the task map.
#[derive(Debug, Clone, Copy)]
pub struct CycleInput<'a> {
    /// Task-space feedback gain `K_x` (scalar times E, (4.14b)); `0 < K_x dt < 2` for stability.
    pub gain: f64,
    /// Joint weight W (4.11).
    pub weight: &'a Weight,
    /// Null-space gradient `grad_H` and `alpha_N` (4.12).
    pub null_space: Option<(&'a DVector<f64>, f64)>,
    /// Damping `lambda^2` (damped least squares; 0 = exact RMRC).
    pub damping: f64,
    /// Sample time dt.
    pub dt: f64,
}

/// Preallocated closed-loop differential IK (Fig. 4.3): (4.12)-(4.16), optionally with hard
/// joint limits ([`SaturatedRmrc`]).
#[derive(Debug, Clone)]
pub struct ClosedLoopIk {
    rmrc: Rmrc,
    limited: Option<SaturatedRmrc>,
    /// Task buffers of the last evaluation (error, Jacobian).
    pub tasks: TaskBuffers,
    xcmd: DVector<f64>,
    /// Joint velocities of the last cycle.
    pub qdot: DVector<f64>,
    q_next: DVector<f64>,
}

impl ClosedLoopIk {
    /// Workspace sized for `task`.
    pub fn new(task: &impl TaskMap) -> Self {
        Self {
            rmrc: Rmrc::new(task.max_rows(), task.nv()),
            limited: None,
            tasks: TaskBuffers::new(task),
            xcmd: DVector::zeros(task.max_rows()),
            qdot: DVector::zeros(task.nv()),
            q_next: DVector::zeros(task.nq()),
        }
    }

    /// Workspace sized for `task` whose steps keep `limits` (SNS, [`SaturatedRmrc`]).
    pub fn with_limits(task: &impl TaskMap, limits: JointLimits) -> Result<Self, IkError> {
        let solver = SaturatedRmrc::new(task.max_rows(), task.nv(), limits)?;
        Ok(Self {
            limited: Some(solver),
            ..Self::new(task)
        })
    }

    /// The limit-keeping solver, if any.
    pub fn limits(&self) -> Option<&SaturatedRmrc> {
        self.limited.as_ref()
    }

    /// Joint velocities of one cycle at `q`: `xd_cmd = xd_d + K_x Delta x` (4.14b), then
    /// (4.12) by Algorithm 4.3 (with the task map's row softness, inside the joint limits if
    /// given); result in `self.qdot`.
    pub fn velocities(
        &mut self,
        task: &mut impl TaskMap,
        q: &DVector<f64>,
        input: &CycleInput<'_>,
    ) -> Result<&DVector<f64>, IkError> {
        check_finite("gain", &[input.gain])?;
        self.tasks.evaluate(task, q)?;
        task.feedforward(&mut self.xcmd);
        let m = self.tasks.rows;
        for i in 0..m {
            self.xcmd[i] += input.gain * self.tasks.err[i];
        }
        let p = RmrcProblem {
            jacobian: &self.tasks.jac,
            rows: m,
            xdot: &self.xcmd,
            weight: input.weight,
            null_space: input.null_space,
            damping: input.damping,
            softness: task.softness(),
        };
        match &mut self.limited {
            Some(s) => {
                s.set_unit_rows(task.unit_rows())?;
                s.solve(&p, q, input.dt, &mut self.qdot)?;
            }
            None => {
                self.rmrc.set_unit_rows(task.unit_rows())?;
                self.rmrc.solve(&p, &mut self.qdot)?;
            }
        }
        Ok(&self.qdot)
    }

    /// One full cycle: [`Self::velocities`] then explicit Euler `q <- q (+) qd dt` (4.16).
    pub fn step(
        &mut self,
        task: &mut impl TaskMap,
        q: &mut DVector<f64>,
        input: &CycleInput<'_>,
    ) -> Result<(), IkError> {
        self.velocities(task, q, input)?;
        self.integrate(task, q, input.dt)
    }

    /// After [`Self::velocities`] with the same `task` and `input`: `correct` changes
    /// `self.qdot` with the limit-keeping solver, which still holds the cycle's
    /// factorisation, and the cycle's problem (e.g. the in-cycle momentum compensation of
    /// `crate::momentum::in_cycle`). An error for a workspace without limits.
    pub fn correct<F>(
        &mut self,
        task: &impl TaskMap,
        input: &CycleInput<'_>,
        correct: F,
    ) -> Result<(), IkError>
    where
        F: FnOnce(&mut SaturatedRmrc, &RmrcProblem<'_>, &mut DVector<f64>) -> Result<(), IkError>,
    {
        let sns = self.limited.as_mut().ok_or(IkError::InvalidParameter {
            name: "correct",
            reason: "needs a workspace with joint limits (ClosedLoopIk::with_limits)",
        })?;
        let p = RmrcProblem {
            jacobian: &self.tasks.jac,
            rows: self.tasks.rows,
            xdot: &self.xcmd,
            weight: input.weight,
            null_space: input.null_space,
            damping: input.damping,
            softness: task.softness(),
        };
        correct(sns, &p, &mut self.qdot)
    }

    /// Explicit Euler `q <- q (+) qd dt` (4.16) with the cycle's velocities.
    pub fn integrate(
        &mut self,
        task: &impl TaskMap,
        q: &mut DVector<f64>,
        dt: f64,
    ) -> Result<(), IkError> {
        task.retract(q, &self.qdot, dt, &mut self.q_next)?;
        q.copy_from(&self.q_next);
        Ok(())
    }
}

/// Jacobian transpose method (4.17): `qd = J^T K_x Delta x` over the first `rows` rows.
pub fn jacobian_transpose(
    jac: &DMatrix<f64>,
    rows: usize,
    err: &DVector<f64>,
    gain: f64,
    qdot: &mut DVector<f64>,
) -> Result<(), IkError> {
    check_dim("qdot", jac.ncols(), qdot.len())?;
    if rows > jac.nrows() || rows > err.len() {
        return Err(IkError::Dimension {
            what: "rows",
            expected: jac.nrows().min(err.len()),
            got: rows,
        });
    }
    for (c, o) in qdot.iter_mut().enumerate() {
        *o = gain * (0..rows).map(|i| jac[(i, c)] * err[i]).sum::<f64>();
    }
    check_finite("qdot", qdot.as_slice())
}

/// Desired task motion for resolved acceleration control (4.20).
#[derive(Debug, Clone, Copy)]
pub struct AccelerationInput<'a> {
    /// Desired task velocity `xd_d` (first m entries).
    pub xdot: &'a DVector<f64>,
    /// Desired task acceleration `xdd_d` (first m entries).
    pub xddot: &'a DVector<f64>,
    /// Position gain `K_x`.
    pub kp: f64,
    /// Velocity gain `K_xd`.
    pub kd: f64,
    /// Joint weight W.
    pub weight: &'a Weight,
    /// Sample time dt.
    pub dt: f64,
}

/// Preallocated resolved acceleration control (4.18)-(4.21).
#[derive(Debug, Clone)]
pub struct ResolvedAcceleration {
    rmrc: Rmrc,
    tasks: TaskBuffers,
    shifted: TaskBuffers,
    /// `Jdot qd` of the last cycle (first m entries).
    pub jdot_qd: DVector<f64>,
    rhs: DVector<f64>,
    /// Joint accelerations of the last cycle.
    pub qddot: DVector<f64>,
    vmean: DVector<f64>,
    q_tmp: DVector<f64>,
}

impl ResolvedAcceleration {
    /// Workspace sized for `task`.
    pub fn new(task: &impl TaskMap) -> Self {
        let (m, n) = (task.max_rows(), task.nv());
        Self {
            rmrc: Rmrc::new(m, n),
            tasks: TaskBuffers::new(task),
            shifted: TaskBuffers::new(task),
            jdot_qd: DVector::zeros(m),
            rhs: DVector::zeros(m),
            qddot: DVector::zeros(n),
            vmean: DVector::zeros(n),
            q_tmp: DVector::zeros(task.nq()),
        }
    }

    /// `Jdot qd` by a central difference of `J qd` along `qd` (first m entries of `jdot_qd`).
    pub fn bias(
        &mut self,
        task: &mut impl TaskMap,
        q: &DVector<f64>,
        qd: &DVector<f64>,
    ) -> Result<(), IkError> {
        let h = 1e-5 / (1.0 + qd.amax());
        self.jdot_qd.fill(0.0);
        for sign in [1.0, -1.0] {
            task.retract(q, qd, sign * h, &mut self.q_tmp)?;
            self.shifted.evaluate(task, &self.q_tmp)?;
            for i in 0..self.shifted.rows {
                let jv: f64 = (0..qd.len())
                    .map(|c| self.shifted.jac[(i, c)] * qd[c])
                    .sum();
                self.jdot_qd[i] += sign * jv / (2.0 * h);
            }
        }
        Ok(())
    }

    /// One cycle: `qdd` from (4.20) (no null-space term), then the trapezoidal update (4.21)
    /// of `qd` and `q` in place.
    pub fn step(
        &mut self,
        task: &mut impl TaskMap,
        q: &mut DVector<f64>,
        qd: &mut DVector<f64>,
        input: &AccelerationInput<'_>,
    ) -> Result<(), IkError> {
        check_dim("qd", self.qddot.len(), qd.len())?;
        self.bias(task, q, qd)?;
        self.tasks.evaluate(task, q)?;
        let m = self.tasks.rows;
        for i in 0..m {
            let jqd: f64 = (0..qd.len()).map(|c| self.tasks.jac[(i, c)] * qd[c]).sum();
            self.rhs[i] =
                input.xddot[i] + input.kd * (input.xdot[i] - jqd) + input.kp * self.tasks.err[i]
                    - self.jdot_qd[i];
        }
        let p = RmrcProblem::new(&self.tasks.jac, m, &self.rhs, input.weight);
        self.rmrc.solve(&p, &mut self.qddot)?;
        self.vmean.copy_from(qd);
        qd.axpy(input.dt, &self.qddot, 1.0);
        self.vmean += &*qd;
        self.vmean *= 0.5;
        task.retract(q, &self.vmean, input.dt, &mut self.q_tmp)?;
        q.copy_from(&self.q_tmp);
        Ok(())
    }
}
