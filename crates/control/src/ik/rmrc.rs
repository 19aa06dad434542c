//! Resolved motion rate control (4.11)-(4.12) solved the Klein-Huang way (Algorithm 4.3),
//! with optional damping (damped least squares, 4.4) and per-row softness (task blending).
//!
//! Signs, derived from (4.11): minimise `1/2 qd^T W qd + alpha_N grad_H^T qd` subject to
//! `J qd = xd`. The Lagrange conditions give `qd = W^-1 J^T lambda + z` with
//! `z = -alpha_N W^-1 grad_H` and `(J W^-1 J^T) lambda = xd - J z`, i.e. (4.12):
//! `qd = J#_W xd - alpha_N N W^-1 grad_H` with `N = E - J#_W J` (Alg. 4.3 lines 1-5).
//! Neither `J#`, `N` nor `W^-1` is formed; only the m x m matrix `B` is factorised in place.
//!
//! Extensions (both keep the same structure): `damping` adds `lambda_d^2 E` to `B` (the
//! weighted damped least squares solution `W^-1 J^T (J W^-1 J^T + lambda_d^2 E)^-1 xd`), and
//! `softness` adds `c_i >= 0` to `B_ii`, the KKT system of the penalty problem
//! `1/2 qd^T W qd + sum_i (xd_i - J_i qd)^2 / (2 c_i)`. As `c_i -> infinity` row `i` drops out
//! continuously; this is how tasks are blended in and out (see [`crate::ik::blend`]).

use super::linalg::{check_dim, check_finite};
use super::weight::Weight;
use crate::error::IkError;
use nalgebra::{DMatrix, DVector};

/// One RMRC problem: the first `rows` rows of `jacobian` and `xdot` form `J` and `xd` (4.12).
#[derive(Debug, Clone, Copy)]
pub struct RmrcProblem<'a> {
    /// Task Jacobian buffer (at least `rows` x n).
    pub jacobian: &'a DMatrix<f64>,
    /// Number of active task rows m.
    pub rows: usize,
    /// Task velocity buffer (at least `rows` entries).
    pub xdot: &'a DVector<f64>,
    /// Joint-space weight W (4.7).
    pub weight: &'a Weight,
    /// Null-space term: gradient of H (length n) and `alpha_N = beta dt` (4.12).
    pub null_space: Option<(&'a DVector<f64>, f64)>,
    /// Damping `lambda_d^2 >= 0` added to `J W^-1 J^T` (damped least squares, section 4.4).
    pub damping: f64,
    /// Per-row softness `c_i >= 0` added to `B_ii` (task blending; 0 = hard constraint).
    pub softness: Option<&'a [f64]>,
}

impl<'a> RmrcProblem<'a> {
    /// Hard problem `J qd = xd` with weight `W` and no null-space term (4.9).
    pub fn new(
        jacobian: &'a DMatrix<f64>,
        rows: usize,
        xdot: &'a DVector<f64>,
        weight: &'a Weight,
    ) -> Self {
        Self {
            jacobian,
            rows,
            xdot,
            weight,
            null_space: None,
            damping: 0.0,
            softness: None,
        }
    }
}

/// Preallocated Klein-Huang RMRC solver (Algorithm 4.3) for up to `m_max` rows and n DoF.
#[derive(Debug, Clone)]
pub struct Rmrc {
    m_max: usize,
    n: usize,
    /// `B = J W^-1 J^T (+ damping)`, then its Cholesky factor `L` (lower triangle).
    b: DMatrix<f64>,
    /// `J D^-1 u` of a rank-one weight (m_max).
    jdu: DVector<f64>,
    /// `J^T lambda` (n).
    g: DVector<f64>,
    z: DVector<f64>,
    lambda: DVector<f64>,
    /// Reciprocal diagonal of the Cholesky factor.
    inv_diag: DVector<f64>,
    /// `D^-1` and `D^-1 u` of the weight (2n).
    scratch: DVector<f64>,
    /// Rows of the factorisation held in `b` (None before the first successful solve).
    factored: Option<usize>,
}

impl Rmrc {
    /// Solver for at most `m_max` task rows and `n` joint velocities.
    pub fn new(m_max: usize, n: usize) -> Self {
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

    /// Number of joint velocities n.
    pub fn nv(&self) -> usize {
        self.n
    }

    /// Lagrange multipliers `lambda` of the last solve (first m entries are valid).
    pub fn multipliers(&self) -> &DVector<f64> {
        &self.lambda
    }

    /// `qdot = J#_W xd - alpha_N N W^-1 grad_H` (4.12) by Algorithm 4.3, without allocation.
    pub fn solve(&mut self, p: &RmrcProblem<'_>, qdot: &mut DVector<f64>) -> Result<(), IkError> {
        let m = p.rows;
        self.check(p, qdot)?;
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

    /// Same as [`Self::solve`] for a problem with the Jacobian, weight, damping and softness
    /// of the last successful `solve` (only `xdot` and the null-space term may differ):
    /// reuses the factorisation, O(m n) instead of O(m^2 n). RMRC is linear in
    /// `(xdot, grad_H)`, so responses to separate inputs can be superposed.
    pub fn resolve(&mut self, p: &RmrcProblem<'_>, qdot: &mut DVector<f64>) -> Result<(), IkError> {
        self.check(p, qdot)?;
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

    /// Yoshikawa manipulability `w = sqrt(det(J J^T))` (4.22) of the first `rows` rows, from
    /// the Cholesky factor (`prod L_ii`); 0 if `J J^T` is numerically singular.
    pub fn manipulability(&mut self, jacobian: &DMatrix<f64>, rows: usize) -> Result<f64, IkError> {
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
    fn check(&self, p: &RmrcProblem<'_>, qdot: &DVector<f64>) -> Result<(), IkError> {
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

/// In-place right-looking Cholesky `B = L L^T` on the lower triangle of the leading `m x m`
/// block of the column-major `mm x mm` buffer `b` (column `k` of `L` is contiguous). The
/// trailing updates are independent axpys, so only `m` steps are on the dependency chain;
/// `inv[k] = 1 / L_kk` is stored for the solves.
fn cholesky_lower(b: &mut [f64], mm: usize, m: usize, inv: &mut [f64]) -> Result<(), IkError> {
    for k in 0..m {
        let d = b[k * mm + k];
        if d.is_nan() || d <= 0.0 {
            return Err(IkError::NotPositiveDefinite);
        }
        let l = d.sqrt();
        b[k * mm + k] = l;
        inv[k] = 1.0 / l;
        for x in &mut b[k * mm + k + 1..k * mm + m] {
            *x *= inv[k];
        }
        for j in k + 1..m {
            let (left, right) = b.split_at_mut(j * mm);
            let ck = &left[k * mm + j..k * mm + m];
            let ljk = ck[0];
            for (x, y) in right[j..m].iter_mut().zip(ck) {
                *x -= ljk * y;
            }
        }
    }
    Ok(())
}

/// Solves `L L^T x = rhs` in place on `x[..m]` with the factor of [`cholesky_lower`].
fn cholesky_lower_solve(b: &[f64], mm: usize, m: usize, inv: &[f64], x: &mut [f64]) {
    for k in 0..m {
        x[k] *= inv[k];
        let xk = x[k];
        for (xi, l) in x[k + 1..m].iter_mut().zip(&b[k * mm + k + 1..k * mm + m]) {
            *xi -= l * xk;
        }
    }
    for i in (0..m).rev() {
        let below = &b[i * mm + i + 1..i * mm + m];
        x[i] = (x[i] - dot(below, &x[i + 1..m])) * inv[i];
    }
}

/// The first `m` entries of each column of `j` (contiguous in nalgebra's column-major storage).
#[inline]
fn columns(j: &DMatrix<f64>, m: usize) -> impl Iterator<Item = &[f64]> {
    j.as_slice()
        .chunks_exact(j.nrows().max(1))
        .map(move |c| &c[..m])
}

/// `y += a x` on equally long slices.
#[inline]
fn axpy(a: f64, x: &[f64], y: &mut [f64]) {
    for (yi, xi) in y.iter_mut().zip(x) {
        *yi += a * xi;
    }
}

/// Dot product of two equally long slices.
#[inline]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    // four independent accumulators: the single-chain sum is latency bound
    let (mut acc, n4) = ([0.0; 4], a.len().min(b.len()) / 4 * 4);
    for (x, y) in a[..n4].chunks_exact(4).zip(b[..n4].chunks_exact(4)) {
        for k in 0..4 {
            acc[k] += x[k] * y[k];
        }
    }
    let tail: f64 = a[n4..].iter().zip(&b[n4..]).map(|(x, y)| x * y).sum();
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}
