//! Initial poses: named joint angles, placing the robot on (or above) the ground.

use crate::error::SimError;
use crate::passive::EndStop;
use crate::plant::Plant;
use biped_dynamics::{update_placements, BodyId};
use nalgebra::DVector;

/// Hip and ankle adduction joints (left, right) of the sway motion.
#[derive(Debug, Clone, PartialEq)]
pub struct SwayJoints {
    /// Hip adduction joints (axis x), left and right.
    pub hips: [String; 2],
    /// Ankle adduction joints (axis x), left and right.
    pub ankles: [String; 2],
}

/// Lola's sway joints.
pub fn lola_sway_joints() -> SwayJoints {
    SwayJoints {
        hips: ["l_hip_adduction".into(), "r_hip_adduction".into()],
        ankles: ["l_foot".into(), "r_foot".into()],
    }
}

/// Lola's standing pose with knees bent by `bend` \[rad]: hip flexion and ankle flexion
/// `-bend / 2` keep the feet flat under the hips.
pub fn lola_pose(bend: f64) -> Vec<(String, f64)> {
    let mut p = Vec::new();
    for side in ["l", "r"] {
        p.push((format!("{side}_thigh"), -0.5 * bend));
        p.push((format!("{side}_shank"), bend));
        p.push((format!("{side}_ankle_cross"), -0.5 * bend));
    }
    p
}

/// Body whose joint is named `joint`.
fn joint_body(plant: &Plant, joint: &str) -> Result<BodyId, SimError> {
    plant
        .model()
        .bodies()
        .iter()
        .position(|b| b.joint_name() == joint)
        .ok_or_else(|| SimError::Unknown {
            kind: "joint",
            name: joint.to_string(),
        })
}

/// Body whose joint is the sway joint `joint` (an unknown name is an unknown "sway joint",
/// not a pose joint).
fn sway_joint_body(plant: &Plant, joint: &str) -> Result<BodyId, SimError> {
    joint_body(plant, joint).map_err(|_| SimError::Unknown {
        kind: "sway joint",
        name: joint.to_string(),
    })
}

/// Neutral configuration with the named one-DoF joint angles set and Type 3 motors at
/// `N q_link` (unloaded gears); every joint with end stops must start inside its range.
pub(super) fn configuration(
    plant: &Plant,
    pose: &[(String, f64)],
) -> Result<DVector<f64>, SimError> {
    let mut q = plant.model().neutral();
    for (name, angle) in pose {
        let b = joint_body(plant, name)?;
        let body = &plant.model().bodies()[b];
        if body.joint().nq() != 1 || !angle.is_finite() {
            return Err(SimError::InvalidParameter {
                what: format!("pose `{name}`"),
                reason: "needs a one-DoF joint and a finite angle".into(),
            });
        }
        q[body.q_index()] = *angle;
    }
    for g in plant.gears() {
        q[g.motor_q] = g.ratio * q[g.link_q];
    }
    within_stops(plant, &q)?;
    Ok(q)
}

/// Rejects a start pose with a joint beyond its end stops (the stop would fight the PD that
/// holds the pose for the whole run).
fn within_stops(plant: &Plant, q: &DVector<f64>) -> Result<(), SimError> {
    match outside_stops(plant, q) {
        Some(s) => Err(SimError::InvalidParameter {
            what: format!("pose `{}`", s.name),
            reason: format!(
                "starts at {} outside the joint range [{}, {}]: set it inside with the pose, \
                 or leave the end stops out",
                q[s.q], s.lower, s.upper
            ),
        }),
        None => Ok(()),
    }
}

/// The first joint with end stops whose coordinate in `q` lies outside its range.
fn outside_stops<'p>(plant: &'p Plant, q: &DVector<f64>) -> Option<&'p EndStop> {
    let inside = |s: &EndStop| (s.lower..=s.upper).contains(&q[s.q]);
    plant.passive().stops().iter().find(|s| !inside(s))
}

/// Rejects a sway amplitude that takes a sway joint beyond its end stops at either extreme
/// of the motion (`+-amplitude` on the hips, `-+amplitude` on the ankles about `q0`): the PD
/// would track a target the stop pushes back from.
pub(super) fn sway_within_stops(
    plant: &Plant,
    q0: &DVector<f64>,
    joints: &SwayJoints,
    amplitude: f64,
) -> Result<(), SimError> {
    let index =
        |name: &str| sway_joint_body(plant, name).map(|b| plant.model().bodies()[b].q_index());
    let hips = [index(&joints.hips[0])?, index(&joints.hips[1])?];
    let ankles = [index(&joints.ankles[0])?, index(&joints.ankles[1])?];
    for sign in [1.0, -1.0] {
        let mut q = q0.clone();
        hips.iter().for_each(|&i| q[i] += sign * amplitude);
        ankles.iter().for_each(|&i| q[i] -= sign * amplitude);
        if let Some(s) = outside_stops(plant, &q) {
            return Err(SimError::InvalidParameter {
                what: "sway amplitude".into(),
                reason: format!(
                    "{amplitude} rad takes `{}` to {} outside its range [{}, {}]: \
                     lower the amplitude or start from another pose",
                    s.name, q[s.q], s.lower, s.upper
                ),
            });
        }
    }
    Ok(())
}

/// Penetration of every contact point when the weight is shared equally by all points.
pub(super) fn static_penetration(plant: &Plant) -> f64 {
    let mass = plant.model().mass();
    let n = plant.contact().npoints().max(1) as f64;
    let w = mass * plant.model().gravity().norm();
    plant.contact().params().static_penetration(w / n)
}

/// Shifts the floating base vertically so that the lowest contact point is `lift` above the
/// ground (negative = penetration).
pub(super) fn place_on_ground(
    plant: &Plant,
    q: &mut DVector<f64>,
    lift: f64,
) -> Result<(), SimError> {
    let (qi, _) = plant
        .floating_base()
        .ok_or_else(|| SimError::Unsupported("scenarios need a floating base".into()))?;
    let low = plant
        .contact()
        .lowest_point(q.as_slice(), plant.layout().nv);
    q[qi + 2] += plant.contact().params().ground_height + lift - low;
    Ok(())
}

/// Height of the floating base origin in `q`.
pub(super) fn base_height(plant: &Plant, q: &DVector<f64>) -> f64 {
    plant.floating_base().map_or(0.0, |(qi, _)| q[qi + 2])
}

/// Vertical distance between the left hip and ankle joint origins at `q`.
pub(super) fn leg_length(
    plant: &mut Plant,
    q: &DVector<f64>,
    j: &SwayJoints,
) -> Result<f64, SimError> {
    let (hip, ankle) = (
        sway_joint_body(plant, &j.hips[0])?,
        sway_joint_body(plant, &j.ankles[0])?,
    );
    let (model, data) = plant.model_and_data();
    update_placements(model, data, q)?;
    Ok((data.world_pos[hip].z - data.world_pos[ankle].z).abs())
}
