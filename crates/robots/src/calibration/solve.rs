//! Offset estimation by Levenberg-Marquardt least squares over all jig poses, with an
//! observability (rank) check and a per-pose residual report (thesis 3.5).

use super::problem::{CalibrationProblem, Evaluation};
use super::report::{finite_result, report, rms, PoseReport};
use super::CalibrationError;
use nalgebra::{DMatrix, DVector};

/// Solver settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveOptions {
    /// Iteration limit.
    pub max_iterations: usize,
    /// Relative singular-value threshold of the column-scaled Jacobian below which a direction
    /// counts as unobservable.
    pub rank_tolerance: f64,
    /// Stop when the step is below this (rad or m).
    pub step_tolerance: f64,
}

impl Default for SolveOptions {
    fn default() -> Self {
        Self {
            max_iterations: 100,
            rank_tolerance: 1e-6,
            step_tolerance: 1e-14,
        }
    }
}

/// Result of a calibration.
#[derive(Debug, Clone, PartialEq)]
pub struct Calibration {
    /// Estimated offsets `q_true = q_meas + offset`, in the problem's joint order.
    pub offsets: DVector<f64>,
    /// Joint names, same order.
    pub joints: Vec<String>,
    /// Standard errors of the offsets from the residual variance, `sqrt(s^2 (J^T J)^-1)_ii`
    /// (zero when there are no redundant rows).
    pub std_errors: DVector<f64>,
    /// Singular values of the column-scaled stacked Jacobian (descending).
    pub singular_values: Vec<f64>,
    /// Levenberg-Marquardt iterations.
    pub iterations: usize,
    /// RMS of all weighted residual rows after calibration.
    pub rms_after: f64,
    /// Per-pose report.
    pub poses: Vec<PoseReport>,
}

/// Column norms of `j`, computed without overflow (each column scaled by its largest entry
/// first): rows weighted by 1e300 have a finite norm.
fn column_norms(j: &DMatrix<f64>) -> Vec<f64> {
    j.column_iter()
        .map(|c| {
            let m = c.amax();
            if m == 0.0 || !m.is_finite() {
                m
            } else {
                m * (c / m).norm()
            }
        })
        .collect()
}

/// Observability check: errors with the joints spanning the (near) null space of the
/// column-scaled Jacobian; returns its singular values otherwise.
pub fn check_observability(
    problem: &CalibrationProblem,
    j: &DMatrix<f64>,
    tol: f64,
) -> Result<Vec<f64>, CalibrationError> {
    let names: Vec<String> = problem.joints().iter().map(|j| j.name.clone()).collect();
    let k = names.len();
    let norms = column_norms(j);
    let top = norms.iter().cloned().fold(0.0, f64::max);
    let dead: Vec<usize> = (0..k)
        .filter(|&i| norms[i].is_nan() || norms[i] <= tol * top.max(1e-300))
        .collect();
    if j.nrows() < k || !dead.is_empty() {
        // Upper bound of the rank: fewer rows than unknowns, or zero columns.
        let rank = (k - dead.len()).min(j.nrows());
        let list: Vec<usize> = if dead.is_empty() {
            (0..k).collect()
        } else {
            dead
        };
        return Err(CalibrationError::Unobservable {
            joints: list.iter().map(|&i| names[i].clone()).collect(),
            rank,
            unknowns: k,
        });
    }
    let mut scaled = j.clone();
    for (i, mut c) in scaled.column_iter_mut().enumerate() {
        // In two steps, so that a column norm near f64::MAX does not underflow the scaling.
        let m = c.amax();
        c /= m;
        c /= norms[i] / m;
    }
    let svd = scaled.svd(false, true);
    let v_t = svd
        .v_t
        .as_ref()
        .ok_or_else(|| CalibrationError::Invalid("SVD failed".into()))?;
    let smax = svd.singular_values.max();
    let mut involved = vec![false; k];
    let mut rank = 0;
    for (i, s) in svd.singular_values.iter().enumerate() {
        if *s > tol * smax {
            rank += 1;
        } else {
            for (c, inv) in involved.iter_mut().enumerate() {
                *inv |= v_t[(i, c)].abs() > 0.1;
            }
        }
    }
    if rank < k {
        return Err(CalibrationError::Unobservable {
            joints: (0..k)
                .filter(|&c| involved[c])
                .map(|c| names[c].clone())
                .collect(),
            rank,
            unknowns: k,
        });
    }
    let mut sv: Vec<f64> = svd.singular_values.iter().cloned().collect();
    sv.sort_by(|a, b| b.total_cmp(a));
    Ok(sv)
}

/// One damped Gauss-Newton step `(J^T J + lambda diag(J^T J)) d = -J^T r`.
fn lm_step(ev: &Evaluation, lambda: f64) -> Option<DVector<f64>> {
    let h = ev.j.tr_mul(&ev.j);
    let g = ev.j.tr_mul(&ev.r);
    let mut a = h.clone();
    for i in 0..a.nrows() {
        a[(i, i)] += lambda * h[(i, i)].max(1e-300);
    }
    a.cholesky().map(|c| -c.solve(&g))
}

/// Estimates the encoder offsets minimising the weighted jig-closure residual over all poses.
///
/// Solved on the problem with its weights divided by the largest one (the same minimiser, rows
/// of order one: weights of 1e300 neither overflow `J^T J` nor look unobservable); residuals
/// are reported in the given weights. A result that is not finite is an error, not a report.
pub fn calibrate(
    problem: &CalibrationProblem,
    options: &SolveOptions,
) -> Result<Calibration, CalibrationError> {
    let (scaled, weight) = normalised(problem);
    let before = scaled.evaluate(&DVector::zeros(problem.joints().len()))?;
    check_observability(&scaled, &before.j, options.rank_tolerance)?;
    let (x, ev, iterations) = levenberg_marquardt(&scaled, &before, options)?;
    let singular_values = check_observability(&scaled, &ev.j, options.rank_tolerance)?;
    let cal = Calibration {
        std_errors: std_errors(&ev),
        offsets: x,
        joints: problem.joints().iter().map(|j| j.name.clone()).collect(),
        singular_values,
        iterations,
        rms_after: weight * rms(ev.r.as_slice()),
        poses: report(&scaled, &before, &ev, weight),
    };
    finite_result(&cal)?;
    Ok(cal)
}

/// `problem` with its weights divided by the largest one, and that weight (1 if all are 0).
fn normalised(problem: &CalibrationProblem) -> (CalibrationProblem, f64) {
    let weights = problem.constraints().iter();
    let top = weights
        .flat_map(|c| [c.position_weight, c.orientation_weight])
        .fold(0.0, f64::max);
    let mut scaled = problem.clone();
    if top > 0.0 {
        for c in &mut scaled.constraints {
            c.position_weight /= top;
            c.orientation_weight /= top;
        }
    }
    (scaled, if top > 0.0 { top } else { 1.0 })
}

/// Levenberg-Marquardt from zero offsets (`start` is the evaluation there): the offsets, the
/// evaluation at them and the iterations, or [`CalibrationError::NoConvergence`].
fn levenberg_marquardt(
    problem: &CalibrationProblem,
    start: &Evaluation,
    options: &SolveOptions,
) -> Result<(DVector<f64>, Evaluation, usize), CalibrationError> {
    let mut x = DVector::zeros(problem.joints().len());
    let mut ev = problem.evaluate(&x)?;
    let mut cost = start.r.norm_squared();
    let mut lambda = 1e-6;
    let mut iterations = 0;
    let mut converged = false;
    while iterations < options.max_iterations && !converged {
        iterations += 1;
        let mut accepted = false;
        while lambda < 1e12 {
            let Some(d) = lm_step(&ev, lambda) else {
                lambda *= 10.0;
                continue;
            };
            let x_new = &x + &d;
            let ev_new = problem.evaluate(&x_new)?;
            let c_new = ev_new.r.norm_squared();
            if c_new <= cost {
                converged = d.amax() <= options.step_tolerance * (1.0 + x.amax()) || c_new == cost;
                (x, ev, cost, accepted) = (x_new, ev_new, c_new, true);
                lambda = (lambda * 0.1).max(1e-12);
                break;
            }
            lambda *= 10.0;
        }
        if !accepted {
            converged = true; // no descent possible: at a (numerical) minimum
        }
    }
    if !converged {
        return Err(CalibrationError::NoConvergence { iterations, cost });
    }
    Ok((x, ev, iterations))
}

/// `sqrt(s^2 (J^T J)^-1)_ii` with `s^2 = |r|^2 / (m - k)`.
fn std_errors(ev: &Evaluation) -> DVector<f64> {
    let (m, k) = ev.j.shape();
    let inv = ev.j.tr_mul(&ev.j).try_inverse();
    match inv {
        Some(inv) if m > k => {
            let s2 = ev.r.norm_squared() / (m - k) as f64;
            DVector::from_fn(k, |i, _| (s2 * inv[(i, i)]).max(0.0).sqrt())
        }
        _ => DVector::zeros(k),
    }
}
