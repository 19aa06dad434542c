//! From the file text to a [`Robot`]: parse, resolve and load the referenced files, then check
//! every name and value against the URDF (errors located at the entry at fault).

use super::check::Checker;
use super::collision::collision;
use super::error::{DescriptionError, Locator, ReferencedError};
use super::raw::{RawCollision, RawDescription};
use super::{Robot, RobotDescription};
use biped_dynamics::urdf::srdf::load_srdf_file;
use biped_dynamics::urdf::{load_file, PackagePath, ResolveError, UrdfOptions};
use std::path::{Path, PathBuf};
use toml::Spanned;

type Res<T> = Result<T, DescriptionError>;

/// What to do when a package cannot be found.
const INSTALL_HINT: &str = "; install example-robot-data (`source scripts/fetch_robots.sh` \
    exports ROBOTS) or add its robots folder to ROS_PACKAGE_PATH";

/// Parses `text` (the file `file` in folder `base`) and loads the robot.
pub(super) fn load_text(text: &str, file: &str, base: &Path, packages: &PackagePath) -> Res<Robot> {
    let loc = Locator { file, text };
    let raw: RawDescription = toml::from_str(text).map_err(|e| loc.toml(e))?;
    let find = |r: &Spanned<String>, field: &str| resolve(&loc, r, field, base, packages);
    let urdf_path = find(&raw.urdf, "urdf")?;
    let options = UrdfOptions {
        floating: raw.floating,
        ..UrdfOptions::default()
    };
    let urdf =
        load_file(&urdf_path, &options).map_err(|e| loc.referenced(raw.urdf.span(), "urdf", e))?;
    let srdf_path = raw.drives.srdf.as_ref().map(|s| find(s, "drives.srdf"));
    let srdf_path = srdf_path.transpose()?;
    let srdf = match (&srdf_path, &raw.drives.srdf) {
        (Some(p), Some(s)) => {
            Some(load_srdf_file(p).map_err(|e| loc.referenced(s.span(), "drives.srdf", e))?)
        }
        _ => None,
    };
    let names = Checker {
        loc: &loc,
        urdf: &urdf,
    };
    let feet = [
        names.foot(&raw.feet.left, "feet.left")?,
        names.foot(&raw.feet.right, "feet.right")?,
    ];
    let g = &raw.groups;
    let legs = [
        names.joints(&g.left_leg, "groups.left_leg", false)?,
        names.joints(&g.right_leg, "groups.right_leg", false)?,
    ];
    let arms = [
        names.joints(&g.left_arm, "groups.left_arm", false)?,
        names.joints(&g.right_arm, "groups.right_arm", false)?,
    ];
    let reducing = names.joints(&raw.momentum.reducing, "momentum.reducing", false)?;
    let producing = match &raw.momentum.producing {
        Some(p) => names.producing(p, &reducing)?,
        None => urdf
            .joints
            .iter()
            .map(|j| j.name.clone())
            .filter(|n| !reducing.contains(n))
            .collect(),
    };
    let comfort = names.comfort(&raw, srdf.as_ref())?;
    let collision_path = raw
        .collision
        .as_ref()
        .map(|c| find(&c.model, "collision.model"));
    let collision_path = collision_path.transpose()?;
    let collision = match (&raw.collision, &collision_path) {
        (Some(c), Some(path)) => Some(collision(&loc, c, path, &urdf)?),
        _ => None,
    };
    let description = RobotDescription {
        file: file.to_string(),
        name: raw.name.get_ref().clone(),
        urdf: urdf_path,
        floating: raw.floating,
        feet,
        legs,
        arms,
        reducing,
        producing,
        comfort_state: raw.comfort.srdf_state.as_ref().map(|s| s.get_ref().clone()),
        comfort_joints: (raw.comfort.joints.iter())
            .map(|(k, v)| (k.clone(), *v.get_ref()))
            .collect(),
        collision_model: collision_path,
        collision_pairs: collision_pairs(&raw.collision),
        collision_exclude: (raw.collision.iter())
            .flat_map(|c| c.exclude.iter().map(|p| p.get_ref().clone()))
            .collect(),
        srdf: srdf_path,
        armature: names.armature(&raw)?,
    };
    Ok(Robot {
        description,
        urdf,
        srdf,
        collision,
        comfort,
    })
}

/// The file a reference names (relative to `base`, or `package://` through `packages`).
fn resolve(
    loc: &Locator,
    reference: &Spanned<String>,
    field: &str,
    base: &Path,
    packages: &PackagePath,
) -> Res<PathBuf> {
    packages
        .resolve(reference.get_ref(), base)
        .map_err(|source| {
            let hint = match source {
                ResolveError::PackageNotFound { .. } => INSTALL_HINT.to_string(),
                _ => String::new(),
            };
            loc.referenced(
                reference.span(),
                field,
                ReferencedError::Resolve { source, hint },
            )
        })
}

/// The explicit pair list of `[collision]`, if any.
fn collision_pairs(c: &Option<RawCollision>) -> Option<Vec<[String; 2]>> {
    let pairs = c.as_ref()?.pairs.as_ref()?;
    Some(
        pairs
            .get_ref()
            .iter()
            .map(|p| p.get_ref().clone())
            .collect(),
    )
}
