//! Collision-model files (TOML): bodies, SSV segments, mirrored segments, segment versions,
//! segment pairs, the activation distance and optional named postures (thesis 6.6-6.8).
//!
//! # Format
//!
//! * `activation_distance` — `d_a` in metres (6.7), finite and >= 0.
//! * `bodies` — body names; [`CollisionModel::update`] takes one pose per body in this order.
//! * `[[segment]]` — `name`, `body` and exactly one geometry source:
//!   * `ssvs = [...]` with entries `{ point = [x,y,z], radius = r }`,
//!     `{ line = [[..],[..]], radius = r }` or `{ triangle = [[..],[..],[..]], radius = r }`
//!     in the body frame; `mirror_copy = "xy" | "yz" | "xz"` on an entry also adds its mirror
//!     image right after it (symmetry inside a segment, 6.6.2);
//!   * `mirror_of = "name"` with `plane = "xy" | "yz" | "xz"`: the whole segment mirrored in
//!     its body frame (the opposite-side version, 6.6.1);
//!   * `version_of = "name"` with `keep = [indices]`: a reduced version holding a subset of
//!     the SSVs (index order of the expanded list), e.g. an inner and an outer thigh (6.8).
//!
//!   `mirror_of` and `version_of` may only refer to segments defined above them.
//! * `pairs = [["seg_a", "seg_b"], ...]` and/or `[[pair]]` tables with keys `a`, `b`.
//! * `[pose.<name>]` — optional postures, one `body = { position = [..], rpy = [..] }` per
//!   body (metres; roll-pitch-yaw in radians, extrinsic x-y-z; `rpy` defaults to zero).
//!
//! Every error ([`FormatError`]) names the file, the 1-based line and the field, for syntax
//! errors and for semantic ones (unknown names, negative radius, non-finite values, ...).
//!
//! # Example
//!
//! This complete file is parsed by the test suite (`tests/model_format.rs`):
//!
//! ```toml
//! # d_a in metres: pairs whose OBBs, enlarged by d_a/2, do not overlap are "beyond d_a".
//! activation_distance = 0.05
//! # Poses are passed to CollisionModel::update in this order.
//! bodies = ["pelvis", "thigh_r", "thigh_l", "hand_r"]
//! # Pairs by segment name (alternatively [[pair]] tables with keys a and b).
//! pairs = [["thigh_r_inner", "thigh_l_inner"], ["hand_r", "thigh_r_outer"], ["hand_r", "pelvis"]]
//!
//! [[segment]]
//! name = "pelvis"
//! body = "pelvis"
//! ssvs = [
//!   { triangle = [[0.08, -0.1, 0.0], [0.08, 0.1, 0.0], [-0.08, 0.0, 0.0]], radius = 0.05 },
//! ]
//!
//! [[segment]]
//! name = "thigh_r"
//! body = "thigh_r"
//! ssvs = [
//!   { line = [[0.0, 0.0, 0.0], [0.0, 0.0, -0.4]], radius = 0.06 },       # index 0
//!   { point = [0.0, 0.05, -0.2], radius = 0.05, mirror_copy = "xz" },    # indices 1 and 2
//! ]
//!
//! # Versions (6.8): the inner side faces the other leg, the outer side the arm.
//! [[segment]]
//! name = "thigh_r_inner"
//! body = "thigh_r"
//! version_of = "thigh_r"
//! keep = [0, 1]
//!
//! [[segment]]
//! name = "thigh_r_outer"
//! body = "thigh_r"
//! version_of = "thigh_r"
//! keep = [0, 2]
//!
//! # The left thigh: the right one mirrored about its body frame's xz plane (6.6.1).
//! [[segment]]
//! name = "thigh_l_inner"
//! body = "thigh_l"
//! mirror_of = "thigh_r_inner"
//! plane = "xz"
//!
//! [[segment]]
//! name = "hand_r"
//! body = "hand_r"
//! ssvs = [{ line = [[0.0, 0.0, 0.0], [0.0, 0.0, -0.15]], radius = 0.04 }]
//!
//! [pose.standing]
//! pelvis = { position = [0.0, 0.0, 1.0] }
//! thigh_r = { position = [0.0, -0.1, 0.95] }
//! thigh_l = { position = [0.0, 0.1, 0.95] }
//! hand_r = { position = [0.0, -0.25, 0.8], rpy = [0.1, 0.0, 0.0] }
//! ```

mod build;
mod error;
mod exact;
mod raw;
mod write;

pub use error::{line_of, FormatError, FormatErrorKind};

use crate::model::CollisionModel;
use error::Locator;
use nalgebra::Isometry3;
use std::collections::BTreeMap;
use std::path::Path;

/// A loaded model file: the collision model and its named postures (body poses in order).
#[derive(Debug, Clone, PartialEq)]
pub struct LoadedModel {
    /// The collision model.
    pub model: CollisionModel,
    /// Named postures from `[pose.<name>]`, one pose per body.
    pub poses: BTreeMap<String, Vec<Isometry3<f64>>>,
}

/// Loads a model file; errors name the file, line and field.
///
/// # Example
///
/// The bundled humanoid model: one segment per `[[segment]]` table, a pose per body in each
/// named posture, and every pair at a non-negative distance when standing.
///
/// ```
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/humanoid.toml");
/// let mut loaded = biped_ssv::format::load(path)?;
/// let text = std::fs::read_to_string(path)?;
/// assert_eq!(loaded.model.segments().len(), text.matches("[[segment]]").count());
/// let standing = &loaded.poses["standing"];
/// assert_eq!(standing.len(), loaded.model.bodies().len());
/// loaded.model.update(standing)?;
/// let (_, closest) = loaded.model.min_distance().unwrap();
/// assert!(closest.result.distance >= 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn load(path: impl AsRef<Path>) -> Result<LoadedModel, FormatError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| FormatError {
        file: file.clone(),
        line: 0,
        field: String::new(),
        kind: FormatErrorKind::Io(e.to_string()),
    })?;
    parse_bytes(&bytes, &file)
}

/// Parses model-file bytes; `file` labels errors.
pub fn parse_bytes(bytes: &[u8], file: &str) -> Result<LoadedModel, FormatError> {
    match std::str::from_utf8(bytes) {
        Ok(text) => parse_str(text, file),
        Err(e) => {
            let valid = &bytes[..e.valid_up_to()];
            Err(FormatError {
                file: file.to_string(),
                line: 1 + valid.iter().filter(|&&b| b == b'\n').count(),
                field: String::new(),
                kind: FormatErrorKind::NotUtf8,
            })
        }
    }
}

/// Parses model-file text; `file` labels errors.
pub fn parse_str(text: &str, file: &str) -> Result<LoadedModel, FormatError> {
    let loc = Locator { file, text };
    let raw: raw::RawFile = toml::from_str(text).map_err(|e| loc.toml(e))?;
    build::build(raw, &loc)
}

/// The model and postures as TOML text with explicit SSVs for every segment.
pub fn to_toml_string(
    model: &CollisionModel,
    poses: &BTreeMap<String, Vec<Isometry3<f64>>>,
) -> Result<String, FormatError> {
    toml::to_string(&write::raw_file(model, poses)).map_err(|e| FormatError {
        file: String::new(),
        line: 0,
        field: String::new(),
        kind: FormatErrorKind::Write(e.to_string()),
    })
}

/// Writes the model and postures to a file (see [`to_toml_string`]).
pub fn save(
    path: impl AsRef<Path>,
    model: &CollisionModel,
    poses: &BTreeMap<String, Vec<Isometry3<f64>>>,
) -> Result<(), FormatError> {
    let path = path.as_ref();
    let text = to_toml_string(model, poses)?;
    std::fs::write(path, text).map_err(|e| FormatError {
        file: path.display().to_string(),
        line: 0,
        field: String::new(),
        kind: FormatErrorKind::Io(e.to_string()),
    })
}
