//! [`WalkTaskFrames`]: the bodies, frames and joints the walking task set ([`super::LolaTasks`],
//! Table 4.2) acts on, for any robot; [`WalkTaskFrames::lola`] names Lola's.

use super::targets::TaskId;
use super::task::Frame;
use crate::error::IkError;
use biped_dynamics::Model;
use biped_robots::lola::LolaModel;

/// Task of each joint slot of [`WalkTaskFrames::joints`].
pub(crate) const JOINT_TASKS: [TaskId; 7] = [
    TaskId::PelvisRotation,
    TaskId::PelvisAdduction,
    TaskId::RightToe,
    TaskId::LeftToe,
    TaskId::HeadPan,
    TaskId::HeadTilt,
    TaskId::Vergence,
];

/// Names of Lola's joints of the 1-D tasks, in slot order.
const LOLA_JOINTS: [&str; 7] = [
    "pelvis_rotation",
    "torso",
    "r_toe",
    "l_toe",
    "head_pan",
    "head",
    "camera",
];

/// What the walking task set acts on. Pairs are `[right, left]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WalkTaskFrames {
    /// Body of the upper-body orientation task (and the frame of the foot orientations).
    pub torso: usize,
    /// Sole frames (foot TCP with the sole on the ground).
    pub soles: [Frame; 2],
    /// Toe segment frames (foot TCP during toe-off), if the feet have toes.
    pub toes: Option<[Frame; 2]>,
    /// First body of each arm: the arm CoG is the CoG of its subtree.
    pub arm_roots: [usize; 2],
    /// `(q index, v index)` of the joint of each 1-D task slot (order of the joint tasks of
    /// [`TaskId::ALL`]: two trunk slots, right and left toe, three further trunk / head
    /// slots); `None`: the slot's task stays off.
    pub joints: [Option<(usize, usize)>; 7],
}

impl WalkTaskFrames {
    /// Lola's: `torso`, `r_sole`/`l_sole`, `r_toe`/`l_toe`, the shoulders, and the pelvis
    /// rotation, torso, toe, head and camera joints.
    pub fn lola(lola: &LolaModel) -> Result<Self, IkError> {
        let model = &lola.model;
        let id = |n: &str| {
            model
                .body_id(n)
                .ok_or_else(|| IkError::UnknownName(n.to_string()))
        };
        let mut joints = [None; 7];
        for (slot, name) in joints.iter_mut().zip(LOLA_JOINTS) {
            let l = lola.limits.iter().find(|l| l.name == name);
            let l = l.ok_or_else(|| IkError::UnknownName(name.to_string()))?;
            *slot = Some((l.q_index, l.v_index));
        }
        Ok(Self {
            torso: id("torso")?,
            soles: [Frame::body(id("r_sole")?), Frame::body(id("l_sole")?)],
            toes: Some([Frame::body(id("r_toe")?), Frame::body(id("l_toe")?)]),
            arm_roots: [id("r_shoulder")?, id("l_shoulder")?],
            joints,
        })
    }

    /// Rejects bodies and coordinates outside `model`.
    pub(crate) fn check(&self, model: &Model) -> Result<(), IkError> {
        let nb = model.nbodies();
        let mut bodies = vec![self.torso, self.soles[0].body, self.soles[1].body];
        bodies.extend(self.arm_roots);
        bodies.extend(self.toes.iter().flatten().map(|f| f.body));
        if let Some(&b) = bodies.iter().find(|&&b| b >= nb) {
            return Err(IkError::UnknownName(format!("body {b}")));
        }
        for &(q, v) in self.joints.iter().flatten() {
            if q >= model.nq() || v >= model.nv() {
                return Err(IkError::Dimension {
                    what: "joint task index",
                    expected: model.nq(),
                    got: q,
                });
            }
        }
        Ok(())
    }
}
