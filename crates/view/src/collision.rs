//! The SSV collision-model file being viewed and edited: loaded with the same loader as
//! `biped ssv model` (`biped_ssv::format`), its bodies bound to frames of the robot, written
//! back as a whole only when the new text loads.

use crate::robot::{PoseJson, Robot};
use crate::source::SegmentSource;
use crate::source::{pair_list, pair_tables, segment_sources, PairListJson, PairTableJson};
use crate::ViewError;
use biped_ssv::format::{self, LoadedModel};
use biped_ssv::{PairDistance, Ssv};
use nalgebra::Isometry3;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Where a collision-model body sits on the robot.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Robot body (`None` = the world).
    pub body: Option<usize>,
    /// Pose of the collision-model body frame in that body's frame.
    pub offset: Isometry3<f64>,
}

/// A collision-model file, loaded and bound to the robot.
#[derive(Debug, Clone)]
pub struct CollisionFile {
    /// The file on disk.
    pub path: PathBuf,
    /// Its current text.
    pub text: String,
    /// The loaded model.
    pub loaded: LoadedModel,
    /// Per collision-model body, its frame on the robot.
    pub frames: Vec<Frame>,
    /// Why the file may not be written (a robot description's own model), if so: edits are
    /// checked, a save is refused with this message.
    pub read_only: Option<String>,
}

/// One SSV as sent to the page: kind, 1-3 points (body frame) and radius.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SsvJson {
    /// `point`, `line` or `triangle`.
    pub kind: &'static str,
    /// The vertices.
    pub points: Vec<[f64; 3]>,
    /// Radius in metres.
    pub radius: f64,
}

impl From<&Ssv> for SsvJson {
    fn from(ssv: &Ssv) -> Self {
        let p = |v: &nalgebra::Point3<f64>| [v.x, v.y, v.z];
        match ssv {
            Ssv::Point(s) => Self {
                kind: "point",
                points: vec![p(s.center())],
                radius: s.radius(),
            },
            Ssv::Line(s) => Self {
                kind: "line",
                points: s.vertices().iter().map(p).collect(),
                radius: s.radius(),
            },
            Ssv::Triangle(s) => Self {
                kind: "triangle",
                points: s.vertices().iter().map(p).collect(),
                radius: s.radius(),
            },
        }
    }
}

/// A collision-model body and where it sits on the robot.
#[derive(Debug, Clone, Serialize)]
pub struct FrameJson {
    /// Collision-model body name.
    pub name: String,
    /// Robot body index (`null` = world).
    pub body: Option<usize>,
    /// Pose in the robot body's frame.
    pub offset: PoseJson,
}

/// One segment: its SSVs as the model expands them, and how the file defines it.
#[derive(Debug, Clone, Serialize)]
pub struct SegmentJson {
    /// Segment name.
    pub name: String,
    /// Index into the model's `bodies`.
    pub body: usize,
    /// The expanded SSVs in the body frame.
    pub ssvs: Vec<SsvJson>,
    /// How the file defines the segment (entries editable when they are explicit).
    pub source: SegmentSource,
}

/// The collision model as the page draws and edits it.
#[derive(Debug, Clone, Serialize)]
pub struct ModelJson {
    /// File path.
    pub file: String,
    /// Activation distance `d_a` in metres.
    pub activation_distance: f64,
    /// Bodies with their robot frames.
    pub bodies: Vec<FrameJson>,
    /// Segments.
    pub segments: Vec<SegmentJson>,
    /// Pairs by segment name.
    pub pairs: Vec<[String; 2]>,
    /// The file's `pairs = [...]` array, which the page edits (`null` without one).
    pub pair_list: Option<PairListJson>,
    /// The file's `[[pair]]` tables, which the page edits too (`null` when a pair is written
    /// as neither).
    pub pair_tables: Option<Vec<PairTableJson>>,
    /// Why a save is refused (the model of a `--robot` description), or `null`.
    pub read_only: Option<String>,
}

/// One pair's distance at a posture.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairJson {
    /// First segment.
    pub a: String,
    /// Second segment.
    pub b: String,
    /// Signed distance in metres (`null` when beyond `d_a` and not computed).
    pub distance: Option<f64>,
    /// Closest point on `a` (world).
    pub point_a: Option<[f64; 3]>,
    /// Closest point on `b` (world).
    pub point_b: Option<[f64; 3]>,
}

impl CollisionFile {
    /// Loads `path` and binds its bodies to `robot`; errors are located (file, line, field).
    pub fn open(path: &Path, robot: &Robot) -> Result<Self, ViewError> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| ViewError::Ssv(format!("{}: cannot read file: {e}", path.display())))?;
        Self::from_text(path, text, robot)
    }

    /// Checks `text` as the new content of the file (nothing is written).
    pub fn from_text(path: &Path, text: String, robot: &Robot) -> Result<Self, ViewError> {
        let label = path.display().to_string();
        let loaded = format::parse_str(&text, &label).map_err(|e| ViewError::Ssv(e.to_string()))?;
        let frames = bind(&loaded, robot, &label, &text)?;
        Ok(Self {
            path: path.to_path_buf(),
            text,
            loaded,
            frames,
            read_only: None,
        })
    }

    /// Replaces the file by `text` if it loads and binds; the file is written as a whole
    /// (temporary sibling, then rename), and left as it was on any error.
    pub fn replace(&mut self, text: String, robot: &Robot) -> Result<(), ViewError> {
        if let Some(why) = &self.read_only {
            return Err(ViewError::ReadOnly(why.clone()));
        }
        let new = Self::from_text(&self.path, text, robot)?;
        biped_sim::record::write_whole(&self.path, |tmp| std::fs::write(tmp, &new.text))
            .map_err(|e| ViewError::Io(format!("{}: cannot write: {e}", self.path.display())))?;
        *self = new;
        Ok(())
    }

    /// The model for the page.
    pub fn to_json(&self) -> ModelJson {
        let model = &self.loaded.model;
        let sources = segment_sources(&self.text);
        let segments = model.segments().iter().zip(model.segment_bodies());
        let segments = segments.map(|(s, &body)| SegmentJson {
            name: s.name().to_string(),
            body,
            ssvs: s.ssvs().iter().map(SsvJson::from).collect(),
            source: sources
                .iter()
                .find(|(name, _)| name == s.name())
                .map_or(SegmentSource::Unknown, |(_, src)| src.clone()),
        });
        let names = model.segments();
        let pair = |p: &biped_ssv::SegmentPair| {
            [names[p.a].name().to_string(), names[p.b].name().to_string()]
        };
        let bodies = model.bodies().iter().zip(&self.frames);
        ModelJson {
            file: self.path.display().to_string(),
            activation_distance: model.activation_distance(),
            bodies: bodies
                .map(|(name, f)| FrameJson {
                    name: name.clone(),
                    body: f.body,
                    offset: PoseJson::from(&f.offset),
                })
                .collect(),
            segments: segments.collect(),
            pairs: model.pairs().iter().map(pair).collect(),
            pair_list: pair_list(&self.text),
            pair_tables: pair_tables(&self.text),
            read_only: self.read_only.clone(),
        }
    }

    /// Every pair's distance with the robot's bodies at `body_poses` (world).
    pub fn distances(&mut self, body_poses: &[Isometry3<f64>]) -> Result<Vec<PairJson>, ViewError> {
        let poses: Vec<Isometry3<f64>> = self
            .frames
            .iter()
            .map(|f| match f.body {
                Some(b) => body_poses[b] * f.offset,
                None => f.offset,
            })
            .collect();
        let model = &mut self.loaded.model;
        model
            .update(&poses)
            .map_err(|e| ViewError::Ssv(format!("{}: {e}", self.path.display())))?;
        let segments = model.segments();
        let rows = model.distances().map(|(pair, result)| {
            let closest = match result {
                PairDistance::Computed(c) => Some(c.result),
                PairDistance::Beyond => None,
            };
            PairJson {
                a: segments[pair.a].name().to_string(),
                b: segments[pair.b].name().to_string(),
                distance: closest.map(|r| r.distance),
                point_a: closest.map(|r| r.point_a.coords.into()),
                point_b: closest.map(|r| r.point_b.coords.into()),
            }
        });
        Ok(rows.collect())
    }
}

/// The robot frame of every collision-model body: a model body or URDF link of that name.
fn bind(
    loaded: &LoadedModel,
    robot: &Robot,
    label: &str,
    text: &str,
) -> Result<Vec<Frame>, ViewError> {
    let bodies = loaded.model.bodies().iter();
    let frame = |name: &String| match robot.frames.get(name) {
        Some(&(body, offset)) => Ok(Frame { body, offset }),
        None => {
            let quoted = format!("\"{name}\"");
            let line = text.find(&quoted).map_or(0, |at| line_of(text, at));
            Err(ViewError::Ssv(format!(
                "{label}:{line}: `bodies`: `{name}` is not a body or link of {}",
                robot.label
            )))
        }
    };
    bodies.map(frame).collect()
}

/// 1-based line of a byte offset.
pub(crate) fn line_of(text: &str, offset: usize) -> usize {
    text[..offset.min(text.len())].matches('\n').count() + 1
}
