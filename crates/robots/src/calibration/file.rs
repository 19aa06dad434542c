//! The calibration file (JSON, [`super::spec`]): reading, the checks of its values, and the
//! calibration problem it describes; see the module documentation of [`super`] for the format.

use super::jig::{BodyFrame, Components, JigConstraint};
use super::limits;
use super::locate::{array_element, key_before, line_of, offset_of};
use super::problem::{CalibratedJoint, CalibrationProblem, JigPose};
use super::spec::{
    CalibrationFile, ComponentsSpec, ConstraintSpec, FrameSpec, PoseEntry, PoseSpec,
};
use super::CalibrationError;
use biped_dynamics::urdf::{self, UrdfModel, UrdfOptions};
use std::path::Path;

/// A parsed file with its source text (for error locations).
pub struct LoadedFile {
    /// File name as given.
    pub file: String,
    /// Source text.
    pub text: String,
    /// Parsed content.
    pub spec: CalibrationFile,
}

impl LoadedFile {
    /// Reads and parses a calibration file; errors name file, line and field.
    pub fn read(path: &Path) -> Result<Self, CalibrationError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| CalibrationError::File {
            file: file.clone(),
            line: 0,
            field: "-".into(),
            message: e.to_string(),
        })?;
        Self::parse(&file, text)
    }

    /// Parses calibration-file text (a leading byte-order mark is skipped) and checks its
    /// values: distinct names, numbers within their physical ranges ([`limits`]); `file`
    /// labels errors.
    pub fn parse(file: &str, text: String) -> Result<Self, CalibrationError> {
        let text = match text.strip_prefix('\u{feff}') {
            Some(rest) => rest.to_string(),
            None => text,
        };
        match serde_json::from_str::<CalibrationFile>(&text) {
            Ok(spec) => {
                let loaded = Self {
                    file: file.to_string(),
                    text,
                    spec,
                };
                loaded.check_values()?;
                Ok(loaded)
            }
            Err(e) => {
                let msg = e.to_string();
                let msg = msg.split(" at line ").next().unwrap_or(&msg).to_string();
                let field = key_before(&text, offset_of(&text, e.line(), e.column()))
                    .unwrap_or_else(|| "-".into());
                Err(CalibrationError::File {
                    file: file.to_string(),
                    line: e.line(),
                    field,
                    message: msg,
                })
            }
        }
    }

    /// A located error about the value `needle` in field `field`.
    pub fn error(&self, needle: &str, field: String, message: String) -> CalibrationError {
        self.error_after(0, needle, field, message)
    }

    /// A located error about `needle`, searched from byte `from` on (e.g. inside one pose).
    pub(crate) fn error_after(
        &self,
        from: usize,
        needle: &str,
        field: String,
        message: String,
    ) -> CalibrationError {
        CalibrationError::File {
            file: self.file.clone(),
            line: line_of(&self.text, needle, from),
            field,
            message,
        }
    }

    /// Loads the URDF (path relative to the file's directory).
    pub fn load_model(&self) -> Result<UrdfModel, CalibrationError> {
        let base = Path::new(&self.file).parent().unwrap_or(Path::new("."));
        let path = base.join(&self.spec.model.urdf);
        let opts = UrdfOptions {
            floating: self.spec.model.floating,
            reject_mimic: false,
        };
        urdf::load_file(&path, &opts).map_err(|e| {
            let urdf = self.spec.model.urdf.display().to_string();
            self.error(&urdf, "model.urdf".into(), e.to_string())
        })
    }

    /// Builds the calibration problem on an already loaded URDF model.
    pub fn problem(&self, urdf: &UrdfModel) -> Result<CalibrationProblem, CalibrationError> {
        let s = &self.spec;
        let model = &urdf.model;
        let joints = s
            .joints
            .iter()
            .enumerate()
            .map(|(i, name)| {
                let at = array_element(&self.text, "joints", i);
                CalibratedJoint::find(model, name)
                    .map_err(|e| self.error_after(at, name, format!("joints[{i}]"), e.to_string()))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let constraints = s
            .constraints
            .iter()
            .enumerate()
            .map(|(i, c)| self.constraint(urdf, i, c))
            .collect::<Result<Vec<_>, _>>()?;
        let poses = s
            .poses
            .iter()
            .enumerate()
            .map(|(i, p)| self.pose(model, i, p))
            .collect::<Result<Vec<_>, _>>()?;
        CalibrationProblem::new(model.clone(), joints, constraints, poses)
            .map_err(|e| self.error("poses", "-".into(), e.to_string()))
    }

    /// Resolves one frame (link + offset) to a body frame.
    fn frame(
        &self,
        urdf: &UrdfModel,
        f: &FrameSpec,
        field: String,
        at: usize,
    ) -> Result<BodyFrame, CalibrationError> {
        let link = urdf.links.iter().find(|l| l.link == f.link);
        let Some(link) = link else {
            return Err(self.error_after(
                at,
                &f.link,
                field,
                format!("no link `{}` in the URDF", f.link),
            ));
        };
        let off = PoseSpec {
            xyz: f.xyz,
            rpy: f.rpy,
        };
        Ok(BodyFrame {
            body: link.body,
            pose: link.pose * off.isometry(),
        })
    }

    /// Resolves constraint `i`.
    fn constraint(
        &self,
        urdf: &UrdfModel,
        i: usize,
        c: &ConstraintSpec,
    ) -> Result<JigConstraint, CalibrationError> {
        let at = array_element(&self.text, "constraints", i);
        Ok(JigConstraint {
            name: c.name.clone(),
            a: self.frame(
                urdf,
                &c.frame_a,
                format!("constraints[{i}].frame_a.link"),
                at,
            )?,
            b: self.frame(
                urdf,
                &c.frame_b,
                format!("constraints[{i}].frame_b.link"),
                at,
            )?,
            components: match c.components {
                ComponentsSpec::Pose => Components::Pose,
                ComponentsSpec::Position => Components::Position,
            },
            position_weight: c.position_weight,
            orientation_weight: c.orientation_weight,
        })
    }

    /// Resolves pose `i`: encoder readings (in range for their joint's kind) into `q`, targets
    /// by constraint name.
    fn pose(
        &self,
        model: &biped_dynamics::Model,
        i: usize,
        p: &PoseEntry,
    ) -> Result<JigPose, CalibrationError> {
        let at = array_element(&self.text, "poses", i);
        let err =
            |needle: &str, field: String, msg: String| self.error_after(at, needle, field, msg);
        let mut q = model.neutral();
        for (name, value) in &p.encoders {
            let field = format!("poses[{i}].encoders.{name}");
            let j = CalibratedJoint::find(model, name)
                .map_err(|e| err(name, field.clone(), e.to_string()))?;
            limits::reading(model, name)
                .check(*value)
                .map_err(|m| err(name, field, format!("encoder reading {m}")))?;
            q[j.q_index] = *value;
        }
        let mut targets = Vec::with_capacity(p.targets.len());
        for (name, t) in &p.targets {
            let field = format!("poses[{i}].targets.{name}");
            let c = self.spec.constraints.iter().position(|c| &c.name == name);
            let Some(c) = c else {
                return Err(err(name, field, format!("no constraint named `{name}`")));
            };
            targets.push((c, t.isometry()));
        }
        Ok(JigPose {
            name: p.name.clone(),
            q_measured: q,
            targets,
        })
    }
}
