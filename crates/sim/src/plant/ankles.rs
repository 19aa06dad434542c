//! The stance (ankle) joints of a floating plant, for IMU feedback through the ankles
//! ([`crate::controller::StanceDamping`]).

use super::Plant;
use crate::error::SimError;
use biped_dynamics::JointModel;
use nalgebra::{DVector, Vector3};

/// One ankle joint: the actuator driving it and its axis in the floating base's frame with the
/// base-vertical component removed (unit length before the removal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnkleAxis {
    /// Actuator index (plant order).
    pub actuator: usize,
    /// Horizontal part of the joint axis in the base frame at the pose of the query.
    pub axis: Vector3<f64>,
}

/// Cosine above which two ankle axes count as parallel (pitch and roll must differ).
const PARALLEL: f64 = 0.9;

/// Least horizontal part of an ankle axis (a yaw joint has none).
const HORIZONTAL: f64 = 0.5;

impl Plant {
    /// The ankles at `q`: for every foot (one per side, parts such as toes excluded: a toe
    /// joint is not an ankle), the first two actuated revolute joints up its chain whose axes
    /// are mostly horizontal and not parallel (pitch and roll). Empty without a floating base.
    pub fn ankle_axes(&mut self, q: &DVector<f64>) -> Result<Vec<AnkleAxis>, SimError> {
        let Some((_, vi)) = self.floating_base() else {
            return Ok(Vec::new());
        };
        biped_dynamics::update_placements(&self.model, &mut self.data, q)?;
        let bodies = self.model.bodies();
        let base = bodies
            .iter()
            .position(|b| b.owns_coordinates() && b.v_index() == vi)
            .unwrap_or(0);
        let to_base = self.data.world_rot[base].transpose();
        let mut out: Vec<AnkleAxis> = Vec::new();
        for foot in self.contact.side_bodies() {
            let first = out.len();
            let mut body = Some(foot);
            while let (Some(b), true) = (body, out.len() < first + 2) {
                body = bodies[b].parent();
                let JointModel::Revolute { axis } = bodies[b].joint() else {
                    continue;
                };
                let v = bodies[b].v_index();
                let Some(k) = self.actuators.iter().position(|a| a.joint_v == v) else {
                    continue;
                };
                let mut a = to_base * (self.data.world_rot[b] * axis.into_inner());
                a.z = 0.0;
                let parallel = out[first..]
                    .iter()
                    .any(|f| f.axis.dot(&a).abs() > PARALLEL * a.norm() * f.axis.norm());
                let taken = out.iter().any(|o| o.actuator == k);
                if a.norm() > HORIZONTAL && !parallel && !taken {
                    out.push(AnkleAxis {
                        actuator: k,
                        axis: a,
                    });
                }
            }
        }
        Ok(out)
    }
}
