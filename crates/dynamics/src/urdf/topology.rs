//! Topology of a parsed URDF: names, parent and child links of the joints, the unique root,
//! connectivity. Every check is one pass over the links and joints.

use super::error::UrdfError;
use super::source::Source;
use std::collections::HashMap;
use urdf_rs::Robot;

/// Parent/child relations of the URDF links, indexed by link.
pub(super) struct Topology {
    /// Root link.
    pub root: usize,
    /// Joints whose parent is the link, in file order.
    pub children: Vec<Vec<usize>>,
    /// Link index of every joint's child.
    pub child_of_joint: Vec<usize>,
    /// Link index of every joint's parent.
    pub parent_of_joint: Vec<usize>,
}

/// Checks names and connectivity and finds the unique root link.
pub(super) fn topology(robot: &Robot, src: &Source<'_>) -> Result<Topology, UrdfError> {
    if robot.links.is_empty() {
        return Err(src.invalid("robot", &robot.name, "link", "no links".into()));
    }
    let mut index: HashMap<&str, usize> = HashMap::new();
    for (i, link) in robot.links.iter().enumerate() {
        check_name(src, "link", &link.name)?;
        if index.insert(link.name.as_str(), i).is_some() {
            return Err(src.invalid("link", &link.name, "name", "duplicate link name".into()));
        }
    }
    let mut joint_names: HashMap<&str, usize> = HashMap::new();
    let mut parent_joint: Vec<Option<usize>> = vec![None; robot.links.len()];
    let mut children = vec![Vec::new(); robot.links.len()];
    let mut child_of_joint = Vec::with_capacity(robot.joints.len());
    let mut parent_of_joint = Vec::with_capacity(robot.joints.len());
    for (j, joint) in robot.joints.iter().enumerate() {
        check_name(src, "joint", &joint.name)?;
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
        parent_of_joint.push(parent);
    }
    let root = unique_root(robot, &parent_joint, src)?;
    check_connected(robot, root, &children, &child_of_joint, src)?;
    Ok(Topology {
        root,
        children,
        child_of_joint,
        parent_of_joint,
    })
}

/// Link and joint names must not be empty (nor only white space).
fn check_name(src: &Source<'_>, tag: &str, name: &str) -> Result<(), UrdfError> {
    match name.trim().is_empty() {
        true => Err(src.invalid(tag, name, "name", "must not be empty".into())),
        false => Ok(()),
    }
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
            let names: Vec<&str> = many
                .iter()
                .take(5)
                .map(|&l| robot.links[l].name.as_str())
                .collect();
            let more = match many.len() {
                n if n > 5 => format!(" and {} more", n - 5),
                _ => String::new(),
            };
            let problem = format!(
                "several root links ({}{more}): the tree is not connected",
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
