//! The closed-loop calibration problem: a model, the joints whose absolute-encoder offsets are
//! unknown, jig constraints and the measured jig poses (thesis 3.5).

use super::jig::{ClosureError, JigConstraint};
use super::limits::{first_repeat, LENGTH};
use super::CalibrationError;
use biped_dynamics::{Data, Jacobians, Model};
use nalgebra::{DMatrix, DVector, Isometry3};

/// A joint whose encoder offset is calibrated: name and its coordinate indices.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CalibratedJoint {
    /// Joint name.
    pub name: String,
    /// Index in `q`.
    pub q_index: usize,
    /// Index in `v` (column of the Jacobians).
    pub v_index: usize,
}

impl CalibratedJoint {
    /// Looks up a one-DoF (revolute or prismatic) joint of `model` by name.
    pub fn find(model: &Model, name: &str) -> Result<Self, CalibrationError> {
        model
            .joints()
            .iter()
            .find(|j| j.name == name && j.nq == 1 && j.nv == 1)
            .map(|j| Self {
                name: name.to_string(),
                q_index: j.q_index,
                v_index: j.v_index,
            })
            .ok_or_else(|| CalibrationError::UnknownJoint(name.to_string()))
    }
}

/// One jig pose: the measured configuration (encoder readings `q_meas = q_true - offset`) and
/// the targets of the constraints active in this pose.
#[derive(Debug, Clone, PartialEq)]
pub struct JigPose {
    /// Pose name (for reports).
    pub name: String,
    /// Measured configuration (full `q`; joints not read keep the model's neutral value).
    pub q_measured: DVector<f64>,
    /// Active constraints: index into the problem's constraints and target pose of `b` in `a`.
    pub targets: Vec<(usize, Isometry3<f64>)>,
}

/// A validated calibration problem.
#[derive(Debug, Clone)]
pub struct CalibrationProblem {
    pub(crate) model: Model,
    pub(crate) joints: Vec<CalibratedJoint>,
    pub(crate) constraints: Vec<JigConstraint>,
    pub(crate) poses: Vec<JigPose>,
}

/// Residual, Jacobian and per-constraint closure errors at one offset vector.
pub(crate) struct Evaluation {
    /// Stacked weighted residual.
    pub r: DVector<f64>,
    /// Its Jacobian w.r.t. the offsets (rows x unknowns).
    pub j: DMatrix<f64>,
    /// Closure errors, per pose, per active constraint.
    pub errors: Vec<Vec<ClosureError>>,
    /// Residual row range of each pose.
    pub pose_rows: Vec<std::ops::Range<usize>>,
}

/// One pose: a finite `q` of length `nq`, at least one active constraint of the
/// `nconstraints`, finite targets with positions within [`LENGTH`].
fn check_pose(p: &JigPose, nq: usize, nconstraints: usize) -> Result<(), CalibrationError> {
    let invalid = |what: String| CalibrationError::Invalid(format!("pose `{}`: {what}", p.name));
    if p.q_measured.len() != nq {
        let n = p.q_measured.len();
        return Err(invalid(format!("q has {n} entries, model nq = {nq}")));
    }
    if p.q_measured.iter().any(|x| !x.is_finite()) {
        return Err(CalibrationError::NonFinite(format!("pose `{}`", p.name)));
    }
    if p.targets.is_empty() {
        return Err(invalid("no jig constraint active".into()));
    }
    for (c, t) in &p.targets {
        if *c >= nconstraints {
            return Err(invalid(format!("constraint index {c} out of range")));
        }
        let v = t.translation.vector.iter().chain(t.rotation.coords.iter());
        if v.clone().any(|x| !x.is_finite()) {
            return Err(CalibrationError::NonFinite(format!(
                "pose `{}` target",
                p.name
            )));
        }
        for &x in t.translation.vector.iter() {
            LENGTH
                .check(x)
                .map_err(|m| invalid(format!("target position {m}")))?;
        }
    }
    Ok(())
}

impl CalibrationProblem {
    /// Validates and assembles a problem: non-empty, distinct joints, poses with finite data
    /// and target positions within [`LENGTH`], valid indices.
    pub fn new(
        model: Model,
        joints: Vec<CalibratedJoint>,
        constraints: Vec<JigConstraint>,
        poses: Vec<JigPose>,
    ) -> Result<Self, CalibrationError> {
        if joints.is_empty() {
            return Err(CalibrationError::Invalid("no joints to calibrate".into()));
        }
        if poses.is_empty() {
            return Err(CalibrationError::Invalid("no jig poses".into()));
        }
        if let Some((_, again)) = first_repeat(joints.iter().map(|j| j.name.as_str())) {
            return Err(CalibrationError::DuplicateJoint(joints[again].name.clone()));
        }
        for c in &constraints {
            let w = [c.position_weight, c.orientation_weight];
            if w.iter().any(|w| !w.is_finite() || *w < 0.0) {
                return Err(CalibrationError::Invalid(format!(
                    "constraint `{}`: weights must be finite and >= 0",
                    c.name
                )));
            }
            let bad = |b: Option<usize>| b.is_some_and(|b| b >= model.nbodies());
            if bad(c.a.body) || bad(c.b.body) {
                return Err(CalibrationError::Invalid(format!(
                    "constraint `{}`: body index out of range",
                    c.name
                )));
            }
        }
        for p in &poses {
            check_pose(p, model.nq(), constraints.len())?;
        }
        Ok(Self {
            model,
            joints,
            constraints,
            poses,
        })
    }

    /// The calibrated joints, in the order of the offset vector.
    pub fn joints(&self) -> &[CalibratedJoint] {
        &self.joints
    }

    /// The jig constraints.
    pub fn constraints(&self) -> &[JigConstraint] {
        &self.constraints
    }

    /// The jig poses.
    pub fn poses(&self) -> &[JigPose] {
        &self.poses
    }

    /// The model.
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// Total number of residual rows.
    pub fn rows(&self) -> usize {
        self.poses
            .iter()
            .flat_map(|p| p.targets.iter())
            .map(|(c, _)| self.constraints[*c].components.rows())
            .sum()
    }

    /// Configuration of pose `p` corrected by `offsets`: `q = q_meas + offset`.
    pub fn corrected(&self, p: usize, offsets: &DVector<f64>) -> DVector<f64> {
        let mut q = self.poses[p].q_measured.clone();
        for (j, x) in self.joints.iter().zip(offsets.iter()) {
            q[j.q_index] += x;
        }
        q
    }

    /// Stacked weighted residual and its analytic Jacobian at `offsets`.
    pub(crate) fn evaluate(&self, offsets: &DVector<f64>) -> Result<Evaluation, CalibrationError> {
        if offsets.iter().any(|x| !x.is_finite()) {
            return Err(CalibrationError::NonFinite("offsets".into()));
        }
        let (m, k, nv) = (self.rows(), self.joints.len(), self.model.nv());
        let mut ev = Evaluation {
            r: DVector::zeros(m),
            j: DMatrix::zeros(m, k),
            errors: Vec::with_capacity(self.poses.len()),
            pose_rows: Vec::with_capacity(self.poses.len()),
        };
        let mut data = Data::new(&self.model);
        let mut jac = Jacobians::new(&self.model);
        let (mut ja, mut jb) = (DMatrix::zeros(6, nv), DMatrix::zeros(6, nv));
        let mut row = 0;
        for (p, pose) in self.poses.iter().enumerate() {
            jac.compute(&self.model, &mut data, &self.corrected(p, offsets))?;
            let start = row;
            let mut errs = Vec::with_capacity(pose.targets.len());
            for (c, target) in &pose.targets {
                let con = &self.constraints[*c];
                let n = con.components.rows();
                let mut jr = DMatrix::zeros(n, nv);
                let r = &mut ev.r.as_mut_slice()[row..row + n];
                errs.push(con.residual(&jac, target, r, &mut jr, (&mut ja, &mut jb))?);
                for (col, joint) in self.joints.iter().enumerate() {
                    ev.j.view_mut((row, col), (n, 1))
                        .copy_from(&jr.column(joint.v_index));
                }
                row += n;
            }
            ev.errors.push(errs);
            ev.pose_rows.push(start..row);
        }
        Ok(ev)
    }

    /// Stacked weighted residual at `offsets` (for finite-difference checks).
    pub fn residual(&self, offsets: &DVector<f64>) -> Result<DVector<f64>, CalibrationError> {
        Ok(self.evaluate(offsets)?.r)
    }

    /// Stacked weighted residual and its analytic Jacobian w.r.t. the offsets.
    pub fn residual_jacobian(
        &self,
        offsets: &DVector<f64>,
    ) -> Result<(DVector<f64>, DMatrix<f64>), CalibrationError> {
        let ev = self.evaluate(offsets)?;
        Ok((ev.r, ev.j))
    }
}
