//! The general Klein-Huang solve of [`super::Rmrc`] (Algorithm 4.3): every task row stacked
//! into `B = J W^-1 J^T (+ damping, softness)`, factorised in place.

use super::dense::{axpy, cholesky_lower, cholesky_lower_solve, columns, dot};
use super::RmrcProblem;
use crate::error::IkError;
use crate::ik::linalg::{check_dim, check_finite};
use crate::ik::weight::Weight;
use nalgebra::{DMatrix, DVector};

/// Preallocated buffers of the stacked solve for up to `m_max` rows and n DoF.
#[derive(Debug, Clone)]
pub(super) struct Kernel {
    m_max: usize,
    pub(super) n: usize,
    /// `B = J W^-1 J^T (+ damping)`, then its Cholesky factor `L` (lower triangle).
    b: DMatrix<f64>,
    /// `J D^-1 u` of a rank-one weight (m_max).
    jdu: DVector<f64>,
    /// `J^T lambda` (n).
    g: DVector<f64>,
    z: DVector<f64>,
    /// Lagrange multipliers (first m entries valid).
    pub(super) lambda: DVector<f64>,
    /// Reciprocal diagonal of the Cholesky factor.
    inv_diag: DVector<f64>,
    /// `D^-1` and `D^-1 u` of the weight (2n).
    scratch: DVector<f64>,
    /// Rows of the factorisation held in `b` (None before the first successful solve).
    pub(super) factored: Option<usize>,
}

impl Kernel {
    /// Buffers for at most `m_max` task rows and `n` joint velocities.
    pub(super) fn new(m_max: usize, n: usize) -> Self {
        Self {
            m_max,
            n,
            b: DMatrix::zeros(m_max, m_max),
            jdu: DVector::zeros(m_max),
            g: DVector::zeros(n),
            z: DVector::zeros(n),
            lambda: DVector::zeros(m_max),
            inv_diag: DVector::zeros(m_max),
            scratch: DVector::zeros(2 * n),
            factored: None,
        }
    }

    /// Row capacity m_max.
    pub(super) fn capacity(&self) -> usize {
        self.m_max
    }

    /// The stacked solve of a problem that passed [`Self::check`].
    pub(super) fn solve(
        &mut self,
        p: &RmrcProblem<'_>,
        qdot: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        let m = p.rows;
        self.factored = None;
        self.null_space_step(p)?;
        self.assemble(p.jacobian, m, p.weight)?;
        for i in 0..m {
            self.b[(i, i)] += p.damping + p.softness.map_or(0.0, |s| s[i]);
        }
        cholesky_lower(
            self.b.as_mut_slice(),
            self.m_max,
            m,
            self.inv_diag.as_mut_slice(),
        )?;
        self.factored = Some(m);
        self.back_substitute(p, qdot)
    }

    /// The solve of a checked problem with the factorisation of the last solve.
    pub(super) fn resolve(
        &mut self,
        p: &RmrcProblem<'_>,
        qdot: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        if self.factored != Some(p.rows) {
            return Err(IkError::InvalidParameter {
                name: "resolve",
                reason: "needs a preceding solve with the same rows",
            });
        }
        self.null_space_step(p)?;
        self.back_substitute(p, qdot)
    }

    /// `z = -alpha_N W^-1 grad_H` (0 without a null-space term).
    fn null_space_step(&mut self, p: &RmrcProblem<'_>) -> Result<(), IkError> {
        match p.null_space {
            Some((grad, alpha)) => {
                check_dim("null-space gradient", self.n, grad.len())?;
                check_finite("alpha_N", &[alpha])?;
                p.weight.solve_into(grad, &mut self.z)?;
                self.z *= -alpha;
            }
            None => self.z.fill(0.0),
        }
        Ok(())
    }

    /// `lambda` from the factor and `qdot = W^-1 (J^T lambda) + z` (Alg. 4.3 lines 3-5);
    /// `J` is read by contiguous columns, `W^-1` applied once to the n-vector `J^T lambda`.
    fn back_substitute(
        &mut self,
        p: &RmrcProblem<'_>,
        qdot: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        let m = p.rows;
        let lambda = &mut self.lambda.as_mut_slice()[..m];
        lambda.copy_from_slice(&p.xdot.as_slice()[..m]);
        for (jc, zc) in columns(p.jacobian, m).zip(self.z.iter()) {
            axpy(-zc, jc, lambda);
        }
        let (b, inv) = (self.b.as_slice(), self.inv_diag.as_slice());
        cholesky_lower_solve(b, self.m_max, m, inv, lambda);
        for (g, jc) in self.g.iter_mut().zip(columns(p.jacobian, m)) {
            *g = dot(jc, lambda);
        }
        p.weight
            .apply_inverse(self.g.as_slice(), qdot.as_mut_slice());
        *qdot += &self.z;
        check_finite("qdot", qdot.as_slice())
    }

    /// Yoshikawa manipulability of the first `rows` rows (see [`super::Rmrc::manipulability`]).
    pub(super) fn manipulability(
        &mut self,
        jacobian: &DMatrix<f64>,
        rows: usize,
    ) -> Result<f64, IkError> {
        self.check_jacobian(jacobian, rows)?;
        self.factored = None;
        self.assemble(jacobian, rows, &Weight::Identity)?;
        match cholesky_lower(
            self.b.as_mut_slice(),
            self.m_max,
            rows,
            self.inv_diag.as_mut_slice(),
        ) {
            Ok(()) => Ok((0..rows).map(|i| self.b[(i, i)]).product()),
            Err(IkError::NotPositiveDefinite) => Ok(0.0),
            Err(e) => Err(e),
        }
    }

    /// Lower triangle of `B = J W^-1 J^T` (column k holds `B[k..m, k]` contiguously) as
    /// `sum_c D^-1_cc J_c J_c^T - (J D^-1 u)(J D^-1 u)^T / c` over the contiguous columns
    /// `J_c` of J (7.14 applied to the whole product: no `J^T` or `W^-1 J^T` is formed; a gemm
    /// call would allocate packing buffers every cycle).
    fn assemble(&mut self, j: &DMatrix<f64>, m: usize, w: &Weight) -> Result<(), IkError> {
        let n = self.n;
        w.validate(n)?;
        let (dinv, du) = self.scratch.as_mut_slice().split_at_mut(n);
        let c = w.inverse_parts(dinv, du);
        let (mm, b) = (self.m_max, self.b.as_mut_slice());
        for k in 0..m {
            b[k * mm + k..k * mm + m].fill(0.0);
        }
        for (jc, d) in columns(j, m).zip(dinv.iter()) {
            for k in 0..m {
                axpy(d * jc[k], &jc[k..], &mut b[k * mm + k..k * mm + m]);
            }
        }
        if c > 0.0 {
            let v = &mut self.jdu.as_mut_slice()[..m];
            v.fill(0.0);
            for (jc, e) in columns(j, m).zip(du.iter()) {
                axpy(*e, jc, v);
            }
            for k in 0..m {
                axpy(-v[k] / c, &v[k..], &mut b[k * mm + k..k * mm + m]);
            }
        }
        for k in 0..m {
            check_finite("J W^-1 J^T", &b[k * mm + k..k * mm + m])?;
        }
        Ok(())
    }

    /// Validates the shapes of a problem and the output.
    pub(super) fn check(&self, p: &RmrcProblem<'_>, qdot: &DVector<f64>) -> Result<(), IkError> {
        self.check_jacobian(p.jacobian, p.rows)?;
        if p.xdot.len() < p.rows {
            return Err(IkError::Dimension {
                what: "xdot",
                expected: p.rows,
                got: p.xdot.len(),
            });
        }
        check_dim("qdot", self.n, qdot.len())?;
        check_finite("xdot", &p.xdot.as_slice()[..p.rows])?;
        if !(p.damping >= 0.0 && p.damping.is_finite()) {
            return Err(IkError::InvalidParameter {
                name: "damping",
                reason: "must be >= 0",
            });
        }
        if let Some(s) = p.softness {
            if s.len() < p.rows || s[..p.rows].iter().any(|c| !(*c >= 0.0 && c.is_finite())) {
                return Err(IkError::InvalidParameter {
                    name: "softness",
                    reason: "needs rows entries, each finite and >= 0",
                });
            }
        }
        Ok(())
    }

    /// Validates a Jacobian buffer for `rows` active rows.
    fn check_jacobian(&self, j: &DMatrix<f64>, rows: usize) -> Result<(), IkError> {
        check_dim("Jacobian columns", self.n, j.ncols())?;
        if rows > self.m_max || rows > j.nrows() {
            return Err(IkError::Dimension {
                what: "task rows (capacity)",
                expected: self.m_max.min(j.nrows()),
                got: rows,
            });
        }
        let nr = j.nrows();
        for c in 0..self.n {
            check_finite("Jacobian", &j.as_slice()[c * nr..c * nr + rows])?;
        }
        Ok(())
    }
}
