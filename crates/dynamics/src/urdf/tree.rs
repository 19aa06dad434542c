//! Conversion of a parsed URDF tree into bodies: fixed-joint merging, joint models, inertias.

use super::error::{Location, UrdfError};
use super::joints::joint_props;
use super::source::Source;
use super::topology::topology;
use super::{LinkFrame, UrdfModel, UrdfOptions};
use crate::{BodyId, BodySpec, JointModel, ModelBuilder, RigidInertia};
use nalgebra::{Isometry3, Matrix3, Translation3, Unit, UnitQuaternion, Vector3};
use urdf_rs::{JointType, Robot};

/// Where a link's frame is: owning body (`None` = world) and pose in that body.
#[derive(Clone, Copy)]
struct Frame {
    body: Option<usize>,
    pose: Isometry3<f64>,
}

/// Converts a parsed URDF into a model (see the module docs for the conventions).
pub(super) fn convert(
    robot: &Robot,
    src: &Source<'_>,
    options: &UrdfOptions,
) -> Result<UrdfModel, UrdfError> {
    let topo = topology(robot, src)?;
    let mut bodies: Vec<(BodySpec, Location)> = Vec::new();
    let mut frames: Vec<Option<Frame>> = vec![None; robot.links.len()];
    let mut order = Vec::with_capacity(robot.links.len());
    let mut warnings = Vec::new();
    let mut joints = Vec::new();
    let root = &robot.links[topo.root];
    frames[topo.root] = Some(if options.floating {
        bodies.push((
            root_spec(root, src, &mut warnings)?,
            src.at("link", &root.name),
        ));
        Frame {
            body: Some(0),
            pose: Isometry3::identity(),
        }
    } else {
        Frame {
            body: None,
            pose: Isometry3::identity(),
        }
    });
    order.push(topo.root);
    let mut stack: Vec<usize> = topo.children[topo.root].iter().rev().copied().collect();
    while let Some(j) = stack.pop() {
        let joint = &robot.joints[j];
        let child = topo.child_of_joint[j];
        check_mimic(joint, src, options, &mut warnings)?;
        let parent = frames[topo.parent_of_joint[j]].expect("parent visited first");
        let placement = parent.pose
            * pose(&joint.origin, || {
                src.invalid(
                    "joint",
                    &joint.name,
                    "origin",
                    "non-finite xyz or rpy".into(),
                )
            })?;
        let inertia = link_inertia(&robot.links[child], src, &mut warnings)?;
        frames[child] = Some(match joint_model(joint, src)? {
            None => merge_fixed(&mut bodies, parent.body, placement, &inertia),
            Some(model) => {
                let spec = BodySpec {
                    name: robot.links[child].name.clone(),
                    joint_name: joint.name.clone(),
                    parent: parent.body,
                    joint: model,
                    placement,
                    inertia,
                };
                bodies.push((spec, src.at("joint", &joint.name)));
                let body = bodies.len() - 1;
                if joint.joint_type != JointType::Floating {
                    joints.push(joint_props(joint, body, src, &mut warnings)?);
                }
                Frame {
                    body: Some(bodies.len() - 1),
                    pose: Isometry3::identity(),
                }
            }
        });
        order.push(child);
        stack.extend(topo.children[child].iter().rev());
    }
    let model = build(bodies, src)?;
    let links = order
        .iter()
        .map(|&l| {
            let f = frames[l].expect("every link visited");
            LinkFrame {
                link: robot.links[l].name.clone(),
                body: f.body,
                pose: f.pose,
            }
        })
        .collect();
    Ok(UrdfModel {
        model,
        links,
        joints,
        warnings,
    })
}

/// Adds a fixed-joint child's inertia to the body it is welded to and returns its frame.
fn merge_fixed(
    bodies: &mut [(BodySpec, Location)],
    body: Option<usize>,
    placement: Isometry3<f64>,
    inertia: &RigidInertia,
) -> Frame {
    if let Some(b) = body {
        let spec = &mut bodies[b].0;
        spec.inertia = spec.inertia.merged(inertia, &placement);
    }
    Frame {
        body,
        pose: placement,
    }
}

/// Feeds the collected bodies (parents given as indices into `bodies`) to the model builder.
fn build(bodies: Vec<(BodySpec, Location)>, src: &Source<'_>) -> Result<crate::Model, UrdfError> {
    let mut builder = ModelBuilder::new();
    let mut ids: Vec<BodyId> = Vec::with_capacity(bodies.len());
    for (mut spec, at) in bodies {
        spec.parent = spec.parent.map(|p| ids[p]);
        ids.push(
            builder
                .add_body(spec)
                .map_err(|source| UrdfError::Model { at, source })?,
        );
    }
    builder.build().map_err(|source| UrdfError::Model {
        at: Location {
            file: src.file.to_string(),
            line: None,
            element: "robot".into(),
        },
        source,
    })
}

/// The free-floating root body (joint "root" attached to the world).
fn root_spec(
    link: &urdf_rs::Link,
    src: &Source<'_>,
    warnings: &mut Vec<String>,
) -> Result<BodySpec, UrdfError> {
    Ok(BodySpec {
        name: link.name.clone(),
        joint_name: "root".into(),
        parent: None,
        joint: JointModel::FreeQuaternion,
        placement: Isometry3::identity(),
        inertia: link_inertia(link, src, warnings)?,
    })
}

/// The joint model of a URDF joint (`None` for `fixed`, which is merged).
fn joint_model(joint: &urdf_rs::Joint, src: &Source<'_>) -> Result<Option<JointModel>, UrdfError> {
    let axis = || unit_axis(joint, src);
    Ok(Some(match joint.joint_type {
        JointType::Fixed => return Ok(None),
        JointType::Revolute | JointType::Continuous => JointModel::Revolute { axis: axis()? },
        JointType::Prismatic => JointModel::Prismatic { axis: axis()? },
        JointType::Floating => JointModel::FreeQuaternion,
        JointType::Planar | JointType::Spherical => {
            let problem = format!("joint type {:?} is not supported", joint.joint_type);
            return Err(src.invalid("joint", &joint.name, "type", problem.to_lowercase()));
        }
    }))
}

/// The joint axis, normalised; zero or non-finite axes are errors.
fn unit_axis(joint: &urdf_rs::Joint, src: &Source<'_>) -> Result<Unit<Vector3<f64>>, UrdfError> {
    let v = Vector3::from(joint.axis.xyz.0);
    let norm = v.norm();
    if !norm.is_finite() || norm < 1e-12 {
        let problem = format!(
            "axis must be finite and non-zero, got {:?}",
            joint.axis.xyz.0
        );
        return Err(src.invalid("joint", &joint.name, "axis xyz", problem));
    }
    Ok(Unit::new_unchecked(v / norm))
}

/// Handles `<mimic>`: a warning by default, an error with `reject_mimic`.
fn check_mimic(
    joint: &urdf_rs::Joint,
    src: &Source<'_>,
    options: &UrdfOptions,
    warnings: &mut Vec<String>,
) -> Result<(), UrdfError> {
    let Some(mimic) = &joint.mimic else {
        return Ok(());
    };
    if options.reject_mimic {
        let problem = format!("mimics joint {:?}; mimic joints are rejected", mimic.joint);
        return Err(src.invalid("joint", &joint.name, "mimic", problem));
    }
    warnings.push(format!(
        "{}: <mimic joint={:?}> ignored: the joint keeps its own independent coordinate",
        src.at("joint", &joint.name),
        mimic.joint
    ));
    Ok(())
}

/// Pose of a URDF `<origin xyz rpy>` (`R = Rz(yaw) Ry(pitch) Rx(roll)`).
fn pose(
    origin: &urdf_rs::Pose,
    error: impl FnOnce() -> UrdfError,
) -> Result<Isometry3<f64>, UrdfError> {
    let [x, y, z] = origin.xyz.0;
    let [roll, pitch, yaw] = origin.rpy.0;
    if ![x, y, z, roll, pitch, yaw].iter().all(|c| c.is_finite()) {
        return Err(error());
    }
    Ok(Isometry3::from_parts(
        Translation3::new(x, y, z),
        UnitQuaternion::from_euler_angles(roll, pitch, yaw),
    ))
}

/// Rotational inertias whose entries are all below this (kg m^2) are round-off of a point mass
/// (e.g. iCub's `1e-35` tensors) and are taken as exactly zero.
const NEGLIGIBLE_INERTIA: f64 = 1e-12;

/// A link's `<inertial>` as a rigid inertia in the link frame.
fn link_inertia(
    link: &urdf_rs::Link,
    src: &Source<'_>,
    warnings: &mut Vec<String>,
) -> Result<RigidInertia, UrdfError> {
    let inertial = &link.inertial;
    let frame = pose(&inertial.origin, || {
        src.invalid(
            "link",
            &link.name,
            "inertial origin",
            "non-finite xyz or rpy".into(),
        )
    })?;
    let t = &inertial.inertia;
    let tensor = Matrix3::new(
        t.ixx, t.ixy, t.ixz, //
        t.ixy, t.iyy, t.iyz, //
        t.ixz, t.iyz, t.izz,
    );
    let r = frame.rotation.to_rotation_matrix();
    let mut about_com = r.matrix() * tensor * r.matrix().transpose();
    if about_com.amax() < NEGLIGIBLE_INERTIA && about_com.amax() > 0.0 {
        warnings.push(format!(
            "{}: inertia tensor below {NEGLIGIBLE_INERTIA:e} kg m^2 taken as zero (point mass)",
            src.at("link", &link.name)
        ));
        about_com = Matrix3::zeros();
    }
    RigidInertia::new(inertial.mass.value, frame.translation.vector, about_com).map_err(|source| {
        UrdfError::Model {
            at: src.at("link", &link.name),
            source,
        }
    })
}
