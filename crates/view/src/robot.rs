//! The robot the viewer shows: its multibody model (for forward kinematics) and the geometry
//! drawn on each body — the Lola-like biped's link boxes or a URDF's visual elements.

use crate::ViewError;
use biped_dynamics::Model;
use biped_robots::lola::{self, params::Locator, LolaType};
use nalgebra::Isometry3;
use serde::Serialize;
use std::collections::HashMap;
use std::path::PathBuf;

/// Where the robot comes from.
#[derive(Debug, Clone)]
pub enum RobotSource {
    /// The Lola-like biped of `crates/robots/data/lola.toml`.
    Lola(LolaType),
    /// A URDF file.
    Urdf {
        /// The file.
        path: PathBuf,
        /// Give the root link a free joint named `root`.
        floating: bool,
        /// Folders searched for `package://` URIs (before `ROS_PACKAGE_PATH`).
        package_path: Vec<PathBuf>,
    },
    /// A robot description file (`biped_robots::description`): its URDF, floating base and
    /// collision model.
    Description {
        /// The description file.
        file: PathBuf,
        /// Folders searched for `package://` URIs (before `$ROBOTS` and `ROS_PACKAGE_PATH`).
        package_path: Vec<PathBuf>,
    },
}

/// A pose as sent to the page: position and unit quaternion `[x, y, z, w]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PoseJson {
    /// Position in metres.
    pub position: [f64; 3],
    /// Orientation quaternion, `[x, y, z, w]`.
    pub quaternion: [f64; 4],
}

impl From<&Isometry3<f64>> for PoseJson {
    fn from(p: &Isometry3<f64>) -> Self {
        let q = p.rotation.quaternion();
        Self {
            position: p.translation.vector.into(),
            quaternion: [q.i, q.j, q.k, q.w],
        }
    }
}

/// The shape of one drawn element, lengths in metres (URDF conventions: cylinders and
/// capsules along z, boxes by their full edge lengths, all centred at the element's pose).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "lowercase")]
pub enum ShapeJson {
    /// A box.
    Box {
        /// Edge lengths.
        size: [f64; 3],
    },
    /// A cylinder along z.
    Cylinder {
        /// Radius.
        radius: f64,
        /// Length.
        length: f64,
    },
    /// A sphere.
    Sphere {
        /// Radius.
        radius: f64,
    },
    /// A capsule along z (length of the cylindrical part).
    Capsule {
        /// Radius.
        radius: f64,
        /// Length.
        length: f64,
    },
    /// A mesh file served at `url`, its vertices scaled per axis.
    Mesh {
        /// Where the page fetches the file (`/api/mesh/K`).
        url: String,
        /// File format from the extension: `stl`, `obj`, `dae` or `wrl` (VRML97).
        format: String,
        /// Scale per axis.
        scale: [f64; 3],
    },
}

/// One drawn element: its shape at a pose in the body frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GeometryJson {
    /// Pose in the body frame.
    pub pose: PoseJson,
    /// Shape.
    pub shape: ShapeJson,
}

/// One body of the scene (index = model body index), with what is drawn on it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyJson {
    /// Body name.
    pub name: String,
    /// Drawn elements.
    pub geometry: Vec<GeometryJson>,
}

/// The loaded robot.
#[derive(Debug, Clone)]
pub struct Robot {
    /// Multibody model.
    pub model: Model,
    /// Per model body, the drawn geometry.
    pub bodies: Vec<BodyJson>,
    /// Geometry welded to the world (a fixed-base URDF's root link), world frame.
    pub world: Vec<GeometryJson>,
    /// Mesh files by the index in their `/api/mesh/K` URL.
    pub meshes: Vec<PathBuf>,
    /// Named frames (model bodies and URDF links): the body (`None` = world) and the frame's
    /// pose in that body's frame.
    pub frames: HashMap<String, (Option<usize>, Isometry3<f64>)>,
    /// Label for the page's title, e.g. `Lola Type2` or the URDF path.
    pub label: String,
    /// Warnings to show the user (unresolvable meshes, ignored URDF tags).
    pub warnings: Vec<String>,
}

impl Robot {
    /// Loads the robot and its drawn geometry.
    pub fn load(source: &RobotSource) -> Result<Self, ViewError> {
        match source {
            RobotSource::Lola(variant) => lola_robot(*variant),
            RobotSource::Urdf {
                path,
                floating,
                package_path,
            } => crate::urdf::urdf_robot(path, *floating, package_path),
            RobotSource::Description { file, package_path } => {
                Ok(crate::description::load(file, package_path)?.0)
            }
        }
    }
}

pub(crate) fn empty_bodies(model: &Model) -> Vec<BodyJson> {
    let names = model.body_names();
    let bodies = names.iter().map(|n| BodyJson {
        name: n.to_string(),
        geometry: Vec::new(),
    });
    bodies.collect()
}

pub(crate) fn body_frames(model: &Model) -> HashMap<String, (Option<usize>, Isometry3<f64>)> {
    let names = model.body_names().into_iter().enumerate();
    let frames = names.map(|(i, n)| (n.to_string(), (Some(i), Isometry3::identity())));
    frames.collect()
}

/// Lola: one box per body of the parameter file, centred at its centre of mass.
fn lola_robot(variant: LolaType) -> Result<Robot, ViewError> {
    let built = lola::build(variant).map_err(|e| ViewError::Robot(e.to_string()))?;
    let loc = Locator {
        file: lola::LOLA_TOML_NAME,
        text: lola::LOLA_TOML,
    };
    let params = loc.parse().map_err(|e| ViewError::Robot(e.to_string()))?;
    let model = built.model;
    let mut bodies = empty_bodies(&model);
    for body in &params.body {
        let Some(id) = model.body_id(body.name.get_ref()) else {
            continue;
        };
        if body.size.iter().all(|&s| s > 0.0) {
            let pose = Isometry3::translation(body.com[0], body.com[1], body.com[2]);
            bodies[id].geometry.push(GeometryJson {
                pose: PoseJson::from(&pose),
                shape: ShapeJson::Box { size: body.size },
            });
        }
    }
    Ok(Robot {
        frames: body_frames(&model),
        model,
        bodies,
        world: Vec::new(),
        meshes: Vec::new(),
        label: format!("Lola {variant:?}"),
        warnings: Vec::new(),
    })
}
