//! The limit and self-collision verdicts of the simulated walk: over every recorded cycle, the
//! smallest distance of a ranged joint to its nearer limit (the plant's end stops let a joint
//! press slightly past its range, which shows as a negative margin) and the smallest SSV
//! distance of the robot's collision pairs at the simulated poses (negative: interpenetration).

use super::summary::DynamicWalkSeries;
use crate::avoidance::{AvoidanceParams, CollisionAvoidance};
use crate::walk::error::{model_err, WalkError};
use crate::walk::robot::WalkRobot;
use biped_dynamics::{update_placements, Data};
use nalgebra::DVector;

/// Smallest joint margin and SSV distance of the simulated motion, with where they occur.
#[derive(Debug, Clone, PartialEq)]
pub struct SimulatedMargins {
    /// Smallest `min(q - lower, upper - q)` over the ranged joints and cycles \[rad or m].
    pub joint_margin: f64,
    /// The joint of that margin.
    pub joint: String,
    /// Smallest SSV distance over the collision pairs and cycles \[m].
    pub distance: f64,
    /// The segment pair of that distance (`a and b`).
    pub pair: String,
}

/// The margins of the series `s` (positions of the plant, whose coordinates are `robot`'s).
pub fn simulated_margins(
    robot: &WalkRobot,
    s: &DynamicWalkSeries,
) -> Result<SimulatedMargins, WalkError> {
    let model = &robot.model;
    let nq = s.q_names.len();
    if nq != model.nq() {
        return Err(model_err(
            "the series' coordinates are not the walk model's",
        ));
    }
    let params = AvoidanceParams::default();
    let mut avoid = CollisionAvoidance::new(model, robot.collision.clone(), params)?;
    let mut data = Data::new(model);
    let mut q = DVector::zeros(nq);
    let mut m = SimulatedMargins {
        joint_margin: f64::INFINITY,
        joint: String::new(),
        distance: f64::INFINITY,
        pair: String::new(),
    };
    let (mut worst_joint, mut worst_pair) = (None, None);
    for row in s.q.chunks_exact(nq) {
        q.copy_from_slice(row);
        for (k, j) in robot.joints.iter().enumerate() {
            let margin = (q[j.q_index] - j.lower).min(j.upper - q[j.q_index]);
            if margin < m.joint_margin {
                (m.joint_margin, worst_joint) = (margin, Some(k));
            }
        }
        update_placements(model, &mut data, &q).map_err(model_err)?;
        avoid.update(&data)?;
        if let Some((pair, c)) = avoid.global_minimum() {
            if c.result.distance < m.distance {
                (m.distance, worst_pair) = (c.result.distance, Some(pair));
            }
        }
    }
    if let Some(k) = worst_joint {
        m.joint = robot.joints[k].name.clone();
    }
    if let Some(i) = worst_pair {
        let c = avoid.collision_model();
        let (p, segments) = (&c.pairs()[i], c.segments());
        m.pair = format!("{} and {}", segments[p.a].name(), segments[p.b].name());
    }
    Ok(m)
}
