//! A robot description (`biped_robots::description`, `--robot g1|talos|FILE.toml`): its URDF
//! drawn as `--urdf` draws one, and its SSV collision-model file, which is shown but not
//! written (a save names `--ssv FILE`).

use crate::robot::Robot;
use crate::ViewError;
use biped_robots::description::{self, Robot as Described};
use std::path::{Path, PathBuf};

/// Folders `package://` meshes are looked up in: `explicit`, then `$ROBOTS` and its parent
/// (the G1's URDF names `package://example-robot-data/robots/...`), then `ROS_PACKAGE_PATH`
/// (added by the URDF loader).
fn mesh_folders(explicit: &[PathBuf]) -> Vec<PathBuf> {
    let mut dirs = explicit.to_vec();
    if let Some(robots) = std::env::var_os("ROBOTS").filter(|r| !r.is_empty()) {
        let robots = PathBuf::from(robots);
        dirs.extend(robots.parent().map(Path::to_path_buf));
        dirs.insert(explicit.len(), robots);
    }
    dirs
}

/// Loads the description `file` (its URDF, SRDF and SSV model, every name checked) and the
/// robot it names; returns the robot and the description's collision-model file.
pub(crate) fn load(
    file: &Path,
    package_path: &[PathBuf],
) -> Result<(Robot, Option<PathBuf>), ViewError> {
    let packages = description::search_path(package_path.to_vec());
    let described =
        Described::load_with(file, &packages).map_err(|e| ViewError::Robot(e.to_string()))?;
    let d = &described.description;
    let mut robot = crate::urdf::urdf_robot(&d.urdf, d.floating, &mesh_folders(package_path))?;
    robot.label = format!("{} ({})", d.name, file.display());
    Ok((robot, d.collision_model.clone()))
}

/// Why the description's own model is not written.
pub(crate) fn read_only_reason(model: &Path, file: &Path) -> String {
    format!(
        "not saved: {} is the collision model of the robot description {}; to edit it, copy it \
         and start biped view with --ssv COPY.toml",
        model.display(),
        file.display()
    )
}
