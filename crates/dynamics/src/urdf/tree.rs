//! Conversion of a parsed URDF tree into bodies: topology checks, fixed-joint merging.

use super::error::{InvalidElement, Location, UrdfError};
use super::joints::joint_props;
use super::locate::element_line;
use super::{LinkFrame, UrdfModel, UrdfOptions};
use crate::{BodyId, BodySpec, JointModel, ModelBuilder, RigidInertia};
use nalgebra::{Isometry3, Matrix3, Translation3, Unit, UnitQuaternion, Vector3};
use std::collections::HashMap;
use urdf_rs::{JointType, Robot};

/// The URDF text and its label, for locating elements in error messages.
pub(super) struct Source<'a> {
    /// Raw XML text.
    pub xml: &'a str,
    /// File name or label.
    pub file: &'a str,
}

impl Source<'_> {
    /// Location of the element `<tag name="name">`.
    pub(super) fn at(&self, tag: &str, name: &str) -> Location {
        Location {
            file: self.file.to_string(),
            line: element_line(self.xml, tag, name),
            element: format!("{tag} {name:?}"),
        }
    }

    /// An [`UrdfError::Invalid`] at `<tag name="name">`.
    pub(super) fn invalid(&self, tag: &str, name: &str, field: &str, problem: String) -> UrdfError {
        UrdfError::Invalid(InvalidElement {
            at: self.at(tag, name),
            field: field.to_string(),
            problem,
        })
    }
}

/// Parent/child relations of the URDF links, indexed by link.
struct Topology {
    /// Root link.
    root: usize,
    /// Joints whose parent is the link, in file order.
    children: Vec<Vec<usize>>,
    /// Link index of every joint's child.
    child_of_joint: Vec<usize>,
}

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
        let parent = frames[link_index(robot, &joint.parent.link)].expect("parent visited first");
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

/// Index of a link known to exist (checked by [`topology`]).
fn link_index(robot: &Robot, name: &str) -> usize {
    robot
        .links
        .iter()
        .position(|l| l.name == name)
        .expect("checked by topology")
}

/// Checks names and connectivity and finds the unique root link.
fn topology(robot: &Robot, src: &Source<'_>) -> Result<Topology, UrdfError> {
    if robot.links.is_empty() {
        return Err(src.invalid("robot", &robot.name, "link", "no links".into()));
    }
    let mut index: HashMap<&str, usize> = HashMap::new();
    for (i, link) in robot.links.iter().enumerate() {
        if index.insert(link.name.as_str(), i).is_some() {
            return Err(src.invalid("link", &link.name, "name", "duplicate link name".into()));
        }
    }
    let mut joint_names: HashMap<&str, usize> = HashMap::new();
    let mut parent_joint: Vec<Option<usize>> = vec![None; robot.links.len()];
    let mut children = vec![Vec::new(); robot.links.len()];
    let mut child_of_joint = Vec::with_capacity(robot.joints.len());
    for (j, joint) in robot.joints.iter().enumerate() {
        if joint_names.insert(joint.name.as_str(), j).is_some() {
            return Err(src.invalid("joint", &joint.name, "name", "duplicate joint name".into()));
        }
        let find = |field: &str, link: &str| {
            index.get(link).copied().ok_or_else(|| {
                src.invalid(
                    "joint",
                    &joint.name,
                    field,
                    format!("no link named {link:?}"),
                )
            })
        };
        let parent = find("parent link", &joint.parent.link)?;
        let child = find("child link", &joint.child.link)?;
        if let Some(other) = parent_joint[child] {
            let problem = format!(
                "link {:?} is already the child of joint {:?}",
                joint.child.link, robot.joints[other].name
            );
            return Err(src.invalid("joint", &joint.name, "child link", problem));
        }
        parent_joint[child] = Some(j);
        children[parent].push(j);
        child_of_joint.push(child);
    }
    let root = unique_root(robot, &parent_joint, src)?;
    check_connected(robot, root, &children, &child_of_joint, src)?;
    Ok(Topology {
        root,
        children,
        child_of_joint,
    })
}

/// The single link without a parent joint.
fn unique_root(
    robot: &Robot,
    parent_joint: &[Option<usize>],
    src: &Source<'_>,
) -> Result<usize, UrdfError> {
    let roots: Vec<usize> = (0..robot.links.len())
        .filter(|&l| parent_joint[l].is_none())
        .collect();
    match roots.as_slice() {
        [root] => Ok(*root),
        [] => Err(src.invalid(
            "robot",
            &robot.name,
            "joint",
            "no root link: the joints form a cycle".into(),
        )),
        many => {
            let names: Vec<&str> = many.iter().map(|&l| robot.links[l].name.as_str()).collect();
            let problem = format!(
                "several root links ({}): the tree is not connected",
                names.join(", ")
            );
            Err(src.invalid("robot", &robot.name, "link", problem))
        }
    }
}

/// Every link must be reachable from the root (otherwise part of the joints form a cycle).
fn check_connected(
    robot: &Robot,
    root: usize,
    children: &[Vec<usize>],
    child_of_joint: &[usize],
    src: &Source<'_>,
) -> Result<(), UrdfError> {
    let mut seen = vec![false; robot.links.len()];
    let mut stack = vec![root];
    while let Some(l) = stack.pop() {
        seen[l] = true;
        stack.extend(children[l].iter().map(|&j| child_of_joint[j]));
    }
    match seen.iter().position(|s| !s) {
        None => Ok(()),
        Some(l) => Err(src.invalid(
            "link",
            &robot.links[l].name,
            "parent",
            "not reachable from the root link: its joints form a cycle".into(),
        )),
    }
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
