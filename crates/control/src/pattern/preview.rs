//! ZMP preview control of the cart-table model (linear inverted pendulum, constant height).
//!
//! Per horizontal axis the state `x = (c, c_dot, c_ddot)` is driven by the jerk `u`:
//! `x_{k+1} = A x_k + b u_k` with `A = [[1, T, T^2/2], [0, 1, T], [0, 0, 1]]`,
//! `b = (T^3/6, T^2/2, T)`, and the ZMP is `p = C x = c - h/g c_ddot`.
//! The LQ servo with integral action works on the incremental system
//! `X_k = (e_k, x_k - x_{k-1})`, `e_k = p_k - p_ref,k`, `du_k = u_k - u_{k-1}`:
//! `X_{k+1} = A~ X_k + b~ du_k - i~ (p_ref,k+1 - p_ref,k)` with
//! `A~ = [[1, C A], [0, A]]`, `b~ = (C b, b)`, `i~ = (1, 0, 0, 0)`, minimising
//! `sum Q_e e^2 + dx^T Q_x dx + R du^2`. With the DARE solution `P`,
//! `m = R + b~^T P b~`, `K = b~^T P A~ / m` and `A_c = A~ - b~ K`, the optimal increment with
//! known future reference is (derived from the quadratic-plus-linear value function)
//!
//! `du_k = -K X_k + sum_{j=1}^{N} f_j (p_ref,k+j - p_ref,k+j-1)`,
//! `f_j = b~^T (A_c^T)^{j-1} P i~ / m`,
//!
//! which is the incremental form of the classical preview servo (integral gain `f_1`). The
//! reference is held at its last value beyond its end.

use super::dare::{solve_dare, DareSolution};
use super::PatternError;
use nalgebra::{Matrix3, Matrix4, RowVector3, RowVector4, Vector3, Vector4};

/// Preview servo for one axis of the cart-table model.
#[derive(Debug, Clone)]
pub struct PreviewController {
    /// Cart-table state matrix `A`.
    pub a: Matrix3<f64>,
    /// Input (jerk) vector `b`.
    pub b: Vector3<f64>,
    /// ZMP output row `C = (1, 0, -h/g)`.
    pub c: RowVector3<f64>,
    /// Augmented state matrix `A~`.
    pub a_aug: Matrix4<f64>,
    /// Augmented input vector `b~`.
    pub b_aug: Vector4<f64>,
    /// Augmented weight `diag(Q_e, Q_x, Q_x, Q_x)`.
    pub q_aug: Matrix4<f64>,
    /// Input weight `R`.
    pub r: f64,
    /// DARE solution for `(A~, b~, Q, R)`.
    pub dare: DareSolution<4>,
    /// State feedback `K` on `X = (e, dx)`.
    pub gain: RowVector4<f64>,
    /// Preview gains `f_1 .. f_N`.
    pub preview: Vec<f64>,
}

impl PreviewController {
    /// Builds the servo for CoM height `h`, gravity `g`, period `dt`, weights and `horizon`
    /// preview samples; fails if the DARE fails or the closed loop is unstable.
    pub fn new(
        h: f64,
        g: f64,
        dt: f64,
        weights: (f64, f64, f64),
        horizon: usize,
    ) -> Result<Self, PatternError> {
        let (qe, qx, r) = weights;
        let a = Matrix3::new(1.0, dt, 0.5 * dt * dt, 0.0, 1.0, dt, 0.0, 0.0, 1.0);
        let b = Vector3::new(dt * dt * dt / 6.0, 0.5 * dt * dt, dt);
        let c = RowVector3::new(1.0, 0.0, -h / g);
        let mut a_aug = Matrix4::identity();
        a_aug.fixed_view_mut::<1, 3>(0, 1).copy_from(&(c * a));
        a_aug.fixed_view_mut::<3, 3>(1, 1).copy_from(&a);
        let mut b_aug = Vector4::zeros();
        b_aug[0] = (c * b)[0];
        b_aug.fixed_rows_mut::<3>(1).copy_from(&b);
        let q_aug = Matrix4::from_diagonal(&Vector4::new(qe, qx, qx, qx));
        let dare = solve_dare(&a_aug, &b_aug, &q_aug, r)?;
        let p = dare.p;
        let m = r + b_aug.dot(&(p * b_aug));
        let gain = (b_aug.transpose() * p * a_aug) / m;
        let ac_t = (a_aug - b_aug * gain).transpose();
        let mut v: Vector4<f64> = p.column(0).into();
        let mut preview = Vec::with_capacity(horizon);
        for _ in 0..horizon {
            preview.push(b_aug.dot(&v) / m);
            v = ac_t * v;
        }
        let ctrl = Self {
            a,
            b,
            c,
            a_aug,
            b_aug,
            q_aug,
            r,
            dare,
            gain,
            preview,
        };
        let spectral_radius = ctrl.spectral_radius();
        if spectral_radius.is_finite() && spectral_radius < 1.0 {
            Ok(ctrl)
        } else {
            Err(PatternError::Unstable { spectral_radius })
        }
    }

    /// Closed-loop matrix `A_c = A~ - b~ K`.
    pub fn closed_loop(&self) -> Matrix4<f64> {
        self.a_aug - self.b_aug * self.gain
    }

    /// Largest eigenvalue modulus of `A_c` (< 1: asymptotically stable).
    pub fn spectral_radius(&self) -> f64 {
        self.closed_loop()
            .complex_eigenvalues()
            .iter()
            .map(|z| z.norm())
            .fold(0.0, f64::max)
    }

    /// Runs the servo from rest at `x0` along `reference` (one value per sample) and writes the
    /// state `x_k = (c, c_dot, c_ddot)` of every sample into `out` (cleared first).
    pub fn track(&self, reference: &[f64], x0: &Vector3<f64>, out: &mut Vec<Vector3<f64>>) {
        out.clear();
        let n = reference.len();
        // Reference increments dr_i = r_i - r_{i-1}; zero beyond the end (reference held).
        let mut dr = Vec::with_capacity(n);
        dr.push(0.0);
        dr.extend(reference.windows(2).map(|w| w[1] - w[0]));
        let runs = nonzero_runs(&dr);
        let (mut x, mut x_prev, mut u) = (*x0, *x0, 0.0);
        for (k, r_k) in reference.iter().enumerate() {
            out.push(x);
            let e = (self.c * x)[0] - r_k;
            let dx = x - x_prev;
            let feedback = self.gain[0] * e + (self.gain.fixed_columns::<3>(1) * dx)[0];
            // sum_j f_j dr_{k+j} over the preview window [k + 1, k + N], nonzero runs only.
            let (lo, hi) = (k + 1, (k + self.preview.len()).min(n - 1) + 1);
            let mut future = 0.0;
            for &(a, b) in runs.iter().skip_while(|r| r.1 <= lo) {
                if a >= hi {
                    break;
                }
                let (a, b) = (a.max(lo), b.min(hi));
                future += dot(&self.preview[a - lo..b - lo], &dr[a..b]);
            }
            u += future - feedback;
            x_prev = x;
            x = self.a * x + self.b * u;
        }
    }
}

/// Maximal index ranges `[a, b)` of nonzero entries.
fn nonzero_runs(v: &[f64]) -> Vec<(usize, usize)> {
    let mut runs = Vec::new();
    let mut start = None;
    for (i, &x) in v.iter().enumerate() {
        match (x != 0.0, start) {
            (true, None) => start = Some(i),
            (false, Some(a)) => {
                runs.push((a, i));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(a) = start {
        runs.push((a, v.len()));
    }
    runs
}

/// Dot product with four independent accumulators (lets the compiler vectorise).
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let mut acc = [0.0; 4];
    let (ca, cb) = (a.chunks_exact(4), b.chunks_exact(4));
    let tail: f64 = ca
        .remainder()
        .iter()
        .zip(cb.remainder())
        .map(|(x, y)| x * y)
        .sum();
    for (x, y) in ca.zip(cb) {
        for i in 0..4 {
            acc[i] += x[i] * y[i];
        }
    }
    acc.iter().sum::<f64>() + tail
}
