//! The joint limits and the joint cost `H_J` of a [`WalkRobot`]'s walking IK.

use crate::ik::joint_cost::{JointCost, JointCostEntry};
use crate::ik::{JointLimits, JointRange};
use crate::walk::error::WalkError;
use crate::walk::method::WalkParams;
use crate::walk::robot::WalkRobot;
use nalgebra::DVector;

/// Hard limits of every ranged joint of `robot` with the settings of `params`.
pub(super) fn joint_limits(
    robot: &WalkRobot,
    params: &WalkParams,
) -> Result<JointLimits, WalkError> {
    let ranges = robot
        .joints
        .iter()
        .map(|l| JointRange {
            q_index: l.q_index,
            v_index: l.v_index,
            lower: l.lower,
            upper: l.upper,
        })
        .collect();
    Ok(JointLimits::new(ranges, params.limits)?)
}

/// `H_J` over the ranged joints of `robot` with comfort pose `comfort` (a configuration).
pub(super) fn joint_cost(
    robot: &WalkRobot,
    comfort: &DVector<f64>,
    w_comfort: f64,
    w_limit: f64,
    margin: f64,
) -> Result<JointCost, WalkError> {
    let entries = robot
        .joints
        .iter()
        .map(|l| JointCostEntry {
            q_index: l.q_index,
            v_index: l.v_index,
            lower: l.lower,
            upper: l.upper,
            comfort: comfort[l.q_index],
            w_comfort,
        })
        .collect();
    Ok(JointCost::new(entries, w_limit, margin)?)
}
