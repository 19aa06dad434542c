//! The calibration file (JSON, serde): model, calibrated joints, jig constraints, measured
//! poses; see the module documentation of [`super`] for the format.

use super::jig::{BodyFrame, Components, JigConstraint};
use super::problem::{CalibratedJoint, CalibrationProblem, JigPose};
use super::CalibrationError;
use biped_dynamics::urdf::{self, UrdfModel, UrdfOptions};
use nalgebra::{Isometry3, Translation3, UnitQuaternion};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Model section: a URDF path (relative to the calibration file) and the floating-base flag.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelSpec {
    /// URDF file.
    pub urdf: PathBuf,
    /// Give the root a free joint.
    #[serde(default)]
    pub floating: bool,
}

/// A pose `xyz` \[m] + `rpy` \[rad] (`R = Rz(yaw) Ry(pitch) Rx(roll)`, as in URDF).
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PoseSpec {
    /// Translation.
    #[serde(default)]
    pub xyz: [f64; 3],
    /// Roll, pitch, yaw.
    #[serde(default)]
    pub rpy: [f64; 3],
}

impl PoseSpec {
    /// As an isometry.
    pub fn isometry(&self) -> Isometry3<f64> {
        let [r, p, y] = self.rpy;
        Isometry3::from_parts(
            Translation3::new(self.xyz[0], self.xyz[1], self.xyz[2]),
            UnitQuaternion::from_euler_angles(r, p, y),
        )
    }

    /// True if all numbers are finite.
    fn finite(&self) -> bool {
        self.xyz
            .iter()
            .chain(self.rpy.iter())
            .all(|x| x.is_finite())
    }
}

/// A frame: URDF link plus an optional offset pose in the link frame.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrameSpec {
    /// URDF link name.
    pub link: String,
    /// Offset in the link frame.
    #[serde(default)]
    pub xyz: [f64; 3],
    /// Offset rotation (roll, pitch, yaw).
    #[serde(default)]
    pub rpy: [f64; 3],
}

/// A jig constraint between two frames.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConstraintSpec {
    /// Unique name, referenced by the poses' `targets`.
    pub name: String,
    /// Reference frame.
    pub frame_a: FrameSpec,
    /// Constrained frame.
    pub frame_b: FrameSpec,
    /// `"pose"` (default) or `"position"`.
    #[serde(default)]
    pub components: ComponentsSpec,
    /// Weight of the position rows \[1/m] (default 1).
    #[serde(default = "one")]
    pub position_weight: f64,
    /// Weight of the orientation rows \[1/rad] (default 1).
    #[serde(default = "one")]
    pub orientation_weight: f64,
}

/// Serde form of [`Components`].
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ComponentsSpec {
    /// Position and orientation.
    #[default]
    Pose,
    /// Position only.
    Position,
}

/// One measured jig pose.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PoseEntry {
    /// Name.
    pub name: String,
    /// Encoder angle per joint \[rad or m]; unlisted joints keep the neutral value.
    pub encoders: BTreeMap<String, f64>,
    /// Target pose of `frame_b` in `frame_a` per active constraint name.
    pub targets: BTreeMap<String, PoseSpec>,
}

/// A whole calibration file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CalibrationFile {
    /// The model.
    pub model: ModelSpec,
    /// Joints whose offsets are estimated.
    pub joints: Vec<String>,
    /// Jig constraints.
    pub constraints: Vec<ConstraintSpec>,
    /// Measured poses.
    pub poses: Vec<PoseEntry>,
    /// Optional known offsets (synthetic data), compared against the estimate.
    #[serde(default)]
    pub reference_offsets: BTreeMap<String, f64>,
}

/// Default weight.
fn one() -> f64 {
    1.0
}

/// A parsed file with its source text (for error locations).
pub struct LoadedFile {
    /// File name as given.
    pub file: String,
    /// Source text.
    pub text: String,
    /// Parsed content.
    pub spec: CalibrationFile,
}

/// 1-based line and column -> byte offset.
fn offset_of(text: &str, line: usize, column: usize) -> usize {
    let start: usize = text
        .split_inclusive('\n')
        .take(line.saturating_sub(1))
        .map(str::len)
        .sum();
    (start + column.saturating_sub(1)).min(text.len())
}

/// The last JSON object key (`"key":`) that starts before byte `offset`, if it is a field
/// name of the format (letters, digits, `_`; a damaged file can put the quotes elsewhere).
fn key_before(text: &str, offset: usize) -> Option<String> {
    quoted_before(text, offset)
        .filter(|k| !k.is_empty() && k.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'))
}

/// The text between the last pair of quotes followed by `:` before byte `offset`.
fn quoted_before(text: &str, offset: usize) -> Option<String> {
    let head = &text[..offset.min(text.len())];
    let bytes = head.as_bytes();
    let mut i = head.len();
    while i > 0 {
        i -= 1;
        if bytes[i] != b':' {
            continue;
        }
        let before = head[..i].trim_end();
        if let Some(stripped) = before.strip_suffix('"') {
            if let Some(q) = stripped.rfind('"') {
                return Some(stripped[q + 1..].to_string());
            }
        }
    }
    None
}

/// 1-based line of the first occurrence of `"needle"` in `text` at or after byte `from`,
/// else of the first occurrence anywhere (0 if absent).
fn line_of(text: &str, needle: &str, from: usize) -> usize {
    let quoted = format!("\"{needle}\"");
    let from = from.min(text.len());
    text[from..]
        .find(&quoted)
        .map(|p| p + from)
        .or_else(|| text.find(&quoted))
        .map(|p| text[..p].matches('\n').count() + 1)
        .unwrap_or(0)
}

/// Byte offset of element `index` of the top-level array `"key": [...]` (0 if not found).
fn array_element(text: &str, key: &str, index: usize) -> usize {
    let quoted = format!("\"{key}\"");
    let Some(k) = text.find(&quoted) else {
        return 0;
    };
    let Some(open) = text[k..].find('[').map(|p| p + k) else {
        return 0;
    };
    let (mut depth, mut in_str, mut escaped, mut seen) = (0usize, false, false, 0usize);
    for (p, ch) in text[open..].char_indices() {
        if in_str {
            (escaped, in_str) = match (escaped, ch) {
                (true, _) => (false, true),
                (false, '\\') => (true, true),
                (false, '"') => (false, false),
                _ => (false, true),
            };
            continue;
        }
        match ch {
            '"' => in_str = true,
            '[' | '{' => {
                depth += 1;
                if depth == 2 {
                    if seen == index {
                        return open + p;
                    }
                    seen += 1;
                }
            }
            ']' | '}' => {
                depth = depth.saturating_sub(1);
                if depth == 0 {
                    return 0;
                }
            }
            _ => {}
        }
    }
    0
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

    /// Parses calibration-file text; `file` labels errors.
    pub fn parse(file: &str, text: String) -> Result<Self, CalibrationError> {
        match serde_json::from_str::<CalibrationFile>(&text) {
            Ok(spec) => Ok(Self {
                file: file.to_string(),
                text,
                spec,
            }),
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
    fn error_after(
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
                CalibratedJoint::find(model, name)
                    .map_err(|e| self.error(name, format!("joints[{i}]"), e.to_string()))
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
        if !off.finite() {
            return Err(self.error_after(at, &f.link, field, "non-finite offset".into()));
        }
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
        let dup = self
            .spec
            .constraints
            .iter()
            .filter(|o| o.name == c.name)
            .count()
            > 1;
        let w_ok = [c.position_weight, c.orientation_weight]
            .iter()
            .all(|w| w.is_finite() && *w >= 0.0);
        if dup || !w_ok {
            let why = if dup {
                "duplicate constraint name"
            } else {
                "weights must be finite and >= 0"
            };
            return Err(self.error(&c.name, format!("constraints[{i}]"), why.into()));
        }
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

    /// Resolves pose `i`: encoder readings into `q`, targets by constraint name.
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
            if !value.is_finite() {
                return Err(err(name, field, "non-finite encoder value".into()));
            }
            q[j.q_index] = *value;
        }
        let mut targets = Vec::with_capacity(p.targets.len());
        for (name, t) in &p.targets {
            let field = format!("poses[{i}].targets.{name}");
            let c = self.spec.constraints.iter().position(|c| &c.name == name);
            let Some(c) = c else {
                return Err(err(name, field, format!("no constraint named `{name}`")));
            };
            if !t.finite() {
                return Err(err(name, field, "non-finite target".into()));
            }
            targets.push((c, t.isometry()));
        }
        Ok(JigPose {
            name: p.name.clone(),
            q_measured: q,
            targets,
        })
    }
}
