//! [`DynamicLeg`]: a leg's joints as the foot force control and the ankle stabiliser use them,
//! and how they are found in a robot description (see [`super::robot`]).

use crate::walk::error::{model_err, WalkError};
use crate::walk::robot::WalkRobot;
use biped_dynamics::{update_placements, Data, JointModel};

/// Number of leg joints the foot force control moves (hip to ankle).
pub const LEG_JOINTS: usize = 6;

/// Lola's leg joints without the side prefix, hip to ankle (the toe stays).
const LOLA_LEG: [&str; LEG_JOINTS] = [
    "hip_rotation",
    "hip_adduction",
    "thigh",
    "shank",
    "ankle_cross",
    "foot",
];

/// One leg of a [`super::DynamicRobot`].
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicLeg {
    /// The joints that move the foot, hip to ankle.
    pub joints: [String; LEG_JOINTS],
    /// The ankle's `[pitch, roll]` joints, each with the sign (+-1) of its axis along the
    /// lateral (pitch) or forward (roll) axis in the walking posture: a positive sign turns
    /// the foot nose-down (pitch) or about the forward axis (roll) as Lola's ankle does.
    pub ankle: [(String, f64); 2],
}

impl DynamicLeg {
    /// Lola's leg of side prefix `side` (`l`, `r`): flexion `*_ankle_cross` and adduction
    /// `*_foot`, both with sign +1.
    pub fn lola(side: &str) -> Self {
        let name = |j: &str| format!("{side}_{j}");
        Self {
            joints: LOLA_LEG.map(name),
            ankle: [(name("ankle_cross"), 1.0), (name("foot"), 1.0)],
        }
    }
}

/// The six joints of a leg group, or an error naming the file.
pub(super) fn leg_names(group: &[String], file: &str) -> Result<[String; LEG_JOINTS], WalkError> {
    group.to_vec().try_into().map_err(|g: Vec<String>| {
        WalkError::Description(format!(
            "{file}: a leg group has {} joints: the dynamic walk's foot force control needs {}",
            g.len(),
            LEG_JOINTS
        ))
    })
}

/// The leg of `joints` with its ankle from the axes of the last two joints in `walk`'s
/// posture: the one closer to the lateral axis is the pitch joint.
pub(super) fn ankle_of(
    walk: &WalkRobot,
    joints: [String; LEG_JOINTS],
) -> Result<DynamicLeg, WalkError> {
    let m = &walk.model;
    let mut data = Data::new(m);
    update_placements(m, &mut data, &walk.posture).map_err(model_err)?;
    let axis = |name: &str| {
        let b = m.bodies().iter().position(|b| b.joint_name() == name);
        let b = b.ok_or_else(|| model_err(format!("no joint {name}")))?;
        match m.bodies()[b].joint() {
            JointModel::Revolute { axis } => Ok(data.world_rot[b] * axis.into_inner()),
            _ => Err(model_err(format!("{name} is not revolute"))),
        }
    };
    let (a, b) = (&joints[LEG_JOINTS - 2], &joints[LEG_JOINTS - 1]);
    let (xa, xb) = (axis(a)?, axis(b)?);
    let ((pitch, p), (roll, r)) = match xa.y.abs() >= xb.y.abs() {
        true => ((a, xa), (b, xb)),
        false => ((b, xb), (a, xa)),
    };
    let ankle = [(pitch.clone(), p.y.signum()), (roll.clone(), r.x.signum())];
    Ok(DynamicLeg { joints, ankle })
}
