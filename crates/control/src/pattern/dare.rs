//! Discrete algebraic Riccati equation (DARE) for a single-input system, solved by the
//! structure-preserving doubling algorithm (quadratic convergence):
//!
//! `P = Q + A^T P A - A^T P b (r + b^T P b)^-1 b^T P A`.
//!
//! With `G_0 = b r^-1 b^T`, `H_0 = Q`, `A_0 = A` and `W_k = E + G_k H_k`:
//! `A_{k+1} = A_k W_k^-1 A_k`, `G_{k+1} = G_k + A_k W_k^-1 G_k A_k^T`,
//! `H_{k+1} = H_k + A_k^T H_k W_k^-1 A_k`; `H_k -> P`. The result is accepted only if the
//! relative DARE residual is below `1e-9` and the closed loop is stable (the stabilising
//! solution; the DARE has others). The doubling result is polished by Newton-Kleinman
//! steps (Lyapunov solves) while the residual decreases: at the 1-5 ms periods of a walking
//! controller the doubling alone leaves relative residuals ~1e-5 (P spans many magnitudes).
//! There the doubling can also drift after its best iterate (3 ms, `r = 1e-6`: the last
//! iterate's closed loop is unstable); the solver then polishes the best iterate, and failing
//! that continues it by the Riccati recursion (monotone convergence) before polishing.

use super::PatternError;
use nalgebra::{DMatrix, DVector, SMatrix, SVector};

/// Stabilising solution of the DARE and how it was obtained.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DareSolution<const N: usize> {
    /// The solution `P` (symmetric).
    pub p: SMatrix<f64, N, N>,
    /// Relative residual `|Q + A^T P A - ... - P| / max(|P|, 1)` (Frobenius norms).
    pub residual: f64,
    /// Doublings performed.
    pub iterations: usize,
}

/// Relative residual of `p` in the DARE `(a, b, q, r)`.
pub fn dare_residual<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
    q: &SMatrix<f64, N, N>,
    r: f64,
    p: &SMatrix<f64, N, N>,
) -> f64 {
    (riccati_map(a, b, q, r, p) - p).norm() / p.norm().max(1.0)
}

/// The right-hand side `Q + A^T P A - A^T P b (r + b^T P b)^-1 b^T P A` (one step of the
/// Riccati recursion; its fixed points solve the DARE).
fn riccati_map<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
    q: &SMatrix<f64, N, N>,
    r: f64,
    p: &SMatrix<f64, N, N>,
) -> SMatrix<f64, N, N> {
    let pb = p * b;
    let s = r + b.dot(&pb);
    let bpa = pb.transpose() * a;
    q + a.transpose() * p * a - bpa.transpose() * bpa / s
}

/// Solves the DARE `(a, b, q, r)` by doubling; `q` symmetric positive semi-definite, `r > 0`.
pub fn solve_dare<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
    q: &SMatrix<f64, N, N>,
    r: f64,
) -> Result<DareSolution<N>, PatternError> {
    let (ends, iterations, last) = doubling(a, b, q, r)?;
    let report = (iterations, last);
    let [last_p, best_p] = ends;
    let first = accept(a, b, r, polish(a, b, q, r, last_p), report);
    if first.is_ok() {
        return first;
    }
    // The doubling can drift (ill-conditioned `I + G_k H_k` when P spans many magnitudes,
    // e.g. 3 ms with r = 1e-6, where the closed loop of its last iterate is unstable): polish
    // its best iterate instead, else continue that one by the Riccati recursion, which
    // converges monotonically to the stabilising solution.
    let second = accept(a, b, r, polish(a, b, q, r, best_p), report);
    if second.is_ok() {
        return second;
    }
    let p = value_iteration(a, b, q, r, best_p);
    accept(a, b, r, polish(a, b, q, r, p), report).or(first)
}

/// Doubling iterations: the last iterate and the one with the smallest DARE residual (later
/// ones can drift away again), the doublings done and the last relative change.
fn doubling<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
    q: &SMatrix<f64, N, N>,
    r: f64,
) -> Result<([SMatrix<f64, N, N>; 2], usize, f64), PatternError> {
    const MAX_DOUBLINGS: usize = 80;
    let eye = SMatrix::<f64, N, N>::identity();
    let (mut ak, mut gk, mut hk) = (*a, b * b.transpose() / r, *q);
    let mut iterations = 0;
    let mut last = f64::INFINITY;
    let mut best = (dare_residual(a, b, q, r, q), *q);
    while iterations < MAX_DOUBLINGS {
        iterations += 1;
        let w_inv = (eye + gk * hk).try_inverse().ok_or(PatternError::Riccati {
            residual: f64::INFINITY,
            iterations,
        })?;
        let a_next = ak * w_inv * ak;
        let g_next = gk + ak * w_inv * gk * ak.transpose();
        let h_next = hk + ak.transpose() * hk * w_inv * ak;
        let change = (h_next - hk).norm() / h_next.norm().max(1.0);
        if !change.is_finite() || !a_next.norm().is_finite() || !g_next.norm().is_finite() {
            break;
        }
        (ak, gk, hk) = (a_next, g_next, h_next);
        last = change;
        let p = 0.5 * (hk + hk.transpose());
        let res = dare_residual(a, b, q, r, &p);
        if res < best.0 {
            best = (res, p);
        }
        if change < 1e-15 {
            break;
        }
    }
    Ok(([0.5 * (hk + hk.transpose()), best.1], iterations, last))
}

/// Riccati recursion `P <- riccati_map(P)` from `p` (at most 2^18 steps, setup time only):
/// the iterate with the smallest residual, checked every 64 steps, stopping below `1e-12`.
fn value_iteration<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
    q: &SMatrix<f64, N, N>,
    r: f64,
    mut p: SMatrix<f64, N, N>,
) -> SMatrix<f64, N, N> {
    let mut best = (dare_residual(a, b, q, r, &p), p);
    for _ in 0..4096 {
        for _ in 0..64 {
            let m = riccati_map(a, b, q, r, &p);
            p = 0.5 * (m + m.transpose());
        }
        let res = dare_residual(a, b, q, r, &p);
        if !res.is_finite() {
            break;
        }
        if res < best.0 {
            best = (res, p);
        }
        if res < 1e-12 {
            break;
        }
    }
    best.1
}

/// Newton-Kleinman steps from `p` while the residual decreases: the result and its residual.
fn polish<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
    q: &SMatrix<f64, N, N>,
    r: f64,
    mut p: SMatrix<f64, N, N>,
) -> (SMatrix<f64, N, N>, f64) {
    const NEWTON_STEPS: usize = 8;
    let mut residual = dare_residual(a, b, q, r, &p);
    for _ in 0..NEWTON_STEPS {
        let Some(next) = newton_step(a, b, q, r, &p) else {
            break;
        };
        let res = dare_residual(a, b, q, r, &next);
        if res.partial_cmp(&residual) != Some(std::cmp::Ordering::Less) {
            break;
        }
        (p, residual) = (next, res);
    }
    (p, residual)
}

/// The solution if its residual is below `1e-9` and its closed loop is stable, else the error
/// (`(iterations, last change)` of the doubling for the report).
fn accept<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
    r: f64,
    (p, residual): (SMatrix<f64, N, N>, f64),
    (iterations, last): (usize, f64),
) -> Result<DareSolution<N>, PatternError> {
    if !(residual.is_finite() && residual < 1e-9) {
        return Err(PatternError::Riccati {
            residual: if residual.is_finite() { residual } else { last },
            iterations,
        });
    }
    let decay = closed_loop_decay(a, b, r, &p);
    if decay.is_nan() || decay >= 1e-6 {
        return Err(PatternError::Unstable {
            spectral_radius: decay,
        });
    }
    Ok(DareSolution {
        p,
        residual,
        iterations,
    })
}

/// One Newton-Kleinman step from `p`: with `K = (r + b^T P b)^-1 b^T P A` and
/// `A_c = A - b K`, solves the Lyapunov equation `P' = A_c^T P' A_c + Q + K^T r K`
/// (dense Kronecker form; setup-time only).
fn newton_step<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
    q: &SMatrix<f64, N, N>,
    r: f64,
    p: &SMatrix<f64, N, N>,
) -> Option<SMatrix<f64, N, N>> {
    let pb = p * b;
    let k = pb.transpose() * a / (r + b.dot(&pb));
    let ac = a - b * k;
    let rhs = q + k.transpose() * k * r;
    let act = DMatrix::from_column_slice(N, N, ac.transpose().as_slice());
    let lhs = DMatrix::identity(N * N, N * N) - act.kronecker(&act);
    let sol = lhs
        .lu()
        .solve(&DVector::from_column_slice(rhs.as_slice()))?;
    let next = SMatrix::<f64, N, N>::from_column_slice(sol.as_slice());
    Some(0.5 * (next + next.transpose()))
}

/// `|A_c^(2^40)|` for the closed loop of `p`, by repeated squaring: ~0 iff `A_c` is stable,
/// i.e. iff `p` is the stabilising solution (the DARE also has non-stabilising ones).
fn closed_loop_decay<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
    r: f64,
    p: &SMatrix<f64, N, N>,
) -> f64 {
    let pb = p * b;
    let mut m = a - b * (pb.transpose() * a) / (r + b.dot(&pb));
    for _ in 0..40 {
        m = m * m;
        let norm = m.norm();
        if !norm.is_finite() || norm > 1e100 {
            return f64::INFINITY;
        }
    }
    m.norm()
}
