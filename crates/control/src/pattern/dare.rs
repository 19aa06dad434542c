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
//! that continues it by the Riccati recursion (monotone convergence) before polishing. If all
//! of that fails, the same is done once more in balanced coordinates (a diagonal change of
//! state that makes every entry of `b` +-1), the result checked on the original problem.

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
    Dare { a, b, q, r }.residual(p)
}

/// Solves the DARE `(a, b, q, r)` by doubling; `q` symmetric positive semi-definite, `r > 0`.
///
/// If that fails, solved again in balanced coordinates (`Balancing`), whose solution is
/// mapped back, polished and accepted on the original problem. On a grid of 2000 preview-servo
/// settings (periods 0.2-50 ms, `Q_e` 0.1-1e4, `Q_x` 0-1, `r` 1e-12-1) this solves 1994
/// against 1982 without balancing in this workspace's FMA build (1975 in a baseline x86-64
/// build; balanced alone 1955): which settings fail depends on rounding, and the six left
/// have `Q_e / r` of 1e11-1e16.
pub fn solve_dare<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
    q: &SMatrix<f64, N, N>,
    r: f64,
) -> Result<DareSolution<N>, PatternError> {
    let dare = Dare { a, b, q, r };
    dare.solve()
        .or_else(|e| solve_balanced(&dare).map_err(|_| e))
}

/// [`Dare::solve`] in balanced coordinates, the solution mapped back, polished and accepted
/// on `dare` itself.
fn solve_balanced<const N: usize>(dare: &Dare<'_, N>) -> Result<DareSolution<N>, PatternError> {
    let balancing = Balancing::of(dare);
    let (sa, sb, sq, sr) = balancing.scaled(dare);
    let scaled = Dare {
        a: &sa,
        b: &sb,
        q: &sq,
        r: sr,
    };
    let s = scaled.solve()?;
    let report = (s.iterations, 0.0);
    dare.accept(dare.polish(balancing.unscaled(&s.p)), report)
}

/// Diagonal change of state `x = T x'` with `T_k = |b_k|` (so every entry of `b' = T^-1 b`
/// is +-1) and a cost scale `c`: the balanced DARE `(T^-1 A T, T^-1 b, T Q T / c, r / c)` has
/// the solution `P' = T P T / c`. For the cart-table servo at 1-20 ms the state entries span
/// `dt^3` to 1, and unbalanced the doubling can overflow at small `r` (`Q` singular).
struct Balancing<const N: usize> {
    /// Diagonal of `T`.
    t: SVector<f64, N>,
    /// Cost scale `c = max(|T Q T|, r)`.
    c: f64,
}

impl<const N: usize> Balancing<N> {
    /// The scaling of `dare` (`T_k = max |b|` where `b_k = 0`, the identity if `b = 0`).
    fn of(dare: &Dare<'_, N>) -> Self {
        let fill = dare.b.amax();
        let fill = if fill > 0.0 && fill.is_finite() {
            fill
        } else {
            1.0
        };
        let t = dare.b.map(|x| if x != 0.0 { x.abs() } else { fill });
        let tqt = dare.q.component_mul(&(t * t.transpose()));
        let c = tqt.amax().max(dare.r);
        let c = if c > 0.0 && c.is_finite() { c } else { 1.0 };
        Self { t, c }
    }

    /// The balanced problem `(A', b', Q', r')`.
    fn scaled(&self, dare: &Dare<'_, N>) -> (Mat<N>, SVector<f64, N>, Mat<N>, f64) {
        let t = &self.t;
        let a = Mat::<N>::from_fn(|i, j| dare.a[(i, j)] * t[j] / t[i]);
        let b = dare.b.component_div(t);
        let q = dare.q.component_mul(&(t * t.transpose())) / self.c;
        (a, b, q, dare.r / self.c)
    }

    /// `P = c T^-1 P' T^-1` from the balanced solution `P'`.
    fn unscaled(&self, p: &Mat<N>) -> Mat<N> {
        let t = &self.t;
        Mat::<N>::from_fn(|i, j| self.c * p[(i, j)] / (t[i] * t[j]))
    }
}

/// Square matrix of the state dimension.
type Mat<const N: usize> = SMatrix<f64, N, N>;

/// One DARE `P = Q + A^T P A - A^T P b (r + b^T P b)^-1 b^T P A`.
struct Dare<'a, const N: usize> {
    a: &'a Mat<N>,
    b: &'a SVector<f64, N>,
    q: &'a Mat<N>,
    r: f64,
}

impl<const N: usize> Dare<'_, N> {
    /// Doubling, polished; if its last iterate fails, its best iterate, then that one
    /// continued by the Riccati recursion.
    fn solve(&self) -> Result<DareSolution<N>, PatternError> {
        let ([last_p, best_p], iterations, last) = self.doubling()?;
        let report = (iterations, last);
        let first = self.accept(self.polish(last_p), report);
        if first.is_ok() {
            return first;
        }
        // The doubling can drift (ill-conditioned `I + G_k H_k` when P spans many magnitudes,
        // e.g. 3 ms with r = 1e-6, where the closed loop of its last iterate is unstable):
        // polish its best iterate instead, else continue that one by the Riccati recursion,
        // which converges monotonically to the stabilising solution.
        let second = self.accept(self.polish(best_p), report);
        if second.is_ok() {
            return second;
        }
        let p = self.value_iteration(best_p);
        self.accept(self.polish(p), report).or(first)
    }

    /// The right-hand side `Q + A^T P A - A^T P b (r + b^T P b)^-1 b^T P A` (one step of the
    /// Riccati recursion; its fixed points solve the DARE).
    fn map(&self, p: &Mat<N>) -> Mat<N> {
        let (a, b) = (self.a, self.b);
        let pb = p * b;
        let s = self.r + b.dot(&pb);
        let bpa = pb.transpose() * a;
        self.q + a.transpose() * p * a - bpa.transpose() * bpa / s
    }

    /// Relative residual `|map(P) - P| / max(|P|, 1)`.
    fn residual(&self, p: &Mat<N>) -> f64 {
        (self.map(p) - p).norm() / p.norm().max(1.0)
    }

    /// State feedback `K = (r + b^T P b)^-1 b^T P A` of `p`.
    fn gain(&self, p: &Mat<N>) -> SMatrix<f64, 1, N> {
        let pb = p * self.b;
        pb.transpose() * self.a / (self.r + self.b.dot(&pb))
    }

    /// Doubling iterations: the last iterate and the one with the smallest DARE residual
    /// (later ones can drift away again), the doublings done and the last relative change.
    fn doubling(&self) -> Result<([Mat<N>; 2], usize, f64), PatternError> {
        const MAX_DOUBLINGS: usize = 80;
        let eye = Mat::<N>::identity();
        let (mut ak, mut gk, mut hk) = (*self.a, self.b * self.b.transpose() / self.r, *self.q);
        let mut iterations = 0;
        let mut last = f64::INFINITY;
        let mut best = (self.residual(self.q), *self.q);
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
            let res = self.residual(&p);
            if res < best.0 {
                best = (res, p);
            }
            if change < 1e-15 {
                break;
            }
        }
        Ok(([0.5 * (hk + hk.transpose()), best.1], iterations, last))
    }

    /// Riccati recursion `P <- map(P)` from `p` (at most 2^18 steps, setup time only): the
    /// iterate with the smallest residual, checked every 64 steps, stopping below `1e-12`.
    fn value_iteration(&self, mut p: Mat<N>) -> Mat<N> {
        let mut best = (self.residual(&p), p);
        for _ in 0..4096 {
            for _ in 0..64 {
                let m = self.map(&p);
                p = 0.5 * (m + m.transpose());
            }
            let res = self.residual(&p);
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

    /// Newton-Kleinman steps from `p` while the residual decreases: the result and its
    /// residual.
    fn polish(&self, mut p: Mat<N>) -> (Mat<N>, f64) {
        const NEWTON_STEPS: usize = 8;
        let mut residual = self.residual(&p);
        for _ in 0..NEWTON_STEPS {
            let Some(next) = self.newton_step(&p) else {
                break;
            };
            let res = self.residual(&next);
            if res.partial_cmp(&residual) != Some(std::cmp::Ordering::Less) {
                break;
            }
            (p, residual) = (next, res);
        }
        (p, residual)
    }

    /// One Newton-Kleinman step from `p`: with the gain `K` and `A_c = A - b K` of `p`, solves
    /// the Lyapunov equation `P' = A_c^T P' A_c + Q + K^T r K` (dense Kronecker form;
    /// setup-time only).
    fn newton_step(&self, p: &Mat<N>) -> Option<Mat<N>> {
        let k = self.gain(p);
        let ac = self.a - self.b * k;
        let rhs = self.q + k.transpose() * k * self.r;
        let act = DMatrix::from_column_slice(N, N, ac.transpose().as_slice());
        let lhs = DMatrix::identity(N * N, N * N) - act.kronecker(&act);
        let sol = lhs
            .lu()
            .solve(&DVector::from_column_slice(rhs.as_slice()))?;
        let next = Mat::<N>::from_column_slice(sol.as_slice());
        Some(0.5 * (next + next.transpose()))
    }

    /// The solution if its residual is below `1e-9` and its closed loop is stable, else the
    /// error (`(iterations, last change)` of the doubling for the report).
    fn accept(
        &self,
        (p, residual): (Mat<N>, f64),
        (iterations, last): (usize, f64),
    ) -> Result<DareSolution<N>, PatternError> {
        if !(residual.is_finite() && residual < 1e-9) {
            return Err(PatternError::Riccati {
                residual: if residual.is_finite() { residual } else { last },
                iterations,
            });
        }
        let decay = self.closed_loop_decay(&p);
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

    /// `|A_c^(2^40)|` for the closed loop of `p`, by repeated squaring: ~0 iff `A_c` is
    /// stable, i.e. iff `p` is the stabilising solution (the DARE also has non-stabilising
    /// ones).
    fn closed_loop_decay(&self, p: &Mat<N>) -> f64 {
        let mut m = self.a - self.b * self.gain(p);
        for _ in 0..40 {
            m = m * m;
            let norm = m.norm();
            if !norm.is_finite() || norm > 1e100 {
                return f64::INFINITY;
            }
        }
        m.norm()
    }
}

#[cfg(test)]
mod tests;
