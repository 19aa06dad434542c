//! Robot description files (TOML): what turns a URDF humanoid into a walking robot — its URDF,
//! feet and soles, limb joint groups, the momentum-producing and -reducing DoFs (thesis 7.3.2),
//! a comfort pose, the SSV collision model and the drive data. The format, with a complete
//! example, is documented in `docs/robot_description.md`; the bundled descriptions are
//! `data/g1.toml` (the Unitree G1 of `biped_dynamics`) and `data/talos.toml` (TALOS from
//! example-robot-data, found at run time, see [`search_path`]).
//!
//! [`Robot::load`] reads a file, resolves the files it refers to (relative to the description's
//! folder, or `package://PKG/...` through [`search_path`]), loads the URDF, SRDF and SSV model,
//! and checks every name against them. Every error names the file, the line and the field
//! ([`DescriptionError`]).
//!
//! # Example
//!
//! ```
//! use biped_robots::description::Robot;
//!
//! let g1 = Robot::load(Robot::bundled("g1").unwrap())?;
//! assert_eq!(g1.urdf.model.nv(), 6 + 29);
//! assert_eq!(g1.description.feet[0].frame, "left_ankle_roll_link");
//! let collision = g1.collision.as_ref().unwrap();
//! assert_eq!(collision.model.segments().len(), 30);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod bind;
mod check;
mod collision;
mod error;
mod raw;

pub use error::{DescriptionError, ReferencedError};

use biped_dynamics::urdf::srdf::Srdf;
use biped_dynamics::urdf::{JointProps, PackagePath, UrdfModel};
use biped_ssv::CollisionModel;
use nalgebra::{DVector, Vector3};
use std::path::{Path, PathBuf};

/// One foot: its frame (a URDF link), the sole rectangle in it and the optional toe joint.
#[derive(Debug, Clone, PartialEq)]
pub struct Foot {
    /// URDF link of the foot (or sole) frame.
    pub frame: String,
    /// Centre of the sole rectangle in the frame \[m].
    pub sole_center: Vector3<f64>,
    /// Sole length (frame x) and width (frame y) \[m].
    pub sole_size: [f64; 2],
    /// Toe joint, if the foot has one.
    pub toe_joint: Option<String>,
}

/// The description file's content with its paths resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotDescription {
    /// The description file (for messages).
    pub file: String,
    /// Robot name.
    pub name: String,
    /// The URDF file.
    pub urdf: PathBuf,
    /// Whether the root link gets a free joint (a walking robot: true).
    pub floating: bool,
    /// Left and right foot.
    pub feet: [Foot; 2],
    /// Joints of the left and right leg (hip to ankle).
    pub legs: [Vec<String>; 2],
    /// Joints of the left and right arm (shoulder to wrist).
    pub arms: [Vec<String>; 2],
    /// Momentum-reducing joints `q_r` (7.3.2), e.g. the arms' flexion joints.
    pub reducing: Vec<String>,
    /// Momentum-producing joints `q_p` (the base is always producing); all joints not in
    /// `reducing` unless listed.
    pub producing: Vec<String>,
    /// SRDF `<group_state>` the comfort pose starts from.
    pub comfort_state: Option<String>,
    /// Comfort-pose joint values given in the file \[rad or m].
    pub comfort_joints: Vec<(String, f64)>,
    /// The SSV collision-model file.
    pub collision_model: Option<PathBuf>,
    /// Segment pairs to check (`None`: those of the collision-model file).
    pub collision_pairs: Option<Vec<[String; 2]>>,
    /// Pairs of those not to check.
    pub collision_exclude: Vec<[String; 2]>,
    /// The SRDF file (motor rotors, named states).
    pub srdf: Option<PathBuf>,
    /// Reflected rotor inertia `N^2 J` \[kg m^2] by joint-name pattern (`*` = any run of
    /// characters), in file order: the first matching entry wins.
    pub armature: Vec<(String, f64)>,
}

/// The SSV collision model bound to the robot's bodies.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotCollision {
    /// Segments, pairs and `d_a`.
    pub model: CollisionModel,
    /// For every collision-model body (same order), the model body (`None`: welded to the world).
    pub model_bodies: Vec<Option<usize>>,
}

/// A loaded robot: description, URDF model, SRDF, collision model and comfort pose.
pub struct Robot {
    /// The description.
    pub description: RobotDescription,
    /// The URDF model (with joint limits).
    pub urdf: UrdfModel,
    /// The SRDF, if the description names one.
    pub srdf: Option<Srdf>,
    /// The collision model, if the description names one.
    pub collision: Option<RobotCollision>,
    /// The comfort pose: a configuration of the model (base at the origin for a floating base).
    pub comfort: DVector<f64>,
}

/// Folders `package://PKG/...` references are looked up in: `explicit`, then the environment
/// variable `ROBOTS` (the robots folder of example-robot-data, which
/// `scripts/fetch_robots.sh` exports), then the entries of `ROS_PACKAGE_PATH`.
pub fn search_path(explicit: Vec<PathBuf>) -> PackagePath {
    let mut dirs = explicit;
    if let Some(robots) = std::env::var_os("ROBOTS").filter(|r| !r.is_empty()) {
        dirs.push(PathBuf::from(robots));
    }
    PackagePath::from_env(dirs)
}

impl Robot {
    /// Loads the description at `path`, resolving `package://` through [`search_path`] with no
    /// explicit folders.
    pub fn load(path: impl AsRef<Path>) -> Result<Robot, DescriptionError> {
        Self::load_with(path, &search_path(Vec::new()))
    }

    /// Loads the description at `path` with the package search path `packages`.
    pub fn load_with(
        path: impl AsRef<Path>,
        packages: &PackagePath,
    ) -> Result<Robot, DescriptionError> {
        let path = path.as_ref();
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|source| DescriptionError::Io {
            file: file.clone(),
            source,
        })?;
        let base = path.parent().unwrap_or(Path::new("."));
        bind::load_text(&text, &file, base, packages)
    }

    /// Loads description text: `file` labels errors, `base` is the folder relative paths are
    /// resolved against, `packages` the `package://` search path.
    pub fn parse(
        text: &str,
        file: &str,
        base: &Path,
        packages: &PackagePath,
    ) -> Result<Robot, DescriptionError> {
        bind::load_text(text, file, base, packages)
    }

    /// Path of a bundled description: `g1` or `talos`.
    pub fn bundled(name: &str) -> Option<PathBuf> {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("data");
        match name {
            "g1" | "talos" => Some(dir.join(format!("{name}.toml"))),
            _ => None,
        }
    }

    /// The URDF properties (range, velocity limit) of joint `name`.
    pub fn joint(&self, name: &str) -> Option<&JointProps> {
        self.urdf.joints.iter().find(|j| j.name == name)
    }

    /// `(q_index, v_index)` of joint `name`.
    pub fn joint_index(&self, name: &str) -> Option<(usize, usize)> {
        let body = self.urdf.model.body(self.joint(name)?.body)?;
        Some((body.q_index(), body.v_index()))
    }

    /// Reflected rotor inertia of joint `name`: the first `armature` entry that matches, else 0.
    pub fn armature(&self, name: &str) -> f64 {
        let a = &self.description.armature;
        let hit = a.iter().find(|(p, _)| check::glob_match(p, name));
        hit.map_or(0.0, |(_, v)| *v)
    }
}
