//! Walking posture, placement on the pattern's footprints, the `none` method's arm lock and
//! the reference method's arm swing about the shoulder (see the module docs of [`super`]).

use super::error::{model_err, WalkError};
use super::robot::{frame_position, WalkRobot};
use crate::ik::Weight;
use crate::momentum::{PointTarget, LOLA_ARMS};
use crate::pattern::fit::{bent_knee_pose, standing_com_height};
use crate::pattern::{PatternParams, PatternSample};
use crate::tasks::LolaTasks;
use biped_robots::lola::LolaModel;
use nalgebra::{DVector, Vector3};

/// Start configuration of `robot` with the sole midpoint on the pattern's first footprints'
/// midpoint.
pub(crate) fn place_on_footprints(
    robot: &WalkRobot,
    tasks: &mut LolaTasks,
    first: &PatternSample,
    arm_pose: [f64; 3],
) -> Result<DVector<f64>, WalkError> {
    let mut q = robot.start_configuration(arm_pose);
    tasks.set_targets_from(&q)?;
    let (data, _) = tasks.kinematics();
    let [right, left] = robot.frames.soles.map(|f| frame_position(data, &f));
    let model_mid = 0.5 * (left + right);
    let pattern_mid =
        0.5 * (first.feet[0].pose.translation.vector + first.feet[1].pose.translation.vector);
    let shift = pattern_mid - model_mid;
    for k in 0..3 {
        q[k] += shift[k];
    }
    Ok(q)
}

/// Knee bend of the walking posture \[rad]: with toe-off and heel strike, straight enough that
/// the stance ankle stays inside its dorsiflexion limit at the end of single support, bent
/// enough that the legs reach the 0.4-0.5 m steps at touch-down (see [`super`]).
pub const WALK_KNEE: f64 = 0.55;

/// Elbow angle of the walking posture \[rad]: bent, away from the stretched-arm singularity
/// of the 3-D arm CoG task (a hanging straight arm cannot move its CoG vertically).
pub const WALK_ELBOW: f64 = -0.8;

/// Start posture: the flat-footed bent-knee pose of [`WALK_KNEE`] with the arm joints
/// `arm_pose = [shoulder flexion, upper-arm abduction (left; mirrored right), elbow]`
/// (default [`super::WalkParams::arm_pose`]: `[0, 0.1, WALK_ELBOW]`).
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

/// Nominal arm CoG relative to the CoG, and relative to its shoulder with the distance
/// `rho` in the sagittal (x-z) plane.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ArmPivot {
    nominal: Vector3<f64>,
    arm: Vector3<f64>,
    rho: f64,
}

/// [`ArmPivot`]s (right, left) at the configuration of `tasks`' last evaluation.
pub(crate) fn arm_pivots(tasks: &LolaTasks, shoulders: &[usize; 2]) -> [ArmPivot; 2] {
    let (data, _) = tasks.kinematics();
    let t = &tasks.targets;
    [0, 1].map(|slot| {
        let arm = t.arm_cog[slot] - (data.world_pos[shoulders[slot]] - t.cog);
        ArmPivot {
            nominal: t.arm_cog[slot],
            arm,
            rho: (arm.x * arm.x + arm.z * arm.z).sqrt(),
        }
    })
}

/// Reference method: the swing offset of [`crate::momentum::ArmSwing`] moves the arm CoG fore-aft about the
/// *current* shoulder (relative to the CoG, planning frame, from the last evaluation) on a
/// circle of radius `rho` in the sagittal plane. A target fixed relative to the CoG would
/// make the arm chase the CoG shifts of the swinging legs and stretch the elbow into the
/// singularity of the 3-D arm CoG task.
pub(crate) fn swing_on_circle(arm: &mut PointTarget, p: &ArmPivot, shoulder: &Vector3<f64>) {
    let x = (p.arm.x + arm.position.x - p.nominal.x).clamp(-0.9 * p.rho, 0.9 * p.rho);
    let z = (p.rho * p.rho - x * x).sqrt();
    arm.position = shoulder + Vector3::new(x, p.arm.y, -z);
    arm.velocity.z = x * arm.velocity.x / z;
}

/// Diagonal weight: 1 except `lock` on the arm joints of `robot` (the `none` method).
pub(crate) fn arm_lock_weight(robot: &WalkRobot, lock: f64) -> Result<Weight, WalkError> {
    let mut d = DVector::from_element(robot.model.nv(), 1.0);
    for name in &robot.arm_joints {
        let l = robot.joint(name);
        let l = l.ok_or_else(|| model_err(format!("no joint {name}")))?;
        d[l.v_index] = lock;
    }
    Ok(Weight::Diagonal(d))
}
