//! SSV collision model of the Lola-like biped (thesis 5.2, 6.6-6.8): the shipped file
//! `data/lola_ssv.toml` (format of [`biped_ssv::format`]) bound to the body indices of a built
//! [`LolaModel`].
//!
//! The file names its bodies after the Lola model's bodies; [`lola_collision_model`] checks
//! that every body used by a segment exists in the model and returns, besides the
//! [`CollisionModel`], the model body index of every collision-model body
//! ([`LolaCollision::model_bodies`]), which is what the avoidance layer needs to feed poses and
//! Jacobians.

use super::LolaModel;
use biped_ssv::format::{self, FormatError};
use biped_ssv::CollisionModel;

/// The shipped collision-model file.
pub const LOLA_SSV_TOML: &str = include_str!("../../data/lola_ssv.toml");

/// Name of the shipped collision-model file in messages.
pub const LOLA_SSV_TOML_NAME: &str = "crates/robots/data/lola_ssv.toml";

/// What can be wrong with a Lola collision-model file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LolaCollisionError {
    /// The file itself is malformed (located: file, line, field).
    #[error(transparent)]
    Format(#[from] FormatError),
    /// A segment is attached to a body the Lola model does not have.
    #[error("{file}:{line}: segment `{segment}`: body `{body}` is not a body of the Lola model")]
    UnknownBody {
        /// File name.
        file: String,
        /// 1-based line of the segment's `body` entry (0 if not found in the text).
        line: usize,
        /// Segment name.
        segment: String,
        /// Body name.
        body: String,
    },
    /// A listed body that no segment uses and the Lola model does not have.
    #[error("{file}: `bodies`: `{body}` is not a body of the Lola model")]
    UnknownListedBody {
        /// File name.
        file: String,
        /// Body name.
        body: String,
    },
}

/// A collision model bound to a [`LolaModel`].
#[derive(Debug, Clone, PartialEq)]
pub struct LolaCollision {
    /// Segments, pairs and `d_a`; its body list is in the file's order.
    pub model: CollisionModel,
    /// For every collision-model body (same order), the index of that body in the Lola model.
    pub model_bodies: Vec<usize>,
}

/// The shipped collision model of the Lola-like robot bound to `lola`'s body indices.
///
/// # Example
///
/// Body poses come from the model's kinematics through [`LolaCollision::model_bodies`].
/// Distances between the robot's own parts do not change when the whole robot is moved.
///
/// ```
/// use biped_dynamics::{update_placements, Data};
/// use biped_robots::lola::{build, lola_collision_model, LolaType};
/// use nalgebra::{DVector, UnitQuaternion, Vector3};
///
/// let lola = build(LolaType::Type2)?;
/// let mut collision = lola_collision_model(&lola)?;
/// let mut data = Data::new(&lola.model);
/// let mut distances_at = |q: &DVector<f64>| -> Result<Vec<Option<f64>>, Box<dyn std::error::Error>> {
///     update_placements(&lola.model, &mut data, q)?;
///     let poses: Vec<_> = collision.model_bodies.iter().map(|&b| data.body_pose(b)).collect();
///     collision.model.update(&poses)?;
///     Ok(collision.model.results().iter().map(|r| r.distance()).collect())
/// };
/// let q = lola.model.neutral();
/// let here = distances_at(&q)?;
/// assert!(here.iter().flatten().all(|&d| d > 0.0)); // nothing touches at the neutral pose
///
/// let mut moved = q.clone(); // base shifted and turned about z
/// moved.fixed_rows_mut::<3>(0).copy_from(&Vector3::new(1.0, -2.0, 0.3));
/// let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.7);
/// moved.fixed_rows_mut::<4>(3).copy_from(&turn.coords);
/// for (a, b) in here.iter().zip(distances_at(&moved)?) {
///     assert_eq!(a.is_some(), b.is_some());
///     assert!((a.unwrap_or(0.0) - b.unwrap_or(0.0)).abs() < 1e-12);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn lola_collision_model(lola: &LolaModel) -> Result<LolaCollision, LolaCollisionError> {
    collision_model_from_str(LOLA_SSV_TOML, LOLA_SSV_TOML_NAME, lola)
}

/// Parses collision-model text (`file` labels errors) and binds it to `lola`'s bodies.
pub fn collision_model_from_str(
    text: &str,
    file: &str,
    lola: &LolaModel,
) -> Result<LolaCollision, LolaCollisionError> {
    let model = format::parse_str(text, file)?.model;
    let mut model_bodies = Vec::with_capacity(model.bodies().len());
    for (k, name) in model.bodies().iter().enumerate() {
        match lola.model.body_id(name) {
            Some(id) => model_bodies.push(id),
            None => return Err(unknown_body(&model, k, text, file)),
        }
    }
    Ok(LolaCollision {
        model,
        model_bodies,
    })
}

/// The error for collision body `k` missing in the Lola model: names the first segment on it.
fn unknown_body(model: &CollisionModel, k: usize, text: &str, file: &str) -> LolaCollisionError {
    let body = model.bodies()[k].clone();
    let segment = model
        .segment_bodies()
        .iter()
        .position(|&b| b == k)
        .map(|s| model.segments()[s].name().to_string());
    match segment {
        Some(segment) => LolaCollisionError::UnknownBody {
            file: file.to_string(),
            line: segment_body_line(text, &segment),
            segment,
            body,
        },
        None => LolaCollisionError::UnknownListedBody {
            file: file.to_string(),
            body,
        },
    }
}

/// 1-based line of the `body = ...` entry of segment `segment` (0 if not found): the first
/// `body` key after the line `name = "<segment>"`.
fn segment_body_line(text: &str, segment: &str) -> usize {
    let quoted = format!("\"{segment}\"");
    let mut lines = text.lines().enumerate().skip_while(|(_, l)| {
        let l = l.trim();
        !(l.starts_with("name") && l.contains(&quoted))
    });
    lines
        .find(|(_, l)| l.trim_start().starts_with("body"))
        .map_or(0, |(k, _)| k + 1)
}
