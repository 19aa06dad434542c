//! The Lola-like biped's walking posture: knee and elbow bend, start configuration and the
//! pattern parameters of that posture.

use crate::momentum::LOLA_ARMS;
use crate::pattern::fit::{bent_knee_pose, standing_com_height};
use crate::pattern::PatternParams;
use crate::walk::error::{model_err, WalkError};
use biped_robots::lola::LolaModel;
use nalgebra::DVector;

/// Knee bend of the walking posture \[rad]: with toe-off and heel strike, straight enough that
/// the stance ankle stays inside its dorsiflexion limit at the end of single support, bent
/// enough that the legs reach the 0.4-0.5 m steps at touch-down (see [`crate::walk`]).
pub const WALK_KNEE: f64 = 0.55;

/// Elbow angle of the walking posture \[rad]: bent, away from the stretched-arm singularity
/// of the 3-D arm CoG task (a hanging straight arm cannot move its CoG vertically).
pub const WALK_ELBOW: f64 = -0.8;

/// Start posture: the flat-footed bent-knee pose of [`WALK_KNEE`] with the arm joints
/// `arm_pose = [shoulder flexion, upper-arm abduction (left; mirrored right), elbow]`
/// (default [`crate::walk::WalkParams::arm_pose`]: `[0, 0.1, WALK_ELBOW]`).
pub fn walk_start_configuration(
    lola: &LolaModel,
    arm_pose: [f64; 3],
) -> Result<DVector<f64>, WalkError> {
    let mut q = bent_knee_pose(lola, WALK_KNEE)?;
    for (k, name) in LOLA_ARMS.iter().enumerate() {
        let l = lola.limits.iter().find(|l| l.name == *name);
        let i = l
            .ok_or_else(|| model_err(format!("no joint {name}")))?
            .q_index;
        let sign = if k == 4 { -1.0 } else { 1.0 };
        q[i] = sign * arm_pose[k % 3];
    }
    Ok(q)
}

/// Pattern parameters for `lola` walking in the [`WALK_KNEE`] posture: the default pattern
/// with `n_steps`, `step_length`, `step_time` and the LIPM height of that posture.
pub fn walk_pattern_params(
    lola: &LolaModel,
    n_steps: usize,
    step_length: f64,
    step_time: f64,
) -> Result<PatternParams, WalkError> {
    Ok(PatternParams {
        n_steps,
        step_length,
        step_time,
        com_height: standing_com_height(lola, WALK_KNEE)?,
        ..PatternParams::default()
    })
}
