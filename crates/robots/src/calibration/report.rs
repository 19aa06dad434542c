//! The calibration report: residuals per pose and closure errors per constraint before and
//! after calibration, and the check that everything reported is finite.

use super::jig::ClosureError;
use super::problem::{CalibrationProblem, Evaluation};
use super::solve::Calibration;
use super::CalibrationError;

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

/// [`CalibrationError::NonFiniteResult`] naming the first non-finite part of `cal`.
pub(crate) fn finite_result(cal: &Calibration) -> Result<(), CalibrationError> {
    let finite = |xs: &[f64]| xs.iter().all(|x| x.is_finite());
    let pose = |p: &PoseReport| {
        finite(&[p.rms_before, p.max_before, p.rms_after, p.max_after])
            && p.constraints.iter().all(|c| {
                finite(&[
                    c.position_before,
                    c.orientation_before,
                    c.position_after,
                    c.orientation_after,
                ])
            })
    };
    let parts = [
        ("offsets", finite(cal.offsets.as_slice())),
        ("std_errors", finite(cal.std_errors.as_slice())),
        ("singular_values", finite(&cal.singular_values)),
        ("rms_after", cal.rms_after.is_finite()),
        ("poses", cal.poses.iter().all(pose)),
    ];
    match parts.iter().find(|(_, ok)| !ok) {
        Some((what, _)) => Err(CalibrationError::NonFiniteResult(what)),
        None => Ok(()),
    }
}

/// RMS of a slice (0 for an empty one).
pub(crate) fn rms(r: &[f64]) -> f64 {
    if r.is_empty() {
        return 0.0;
    }
    (r.iter().map(|x| x * x).sum::<f64>() / r.len() as f64).sqrt()
}

/// Largest absolute entry.
fn max_abs(r: &[f64]) -> f64 {
    r.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// Per-pose, per-constraint report from the evaluations before and after, the weighted rows
/// multiplied by `weight` (the scale the solver divided out).
pub(crate) fn report(
    problem: &CalibrationProblem,
    before: &Evaluation,
    after: &Evaluation,
    weight: f64,
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
                rms_before: weight * rms(rb),
                max_before: weight * max_abs(rb),
                rms_after: weight * rms(ra),
                max_after: weight * max_abs(ra),
                constraints,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;

    /// Each non-finite part of a result is named; a finite result passes.
    #[test]
    fn non_finite_results_are_named() {
        let good = Calibration {
            offsets: DVector::from_element(2, 0.1),
            joints: vec!["a".into(), "b".into()],
            std_errors: DVector::from_element(2, 1e-3),
            singular_values: vec![2.0, 1.0],
            iterations: 3,
            rms_after: 1e-4,
            poses: vec![],
        };
        assert!(finite_result(&good).is_ok());
        let mut bad = good.clone();
        bad.std_errors[1] = f64::INFINITY;
        let e = finite_result(&bad).unwrap_err();
        assert!(
            matches!(e, CalibrationError::NonFiniteResult("std_errors")),
            "{e}"
        );
        let mut bad = good.clone();
        bad.offsets[0] = f64::NAN;
        let e = finite_result(&bad).unwrap_err();
        assert!(
            matches!(e, CalibrationError::NonFiniteResult("offsets")),
            "{e}"
        );
    }
}
