//! Placement of the walking posture on the pattern's footprints, the `none` method's arm lock
//! and the reference method's arm swing about the shoulder (see the module docs of
//! [`super`]; the Lola-like biped's posture itself is in `robot::lola_posture`).

use super::error::{model_err, WalkError};
use super::robot::{frame_position, WalkRobot};
use crate::ik::Weight;
use crate::momentum::PointTarget;
use crate::pattern::PatternSample;
use crate::tasks::LolaTasks;
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
