//! Offset estimation by Levenberg-Marquardt least squares over all jig poses, with an
//! observability (rank) check and a per-pose residual report (thesis 3.5).

use super::jig::ClosureError;
use super::problem::{CalibrationProblem, Evaluation};
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

/// Closure errors of one constraint in one pose, before and after calibration.
#[derive(Debug, Clone, PartialEq)]
pub struct ConstraintReport {
    /// Constraint name.
    pub name: String,
    /// Position error norm before \[m].
    pub position_before: f64,
    /// Orientation error angle before \[rad].
    pub orientation_before: f64,
    /// Position error norm after \[m].
    pub position_after: f64,
    /// Orientation error angle after \[rad].
    pub orientation_after: f64,
}

/// Weighted residual statistics of one pose before and after calibration.
#[derive(Debug, Clone, PartialEq)]
pub struct PoseReport {
    /// Pose name.
    pub name: String,
    /// RMS of the weighted residual rows before.
    pub rms_before: f64,
    /// Largest absolute weighted residual row before.
    pub max_before: f64,
    /// RMS after.
    pub rms_after: f64,
    /// Largest absolute row after.
    pub max_after: f64,
    /// Per-constraint closure errors.
    pub constraints: Vec<ConstraintReport>,
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

/// Column norms of `j`.
fn column_norms(j: &DMatrix<f64>) -> Vec<f64> {
    j.column_iter().map(|c| c.norm()).collect()
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
        c /= norms[i];
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
pub fn calibrate(
    problem: &CalibrationProblem,
    options: &SolveOptions,
) -> Result<Calibration, CalibrationError> {
    let k = problem.joints().len();
    let mut x = DVector::zeros(k);
    let before = problem.evaluate(&x)?;
    check_observability(problem, &before.j, options.rank_tolerance)?;
    let mut ev = problem.evaluate(&x)?;
    let mut cost = ev.r.norm_squared();
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
    let singular_values = check_observability(problem, &ev.j, options.rank_tolerance)?;
    Ok(Calibration {
        std_errors: std_errors(&ev),
        offsets: x,
        joints: problem.joints().iter().map(|j| j.name.clone()).collect(),
        singular_values,
        iterations,
        rms_after: rms(ev.r.as_slice()),
        poses: report(problem, &before, &ev),
    })
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

/// RMS of a slice (0 for an empty one).
fn rms(r: &[f64]) -> f64 {
    if r.is_empty() {
        return 0.0;
    }
    (r.iter().map(|x| x * x).sum::<f64>() / r.len() as f64).sqrt()
}

/// Largest absolute entry.
fn max_abs(r: &[f64]) -> f64 {
    r.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// Per-pose, per-constraint report from the evaluations before and after.
fn report(
    problem: &CalibrationProblem,
    before: &Evaluation,
    after: &Evaluation,
) -> Vec<PoseReport> {
    let pair = |e: &ClosureError| (e.position.norm(), e.orientation.norm());
    problem
        .poses()
        .iter()
        .enumerate()
        .map(|(p, pose)| {
            let rb = &before.r.as_slice()[before.pose_rows[p].clone()];
            let ra = &after.r.as_slice()[after.pose_rows[p].clone()];
            let constraints = pose
                .targets
                .iter()
                .enumerate()
                .map(|(i, (c, _))| {
                    let (pb, ob) = pair(&before.errors[p][i]);
                    let (pa, oa) = pair(&after.errors[p][i]);
                    ConstraintReport {
                        name: problem.constraints()[*c].name.clone(),
                        position_before: pb,
                        orientation_before: ob,
                        position_after: pa,
                        orientation_after: oa,
                    }
                })
                .collect();
            PoseReport {
                name: pose.name.clone(),
                rms_before: rms(rb),
                max_before: max_abs(rb),
                rms_after: rms(ra),
                max_after: max_abs(ra),
                constraints,
            }
        })
        .collect()
}
