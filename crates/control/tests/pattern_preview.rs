//! ZMP preview servo: DARE solution, stability, optimality against a batch least-squares
//! solution and steady-state tracking.

use biped_control::pattern::dare::solve_dare;
use biped_control::pattern::preview::PreviewController;
use nalgebra::{DMatrix, DVector, Matrix4, Vector3, Vector4};

const H: f64 = 0.96;
const G: f64 = 9.81;

/// Independent DARE residual `Q + A^T P A - A^T P b (r + b^T P b)^-1 b^T P A - P`.
fn residual(c: &PreviewController) -> f64 {
    let (a, b, p) = (c.a_aug, c.b_aug, c.dare.p);
    let s = c.r + (b.transpose() * p * b)[0];
    let rhs = c.q_aug + a.transpose() * p * a - a.transpose() * p * b * b.transpose() * p * a / s;
    (rhs - p).abs().max() / p.abs().max()
}

/// The independent residual is below `tol` and the closed loop is stable.
fn assert_stabilising(c: &PreviewController, tol: f64, what: &str) {
    let res = residual(c);
    assert!(res < tol, "{what}: residual {res:e}");
    let rho = c
        .closed_loop()
        .complex_eigenvalues()
        .map(|z| z.norm())
        .max();
    assert!(rho < 1.0, "{what}: closed loop rho {rho}");
}

#[test]
fn dare_residual_vanishes_for_control_periods() {
    for dt in [0.001, 0.002, 0.005, 0.01, 0.02] {
        for (qe, qx, r) in [(1.0, 0.0, 1e-6), (1.0, 1e-3, 1e-5), (10.0, 0.0, 1e-8)] {
            let c = PreviewController::new(H, G, dt, (qe, qx, r), 10).unwrap();
            let res = residual(&c);
            assert!(
                res < 1e-10,
                "dt {dt} weights {qe} {qx} {r}: residual {res:e}"
            );
            assert!((c.dare.p - c.dare.p.transpose()).norm() == 0.0);
            assert!(
                c.dare.p.symmetric_eigenvalues().min() > 0.0,
                "P positive definite"
            );
        }
    }
}

/// Short periods with a small input weight, where the doubling alone drifts (P spans many
/// magnitudes; at 3 ms, r = 1e-6 its last iterate has an unstable closed loop): the solver
/// falls back to its best iterate and the Riccati recursion, and must still return the
/// stabilising solution with the independent residual below 1e-10.
#[test]
fn dare_is_solved_at_short_periods_with_small_input_weight() {
    for dt in [0.001, 0.0015, 0.002, 0.003, 0.005, 0.01] {
        for (qe, r) in [
            (1.0, 1e-7),
            (1.0, 1e-6),
            (10.0, 1e-6),
            (1.0, 1e-5),
            (100.0, 1e-5),
        ] {
            let c = PreviewController::new(H, G, dt, (qe, 0.0, r), 10)
                .unwrap_or_else(|e| panic!("dt {dt} qe {qe} r {r}: {e}"));
            assert_stabilising(&c, 1e-10, &format!("dt {dt} qe {qe} r {r}"));
        }
    }
}

/// Only the ZMP error weighted (`Q` singular) with small input weights: unbalanced, the
/// doubling overflowed at these settings and no fallback recovered (the first seven from a
/// 672-point grid in a baseline x86-64 build, the last four from random settings in this
/// workspace's FMA build; which settings fail depends on rounding); the balanced retry solves
/// each, and the independent residual and the closed loop check the result.
#[test]
fn dare_is_solved_with_singular_q_and_tiny_input_weight() {
    for (dt, qe, r) in [
        (0.0015, 1.0, 1e-10),
        (0.0015, 10.0, 1e-8),
        (0.0015, 100.0, 1e-9),
        (0.005, 10.0, 1e-10),
        (0.005, 100.0, 1e-8),
        (0.005, 100.0, 1e-7),
        (0.02, 1.0, 1e-10),
        (0.012447151732843723, 1.70006633303901, 1.968753254333172e-7),
        (
            0.0008140926002247266,
            0.267486238895668,
            7.569340360925962e-8,
        ),
        (
            0.00607299746365115,
            0.3480177336354832,
            2.3020855018355242e-8,
        ),
        (
            0.0036637531332310938,
            0.4092178931529138,
            4.573769696813325e-9,
        ),
    ] {
        let c = PreviewController::new(H, G, dt, (qe, 0.0, r), 10)
            .unwrap_or_else(|e| panic!("dt {dt} qe {qe} r {r}: {e}"));
        assert_stabilising(&c, 1e-10, &format!("dt {dt} qe {qe} r {r}"));
    }
}

#[test]
fn doubling_agrees_with_riccati_value_iteration() {
    let c = PreviewController::new(H, G, 0.01, (1.0, 0.0, 1e-6), 10).unwrap();
    let (a, b, q, r) = (c.a_aug, c.b_aug, c.q_aug, c.r);
    let mut p = q;
    for _ in 0..200_000 {
        let s = r + (b.transpose() * p * b)[0];
        p = q + a.transpose() * p * a - a.transpose() * p * b * b.transpose() * p * a / s;
    }
    let rel = (p - c.dare.p).norm() / p.norm();
    assert!(rel < 1e-8, "value iteration vs doubling: {rel:e}");
}

#[test]
fn unstabilisable_problem_is_an_error() {
    // b = 0: nothing can be controlled, the DARE has no stabilising solution.
    let a = Matrix4::identity() * 1.1;
    let r = solve_dare(&a, &Vector4::zeros(), &Matrix4::identity(), 1.0);
    assert!(r.is_err(), "{r:?}");
}

#[test]
fn closed_loop_decays_and_preview_gains_fade() {
    let c = PreviewController::new(H, G, 0.001, (1.0, 0.0, 1e-6), 1600).unwrap();
    assert!(c.spectral_radius() < 1.0);
    // Independent of the eigenvalue routine: powers of A_c go to zero.
    let mut m = Matrix4::<f64>::identity();
    for _ in 0..20_000 {
        m *= c.closed_loop();
    }
    assert!(m.norm() < 1e-6, "|A_c^20000| = {}", m.norm());
    let f = &c.preview;
    assert!(f[0] > 0.0);
    assert!(
        f[f.len() - 1].abs() < 0.02 * f[0],
        "preview gains fade over 1.6 s"
    );
}

#[test]
fn constant_reference_is_reached_without_steady_error() {
    let c = PreviewController::new(H, G, 0.005, (1.0, 0.0, 1e-6), 320).unwrap();
    let reference: Vec<f64> = (0..2000).map(|k| if k < 200 { 0.0 } else { 0.1 }).collect();
    let mut out = Vec::new();
    c.track(&reference, &Vector3::zeros(), &mut out);
    let last = out.last().unwrap();
    assert!((last[0] - 0.1).abs() < 1e-9 && last[1].abs() < 1e-9 && last[2].abs() < 1e-9);
}

/// Batch least squares over `dj` (jerk increments) of
/// `sum_k qe e_k^2 + sum_k r dj_k^2` for the cart-table model from rest.
fn batch_optimum(dt: f64, qe: f64, r: f64, reference: &[f64]) -> Vec<f64> {
    let n = reference.len();
    let simulate = |dj: &DVector<f64>| -> Vec<Vector3<f64>> {
        let c = PreviewController::new(H, G, dt, (qe, 0.0, r), 1).unwrap();
        let (mut x, mut u, mut xs) = (Vector3::zeros(), 0.0, Vec::with_capacity(n));
        for k in 0..n {
            xs.push(x);
            u += dj[k];
            x = c.a * x + c.b * u;
        }
        xs
    };
    let zmp = |x: &Vector3<f64>| x[0] - H / G * x[2];
    let base = simulate(&DVector::zeros(n));
    let mut phi = DMatrix::zeros(2 * n, n);
    let mut rhs = DVector::zeros(2 * n);
    for k in 0..n {
        rhs[k] = -qe.sqrt() * (zmp(&base[k]) - reference[k]);
    }
    for j in 0..n {
        let mut unit = DVector::zeros(n);
        unit[j] = 1.0;
        let xs = simulate(&unit);
        for k in 0..n {
            phi[(k, j)] = qe.sqrt() * zmp(&xs[k]);
        }
        phi[(n + j, j)] = r.sqrt();
    }
    let dj = phi.svd(true, true).solve(&rhs, 1e-14).unwrap();
    simulate(&dj).iter().map(|x| x[0]).collect()
}

#[test]
fn servo_equals_batch_least_squares_optimum() {
    // Coarse period so the dense problem stays small; the walk ends 4 s before the horizon so
    // the finite batch horizon approximates the infinite one.
    let (dt, qe, r) = (0.02, 1.0, 1e-4);
    let n = 400;
    let reference: Vec<f64> = (0..n)
        .map(|k| {
            let t = k as f64 * dt;
            if t < 1.0 {
                0.0
            } else if t < 2.0 {
                0.1
            } else if t < 3.0 {
                -0.05
            } else {
                0.2
            }
        })
        .collect();
    let c = PreviewController::new(H, G, dt, (qe, 0.0, r), n).unwrap();
    let mut out = Vec::new();
    c.track(&reference, &Vector3::zeros(), &mut out);
    let batch = batch_optimum(dt, qe, r, &reference);
    let err = out
        .iter()
        .zip(&batch)
        .map(|(x, b)| (x[0] - b).abs())
        .fold(0.0, f64::max);
    assert!(
        err < 1e-6,
        "servo vs batch optimum: max CoM difference {err:e}"
    );
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
    /// Any period of 0.5-20 ms and weights with `Q_e / r` up to 1e9 (`Q_x` zero or not): the
    /// servo is built and its `P` is the stabilising DARE solution (20000 random settings in
    /// this range all pass; 0.06 % fail without the balanced retry, more above 1e10).
    #[test]
    fn dare_is_solved_over_the_weight_range(
        dt in 5e-4f64..0.02,
        log_qe in -1.0f64..2.0,
        qx in proptest::prop_oneof![proptest::strategy::Just(0.0), 1e-6f64..1.0],
        log_ratio in 2.0f64..9.0,
    ) {
        let qe = 10f64.powf(log_qe);
        let r = qe / 10f64.powf(log_ratio);
        let c = PreviewController::new(H, G, dt, (qe, qx, r), 10)
            .unwrap_or_else(|e| panic!("dt {dt} qe {qe} qx {qx} r {r}: {e}"));
        // The solver accepts a relative Frobenius residual below 1e-9, which bounds this
        // max-entry one by 4e-9 for 4x4 matrices; the curated settings above reach 1e-10,
        // random ones need not (7.4e-10 at 3.2 ms, Q_e 6.4, r 2.7e-7 in the test profile).
        assert_stabilising(&c, 4e-9, &format!("dt {dt} qe {qe} qx {qx} r {r}"));
    }
}
