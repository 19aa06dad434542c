//! URDF import (urdf-rs): a URDF kinematic tree becomes a [`Model`].
//!
//! Conventions:
//! - `revolute` and `continuous` joints become [`JointModel::Revolute`], `prismatic` ones
//!   [`JointModel::Prismatic`] (axis normalised; a zero axis is an error), `floating` ones
//!   [`JointModel::FreeQuaternion`]; `planar` and `spherical` joints are rejected.
//! - `fixed` joints are merged: the child link's inertia is added to the body it is welded to
//!   ([`RigidInertia::merged`]) and its frame is kept, so joints below it attach correctly.
//! - With [`UrdfOptions::floating`] the root link gets a `FreeQuaternion` joint named `"root"`
//!   attached to the world (q = `[x, y, z, qx, qy, qz, qw]`, v = body-frame `[linear; angular]`);
//!   otherwise the root link is welded to the world and its inertia does not matter.
//! - `<inertial>`: mass, CoM at the inertial origin `xyz`, and the tensor given about the CoM in
//!   the axes rotated by the inertial origin `rpy` (`R = Rz(yaw) Ry(pitch) Rx(roll)`).
//! - Rotational inertias with all entries below 1e-12 kg m^2 are taken as zero (with a warning).
//! - Joint limits and `<dynamics>` are read into [`UrdfModel::joints`] ([`JointProps`], see
//!   `joints` for their conventions); the model itself carries none of them.
//! - Meshes, visuals, collisions and transmissions are ignored by the import (the link geometry
//!   is read separately by [`read_geometry_file`], mesh files found by [`PackagePath`]); `<visual>`,
//!   `<collision>` and `<material>` elements are removed before parsing (see `scan`). `<mimic>` tags are
//!   ignored with a warning (the joints stay independent) unless [`UrdfOptions::reject_mimic`].
//! - The root element must be `<robot>`, link and joint names must not be empty, and elements
//!   may nest at most [`MAX_DEPTH`] levels (the text is checked in one pass before urdf-rs
//!   reads it, so no input makes the import recurse deeply or take more than linear time).
//! - Bodies and coordinates follow a depth-first traversal from the root, children in file order.
//!
//! The robot's SRDF adds what the URDF lacks for simulation ([`srdf`]): motor rotors and named
//! configurations.

mod error;
mod geometry;
mod joints;
mod lines;
mod markup;
mod package;
mod scan;
mod source;
pub mod srdf;
mod topology;
mod tree;

pub use error::{InvalidElement, Location, UrdfError};
pub use geometry::{read_geometry_file, read_geometry_str, GeometryElement, LinkGeometry, Shape};
pub use joints::JointProps;
pub use package::{PackagePath, ResolveError};
pub use scan::MAX_DEPTH;

use crate::{BodyId, Model};
#[cfg(doc)]
use crate::{JointModel, RigidInertia};
use nalgebra::Isometry3;
use std::path::Path;

/// Options of the URDF importer.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct UrdfOptions {
    /// Give the root link a free (quaternion) joint named `"root"` instead of welding it to the world.
    pub floating: bool,
    /// Treat `<mimic>` tags as errors instead of ignoring them with a warning.
    pub reject_mimic: bool,
}

/// Where a URDF link ended up: the body it belongs to and its pose in that body's frame.
#[derive(Debug, Clone)]
pub struct LinkFrame {
    /// URDF link name.
    pub link: String,
    /// Body the link is part of (`None` = welded to the world).
    pub body: Option<BodyId>,
    /// Pose of the link frame in the body frame (world frame if `body` is `None`).
    pub pose: Isometry3<f64>,
}

/// An imported URDF: the model, every link's frame, and warnings for the caller to show.
pub struct UrdfModel {
    /// The multibody model.
    pub model: Model,
    /// Every URDF link, in traversal order, with the body it was merged into.
    pub links: Vec<LinkFrame>,
    /// Limits and passive dynamics of every movable joint except the floating root, in body
    /// order.
    pub joints: Vec<JointProps>,
    /// Non-fatal issues (ignored `<mimic>` tags, negligible inertias), one line each, located.
    pub warnings: Vec<String>,
}

/// Reads and converts a URDF file.
///
/// # Example
///
/// The bundled Unitree G1 welded to the world at its pelvis: 29 revolute joints, each with
/// its `<limit>` kept in [`UrdfModel::joints`], and every link findable by name.
///
/// ```
/// use biped_dynamics::urdf::{load_file, UrdfOptions};
///
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/g1_29dof_rev_1_0.urdf");
/// let g1 = load_file(path, &UrdfOptions::default())?;
/// assert_eq!((g1.model.nq(), g1.model.nv()), (29, 29));
/// assert_eq!(g1.joints.len(), 29);
/// let knee = g1.joints.iter().find(|j| j.name == "left_knee_joint").unwrap();
/// // the file: <limit lower="-0.087267" upper="2.8798" effort="139" velocity="20"/>
/// assert_eq!(knee.range, Some([-0.087267, 2.8798]));
/// assert_eq!((knee.effort, knee.velocity), (Some(139.0), Some(20.0)));
/// let foot = g1.links.iter().find(|l| l.link == "left_ankle_roll_link").unwrap();
/// assert_eq!(g1.model.body(foot.body.unwrap()).unwrap().name(), "left_ankle_roll_link");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn load_file(path: impl AsRef<Path>, options: &UrdfOptions) -> Result<UrdfModel, UrdfError> {
    let path = path.as_ref();
    load_str(&read_file(path)?, &path.display().to_string(), options)
}

/// The text of a URDF file, with the errors of [`load_file`] (unreadable, not UTF-8).
pub fn read_file(path: impl AsRef<Path>) -> Result<String, UrdfError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    lines::read_text(path).map_err(|e| match e {
        lines::ReadError::Io(source) => UrdfError::Io {
            file: file.clone(),
            source,
        },
        lines::ReadError::NotUtf8 { line } => UrdfError::NotUtf8 { file, line },
    })
}

/// Converts URDF text; `file` labels the source in error messages.
pub fn load_str(xml: &str, file: &str, options: &UrdfOptions) -> Result<UrdfModel, UrdfError> {
    let scanned = scan::scan(xml).map_err(|e| match e {
        scan::ScanError::Malformed { line, problem } => UrdfError::Parse {
            file: file.to_string(),
            line: Some(line),
            message: lines::one_line(&problem),
        },
        scan::ScanError::TooDeep { line } => UrdfError::TooDeep {
            file: file.to_string(),
            line,
            limit: MAX_DEPTH,
        },
    })?;
    let src = source::Source {
        scanned: &scanned,
        file,
    };
    src.check_root()?;
    let robot = urdf_rs::read_from_string(&scanned.stripped).map_err(|e| UrdfError::Parse {
        file: file.to_string(),
        line: None,
        message: one_line(&e.to_string()),
    })?;
    tree::convert(&robot, &src, options)
}

/// Collapses a multi-line parser message into one line.
fn one_line(message: &str) -> String {
    message.split_whitespace().collect::<Vec<_>>().join(" ")
}
