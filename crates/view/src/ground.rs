//! How low the robot reaches at a posture: the lowest point of its drawn geometry (exact for
//! boxes, cylinders, spheres, capsules and STL/OBJ meshes; a mesh of another format counts
//! with its origin) or of its body frames, so that the neutral pose can stand on `z = 0`.

use crate::robot::{GeometryJson, Robot, ShapeJson};
use nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};

fn isometry(g: &GeometryJson) -> Isometry3<f64> {
    let [x, y, z, w] = g.pose.quaternion;
    let q = UnitQuaternion::from_quaternion(Quaternion::new(w, x, y, z));
    Isometry3::from_parts(Translation3::from(Vector3::from(g.pose.position)), q)
}

/// The lowest world z of one element placed at `pose`.
fn lowest(robot: &Robot, shape: &ShapeJson, pose: &Isometry3<f64>) -> f64 {
    let centre = pose.translation.vector.z;
    let r = pose.rotation.to_rotation_matrix();
    let z = r.matrix().row(2);
    match shape {
        ShapeJson::Box { size } => centre - (0..3).map(|j| z[j].abs() * size[j] / 2.0).sum::<f64>(),
        ShapeJson::Sphere { radius } => centre - radius,
        ShapeJson::Cylinder { radius, length } => {
            centre - z[2].abs() * length / 2.0 - radius * (1.0 - z[2] * z[2]).max(0.0).sqrt()
        }
        ShapeJson::Capsule { radius, length } => centre - z[2].abs() * length / 2.0 - radius,
        ShapeJson::Mesh { url, scale, .. } => {
            let index = url.rsplit('/').next().and_then(|k| k.parse::<usize>().ok());
            let mesh = index
                .and_then(|k| robot.meshes.get(k))
                .and_then(|path| biped_ssv::mesh::read_file(path).ok());
            let Some(mesh) = mesh else {
                return centre;
            };
            let scaled =
                |v: &Point3<f64>| Point3::new(v.x * scale[0], v.y * scale[1], v.z * scale[2]);
            let low = mesh.vertices().iter().map(|v| (pose * scaled(v)).z);
            low.fold(centre, f64::min)
        }
    }
}

/// The lowest world z of the robot's geometry and body frames with the bodies at `poses`.
pub fn lowest_point(robot: &Robot, poses: &[Isometry3<f64>]) -> f64 {
    let frames = poses.iter().map(|p| p.translation.vector.z);
    let mut low = frames.fold(f64::INFINITY, f64::min);
    for (body, pose) in robot.bodies.iter().zip(poses) {
        for g in &body.geometry {
            low = low.min(lowest(robot, &g.shape, &(pose * isometry(g))));
        }
    }
    low
}
