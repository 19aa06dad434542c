//! A comfortable standing pose of the Lola model and the joint-limit/comfort cost H_J
//! (Fig. 4.2) over its 25 actuated joints.

use crate::error::IkError;
use crate::ik::joint_cost::{JointCost, JointCostEntry};
use biped_robots::lola::LolaModel;
use nalgebra::DVector;

/// Joint angles of the standing pose that differ from zero (bent knees, flat feet, arms
/// slightly bent: away from the limits at 0 of knees and elbows).
const STANDING: [(&str, f64); 12] = [
    ("l_thigh", -0.25),
    ("r_thigh", -0.25),
    ("l_shank", 0.5),
    ("r_shank", 0.5),
    ("l_ankle_cross", -0.25),
    ("r_ankle_cross", -0.25),
    ("l_upper_arm", 0.1),
    ("r_upper_arm", -0.1),
    ("l_forearm", -0.3),
    ("r_forearm", -0.3),
    ("l_shoulder", 0.0),
    ("r_shoulder", 0.0),
];

/// Standing configuration: base at the origin, upright, joints of `STANDING`; a joint
/// without a listed value sits at the middle of its range clamped to 0 where 0 is inside.
pub fn standing_configuration(lola: &LolaModel) -> DVector<f64> {
    let mut q = lola.model.neutral();
    for l in &lola.limits {
        let listed = STANDING.iter().find(|(n, _)| *n == l.name).map(|s| s.1);
        q[l.q_index] = listed.unwrap_or(0.0).clamp(l.lower, l.upper);
    }
    q
}

/// `H_J` over all actuated joints of `lola` with comfort pose `comfort` (a configuration).
pub fn lola_joint_cost(
    lola: &LolaModel,
    comfort: &DVector<f64>,
    w_comfort: f64,
    w_limit: f64,
    margin: f64,
) -> Result<JointCost, IkError> {
    let entries = lola
        .limits
        .iter()
        .map(|l| {
            let c = comfort.get(l.q_index).copied().ok_or(IkError::Dimension {
                what: "comfort configuration",
                expected: l.q_index + 1,
                got: comfort.len(),
            })?;
            Ok(JointCostEntry {
                q_index: l.q_index,
                v_index: l.v_index,
                lower: l.lower,
                upper: l.upper,
                comfort: c,
                w_comfort,
            })
        })
        .collect::<Result<Vec<_>, IkError>>()?;
    JointCost::new(entries, w_limit, margin)
}
