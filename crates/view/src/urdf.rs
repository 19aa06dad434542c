//! A URDF robot for the viewer: every `<visual>` element on the body its link was merged
//! into, meshes served by index, and a link's collision geometry when none of its visuals can
//! be drawn.

use crate::robot::{body_frames, empty_bodies, GeometryJson, PoseJson, Robot, ShapeJson};
use crate::ViewError;
use biped_dynamics::urdf::{self, GeometryElement, PackagePath, Shape, UrdfOptions};
use nalgebra::Isometry3;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// A URDF: every `<visual>` element on the body its link was merged into.
pub(crate) fn urdf_robot(
    path: &Path,
    floating: bool,
    package_path: &[PathBuf],
) -> Result<Robot, ViewError> {
    let options = UrdfOptions {
        floating,
        reject_mimic: false,
    };
    let imported = urdf::load_file(path, &options).map_err(|e| ViewError::Robot(e.to_string()))?;
    let links = urdf::read_geometry_file(path).map_err(|e| ViewError::Robot(e.to_string()))?;
    let packages = PackagePath::from_env(package_path.to_vec());
    let base = path.parent().unwrap_or(Path::new("."));
    let model = imported.model;
    let mut robot = Robot {
        bodies: empty_bodies(&model),
        frames: body_frames(&model),
        world: Vec::new(),
        meshes: Vec::new(),
        label: path.display().to_string(),
        warnings: imported.warnings,
        model,
    };
    let frames: HashMap<&str, _> = imported
        .links
        .iter()
        .map(|l| (l.link.as_str(), (l.body, l.pose)))
        .collect();
    for l in &imported.links {
        robot.frames.insert(l.link.clone(), (l.body, l.pose));
    }
    for link in &links {
        let Some(&(body, link_pose)) = frames.get(link.link.as_str()) else {
            continue;
        };
        let mut drawn = robot.place(&link.visuals, body, &link_pose, &packages, base);
        // A link none of whose visuals could be drawn shows its collision geometry instead.
        if drawn == 0 && !link.visuals.is_empty() {
            drawn = robot.place(&link.collisions, body, &link_pose, &packages, base);
            if drawn > 0 {
                let what = format!("link \"{}\"", link.link);
                robot
                    .warnings
                    .push(format!("{what}: drawn from its <collision> elements"));
            }
        }
    }
    robot.warnings = collapse_unresolved(std::mem::take(&mut robot.warnings));
    Ok(robot)
}

/// The warnings with those of meshes not drawn for one same reason (a package not found,
/// as for every mesh of a robot whose package is not installed) folded into the first.
fn collapse_unresolved(warnings: Vec<String>) -> Vec<String> {
    const NOT_DRAWN: &str = ": mesh not drawn: ";
    let mut out: Vec<String> = Vec::new();
    let mut counts: Vec<(usize, String, usize)> = Vec::new(); // (index in out, reason, more)
    for w in warnings {
        let reason = w.split_once(NOT_DRAWN).map(|(_, r)| r.to_string());
        match reason {
            Some(r) => match counts.iter_mut().find(|(_, seen, _)| *seen == r) {
                Some((_, _, more)) => *more += 1,
                None => {
                    counts.push((out.len(), r, 0));
                    out.push(w);
                }
            },
            None => out.push(w),
        }
    }
    for (at, _, more) in counts.into_iter().filter(|c| c.2 > 0) {
        out[at].push_str(&format!(" (and {more} more meshes for the same reason)"));
    }
    out
}

impl Robot {
    /// Adds the drawable ones of `elements` (of a link at `link_pose` in `body`); returns how
    /// many.
    fn place(
        &mut self,
        elements: &[GeometryElement],
        body: Option<usize>,
        link_pose: &Isometry3<f64>,
        packages: &PackagePath,
        base: &Path,
    ) -> usize {
        let mut drawn = 0;
        for element in elements {
            let Some(shape) = self.shape(&element.shape, packages, base, &element.at) else {
                continue;
            };
            let geometry = GeometryJson {
                pose: PoseJson::from(&(link_pose * element.origin)),
                shape,
            };
            match body {
                Some(b) => self.bodies[b].geometry.push(geometry),
                None => self.world.push(geometry),
            }
            drawn += 1;
        }
        drawn
    }

    /// The drawn shape of a URDF shape; a mesh that cannot be resolved, or of a format the
    /// page cannot read, is left out with a warning.
    fn shape(
        &mut self,
        shape: &Shape,
        packages: &PackagePath,
        base: &Path,
        at: &impl std::fmt::Display,
    ) -> Option<ShapeJson> {
        Some(match shape {
            Shape::Box { size } => ShapeJson::Box { size: *size },
            Shape::Cylinder { radius, length } => ShapeJson::Cylinder {
                radius: *radius,
                length: *length,
            },
            Shape::Sphere { radius } => ShapeJson::Sphere { radius: *radius },
            Shape::Capsule { radius, length } => ShapeJson::Capsule {
                radius: *radius,
                length: *length,
            },
            Shape::Mesh { filename, scale } => {
                let file = match packages.resolve(filename, base) {
                    Ok(file) => file,
                    Err(e) => {
                        self.warnings.push(format!("{at}: mesh not drawn: {e}"));
                        return None;
                    }
                };
                let ext = file.extension().and_then(|e| e.to_str()).unwrap_or("");
                let format = ext.to_ascii_lowercase();
                if !["stl", "obj", "dae", "wrl"].contains(&format.as_str()) {
                    let what = format!("{at}: mesh {} not drawn", file.display());
                    self.warnings.push(format!(
                        "{what}: format `{ext}` (STL, OBJ, DAE or VRML97 .wrl)"
                    ));
                    return None;
                }
                self.meshes.push(file);
                ShapeJson::Mesh {
                    url: format!("/api/mesh/{}", self.meshes.len() - 1),
                    format,
                    scale: *scale,
                }
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::collapse_unresolved;

    #[test]
    fn meshes_not_drawn_for_one_reason_are_one_warning() {
        let w = |s: &str| s.to_string();
        let folded = collapse_unresolved(vec![
            w("r.urdf:3: link \"a\" visual: mesh not drawn: package \"p\" not found"),
            w("link \"a\": drawn from its <collision> elements"),
            w("r.urdf:5: link \"b\" visual: mesh not drawn: package \"p\" not found"),
            w("r.urdf:7: link \"c\" visual: mesh not drawn: package \"p\" not found"),
            w("r.urdf:9: link \"d\" visual: mesh not drawn: x.stl: no such file"),
        ]);
        assert_eq!(
            folded,
            [
                "r.urdf:3: link \"a\" visual: mesh not drawn: package \"p\" not found (and 2 \
                 more meshes for the same reason)",
                "link \"a\": drawn from its <collision> elements",
                "r.urdf:9: link \"d\" visual: mesh not drawn: x.stl: no such file",
            ]
        );
    }
}
