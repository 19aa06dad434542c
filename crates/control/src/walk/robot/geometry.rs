//! Pattern geometry of a described robot from its kinematics: step width and CoM height in
//! the walking posture, the reach of the legs and the natural step length.
//!
//! - Leg length `l`: hip (the body of the leg's first joint) to sole frame with every joint
//!   at 0 (straight legs); hip height `h` above the sole in the walking posture.
//! - One leg reaches `d = sqrt(l^2 - h^2)` fore or aft of the point below its hip, so two
//!   consecutive footprints are at most `2 d` apart with stretched legs: the pattern's
//!   `reach` is [`REACH_FRACTION`] of that (flat feet, no toe-off to lengthen the rear leg).
//! - The natural step length is [`STEP_FRACTION`] of `2 d` (for the Lola-like model, 0.4 m
//!   steps against its 0.55 m reach: the same share of the stretched-leg distance).

use crate::tasks::Frame;
use crate::walk::error::{model_err, WalkError};
use biped_dynamics::{center_of_mass, update_placements, Data, Model};
use biped_robots::description::Robot;
use nalgebra::{DVector, Vector3};

/// Share of the stretched-leg footprint distance `2 d` the pattern lets a step take.
pub const REACH_FRACTION: f64 = 0.8;

/// Share of `2 d` of the natural step length.
pub const STEP_FRACTION: f64 = 0.5;

/// What [`derive`] finds.
#[derive(Debug, Clone, Copy)]
pub(super) struct Derived {
    pub step_width: f64,
    pub com_height: f64,
    pub reach: f64,
    pub natural_step_length: f64,
}

/// World origin of `frame` in `data`'s last kinematics.
pub(crate) fn frame_position(data: &Data, frame: &Frame) -> Vector3<f64> {
    data.world_pos[frame.body] + data.world_rot[frame.body] * frame.offset.translation.vector
}

/// Step width, CoM height, reach and natural step length (module docs) of `robot` in the
/// walking posture `posture` with sole frames `soles` (`[right, left]`).
pub(super) fn derive(
    model: &Model,
    soles: &[Frame; 2],
    posture: &DVector<f64>,
    robot: &Robot,
) -> Result<Derived, WalkError> {
    let file = &robot.description.file;
    let mut data = Data::new(model);
    update_placements(model, &mut data, posture).map_err(model_err)?;
    let com = center_of_mass(model, &mut data, posture, None).map_err(model_err)?;
    let feet = soles.map(|s| frame_position(&data, &s));
    let hips = [1, 0].map(|side| {
        let first = robot.description.legs[side].first();
        first.and_then(|n| robot.joint(n)).map(|j| j.body)
    });
    let [Some(hr), Some(hl)] = hips else {
        return Err(WalkError::Description(format!(
            "{file}: a leg group is empty"
        )));
    };
    let height = 0.5 * ((data.world_pos[hr] - feet[0]).z + (data.world_pos[hl] - feet[1]).z);
    update_placements(model, &mut data, &model.neutral()).map_err(model_err)?;
    let length = (data.world_pos[hr] - frame_position(&data, &soles[0])).norm();
    let d = (length * length - height * height).max(0.0).sqrt();
    Ok(Derived {
        step_width: (feet[1].y - feet[0].y).abs(),
        com_height: com.position.z - 0.5 * (feet[0].z + feet[1].z),
        reach: REACH_FRACTION * 2.0 * d,
        natural_step_length: STEP_FRACTION * 2.0 * d,
    })
}
