//! [`WalkRobot::from_description`]: a walking robot from a robot description file.
//!
//! - Sole frame: the foot frame's link moved down to the plane of the sole rectangle, so its
//!   origin lies below the ankle like Lola's sole frame; the rectangle gives
//!   [`crate::pattern::FootGeometry`] (front / back edge from the origin, half width).
//! - Upper body: the body the arms are mounted on (the parent of the first arm joint's body).
//! - Joint tasks hold every movable joint outside the legs and arms (waist, head) at its
//!   posture value, at most five of them ([`super::HELD_SLOTS`]); joints beyond an arm group
//!   on the arm's subtree (hands, grippers) move with the arm; toe joints, where the
//!   description names them, are held too and the feet stay flat (no toe-off).
//! - Walking posture: the description's comfort pose; pattern geometry from it
//!   ([`super::geometry`]).

use super::geometry::{derive, Derived};
use super::{WalkJoint, WalkRobot, HELD_SLOTS};
use crate::pattern::{FootGeometry, FootRoll};
use crate::tasks::{Frame, WalkTaskFrames};
use crate::walk::error::WalkError;
use biped_dynamics::urdf::UrdfModel;
use biped_robots::description::{Foot, Robot};
use nalgebra::{Isometry3, Translation3};

impl WalkRobot {
    /// The robot of a loaded description (see the module docs); an error names the file and
    /// what is missing (a collision model, a frame, too many trunk joints).
    pub fn from_description(robot: &Robot) -> Result<Self, WalkError> {
        let d = &robot.description;
        let file = &d.file;
        if !d.floating {
            return Err(WalkError::Description(format!(
                "{file}: `floating = false`: a walking robot needs a floating base"
            )));
        }
        let urdf = &robot.urdf;
        let model = urdf.model.clone();
        let joints = ranged_joints(robot);
        let collision = collision_model(robot)?;
        // description order is [left, right]; the walk's slots are [right, left]
        let soles = [
            sole_frame(urdf, &d.feet[1], file)?,
            sole_frame(urdf, &d.feet[0], file)?,
        ];
        let arm_roots = [
            first_body(robot, &d.arms[1])?,
            first_body(robot, &d.arms[0])?,
        ];
        let torso = torso(robot, arm_roots[1])?;
        let (held, hands) = held_joints(robot, &arm_roots);
        let slots = held_slots(robot, &held)?;
        let mut arm_joints: Vec<String> = d.arms.iter().flatten().cloned().collect();
        arm_joints.extend(hands);
        let mut recorded = arm_joints.clone();
        recorded.extend(held.iter().cloned());
        let foot = foot_geometry(&d.feet[0]);
        let Derived {
            step_width,
            com_height,
            reach,
            natural_step_length,
        } = derive(&model, &soles, &robot.comfort, robot)?;
        Ok(Self {
            name: d.name.clone(),
            frames: WalkTaskFrames {
                torso,
                soles,
                toes: None,
                arm_roots,
                joints: slots,
            },
            arm_joints,
            arm_pose_joints: Vec::new(),
            reducing: d.reducing.clone(),
            recorded,
            collision,
            posture: robot.comfort.clone(),
            foot,
            roll: FootRoll::flat(),
            step_width,
            com_height,
            reach,
            natural_step_length,
            joints,
            model,
        })
    }
}

/// The description's collision model, which the walk's self-collision avoidance needs.
fn collision_model(robot: &Robot) -> Result<biped_ssv::CollisionModel, WalkError> {
    let file = &robot.description.file;
    let c = robot.collision.as_ref().ok_or_else(|| {
        WalkError::Description(format!(
            "{file}: no [collision] model: the walk's self-collision avoidance needs one \
             (`biped ssv fit` makes one)"
        ))
    })?;
    Ok(c.model.clone())
}

/// The body that carries the left arm (the upper-body task's frame).
fn torso(robot: &Robot, left_arm_root: usize) -> Result<usize, WalkError> {
    let file = &robot.description.file;
    (robot.urdf.model.body(left_arm_root))
        .and_then(|b| b.parent())
        .ok_or_else(|| WalkError::Description(format!("{file}: the left arm has no parent body")))
}

/// The walk's single-joint task slots of the joints outside the legs and arms.
fn held_slots(robot: &Robot, held: &[String]) -> Result<[Option<(usize, usize)>; 7], WalkError> {
    if held.len() > HELD_SLOTS.len() {
        return Err(WalkError::Description(format!(
            "{}: {} joints outside the legs and arms ({}): the walk holds at most {}",
            robot.description.file,
            held.len(),
            held.join(", "),
            HELD_SLOTS.len()
        )));
    }
    let mut slots = [None; 7];
    for (name, &slot) in held.iter().zip(HELD_SLOTS.iter()) {
        slots[slot] = robot.joint_index(name);
    }
    Ok(slots)
}

/// The URDF's movable joints with a finite range.
fn ranged_joints(robot: &Robot) -> Vec<WalkJoint> {
    let model = &robot.urdf.model;
    robot
        .urdf
        .joints
        .iter()
        .filter_map(|j| {
            let [lower, upper] = j.range?;
            let b = model.body(j.body)?;
            Some(WalkJoint {
                name: j.name.clone(),
                q_index: b.q_index(),
                v_index: b.v_index(),
                lower,
                upper,
            })
        })
        .collect()
}

/// Movable joints in neither a leg nor an arm group, in URDF order (toe joints last): those
/// on the trunk and head (held by joint tasks), and those on an arm's subtree beyond its group
/// (hands, grippers: moved with the arm).
fn held_joints(robot: &Robot, arm_roots: &[usize; 2]) -> (Vec<String>, Vec<String>) {
    let d = &robot.description;
    let model = &robot.urdf.model;
    let grouped = |n: &String| d.legs.iter().chain(&d.arms).any(|g| g.contains(n));
    let toe = |n: &String| d.feet.iter().any(|f| f.toe_joint.as_ref() == Some(n));
    let on_arm = |mut b: usize| loop {
        if arm_roots.contains(&b) {
            return true;
        }
        match model.body(b).and_then(|x| x.parent()) {
            Some(p) => b = p,
            None => return false,
        }
    };
    let (mut held, mut hands) = (Vec::new(), Vec::new());
    for j in &robot.urdf.joints {
        if grouped(&j.name) || toe(&j.name) {
            continue;
        }
        match on_arm(j.body) {
            true => hands.push(j.name.clone()),
            false => held.push(j.name.clone()),
        }
    }
    held.extend(d.feet.iter().filter_map(|f| f.toe_joint.clone()));
    (held, hands)
}

/// Body moved by the first joint of `group`.
fn first_body(robot: &Robot, group: &[String]) -> Result<usize, WalkError> {
    let file = &robot.description.file;
    let name = group
        .first()
        .ok_or_else(|| WalkError::Description(format!("{file}: an arm group is empty")))?;
    robot
        .joint(name)
        .map(|j| j.body)
        .ok_or_else(|| WalkError::Description(format!("{file}: `{name}` is not a movable joint")))
}

/// The sole frame of `foot`: its link frame moved along its z axis to the sole plane.
fn sole_frame(urdf: &UrdfModel, foot: &Foot, file: &str) -> Result<Frame, WalkError> {
    let link = urdf.links.iter().find(|l| l.link == foot.frame);
    let (body, pose) = match link {
        Some(l) => (l.body, l.pose),
        None => (None, Isometry3::identity()),
    };
    let body = body.ok_or_else(|| {
        WalkError::Description(format!(
            "{file}: foot frame `{}` is not on a moving body",
            foot.frame
        ))
    })?;
    let down = Translation3::new(0.0, 0.0, foot.sole_center.z);
    Ok(Frame {
        body,
        offset: pose * Isometry3::from_parts(down, Default::default()),
    })
}

/// Sole rectangle relative to the sole frame (origin below the ankle).
fn foot_geometry(foot: &Foot) -> FootGeometry {
    let (c, [length, width]) = (&foot.sole_center, foot.sole_size);
    FootGeometry {
        front: c.x + 0.5 * length,
        back: 0.5 * length - c.x,
        half_width: 0.5 * width - c.y.abs(),
        ..FootGeometry::default()
    }
}
