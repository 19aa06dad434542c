//! World pose and velocity of one body by walking its joint chain from the root (2.33), so
//! that contact forces can be computed before the dynamics pass without a full kinematics
//! pass over all bodies. Supports the joints of a foot chain: free quaternion, revolute,
//! prismatic and fixed.

use crate::error::SimError;
use biped_dynamics::{BodyId, JointModel, Model};
use nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3};

/// One joint on the chain.
#[derive(Debug, Clone)]
enum Link {
    Free {
        q: usize,
        v: usize,
    },
    Revolute {
        axis: Unit<Vector3<f64>>,
        q: usize,
        v: usize,
    },
    Prismatic {
        axis: Vector3<f64>,
        q: usize,
        v: usize,
    },
    Fixed,
}

/// A joint with its placement in the parent frame.
#[derive(Debug, Clone)]
struct Step {
    link: Link,
    rot: Matrix3<f64>,
    trans: Vector3<f64>,
}

/// World pose and velocity of a body frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyState {
    /// Rotation body -> world (`A_IK`).
    pub rot: Matrix3<f64>,
    /// Origin in world coordinates.
    pub pos: Vector3<f64>,
    /// Angular velocity in world coordinates.
    pub omega: Vector3<f64>,
    /// Velocity of the origin in world coordinates.
    pub vel: Vector3<f64>,
}

impl BodyState {
    /// The world frame at rest.
    pub fn identity() -> Self {
        Self {
            rot: Matrix3::identity(),
            pos: Vector3::zeros(),
            omega: Vector3::zeros(),
            vel: Vector3::zeros(),
        }
    }

    /// World position and velocity of the body-fixed point `c` (body coordinates).
    #[inline]
    pub fn point(&self, c: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        let r = self.rot * c;
        (self.pos + r, self.vel + self.omega.cross(&r))
    }
}

/// The joints from the world to one body, root first.
#[derive(Debug, Clone)]
pub struct BodyChain {
    steps: Vec<Step>,
}

impl BodyChain {
    /// Chain of `body`; `Unsupported` if a joint on it is not free/revolute/prismatic/fixed.
    pub fn new(model: &Model, body: BodyId) -> Result<Self, SimError> {
        let mut steps = Vec::new();
        let mut cur = Some(body);
        while let Some(i) = cur {
            let b = model.body(i).ok_or_else(|| SimError::Unknown {
                kind: "body",
                name: format!("#{i}"),
            })?;
            let (q, v) = (b.q_index(), b.v_index());
            let link = match b.joint() {
                JointModel::FreeQuaternion => Link::Free { q, v },
                JointModel::Revolute { axis } => Link::Revolute { axis: *axis, q, v },
                JointModel::Prismatic { axis } => Link::Prismatic {
                    axis: axis.into_inner(),
                    q,
                    v,
                },
                JointModel::Fixed => Link::Fixed,
                other => {
                    return Err(SimError::Unsupported(format!(
                        "joint of body `{}` on a contact chain: {other:?}",
                        b.name()
                    )))
                }
            };
            let p = b.placement();
            steps.push(Step {
                link,
                rot: p.rotation.to_rotation_matrix().into_inner(),
                trans: p.translation.vector,
            });
            cur = b.parent();
        }
        steps.reverse();
        Ok(Self { steps })
    }

    /// Pose and velocity of the body at `(q, v)` (`v` of a free joint in body coordinates,
    /// `[linear; angular]`). The free-joint quaternion is normalised here.
    pub fn eval(&self, q: &[f64], v: &[f64]) -> BodyState {
        let mut s = BodyState::identity();
        for step in &self.steps {
            let rot_j = s.rot * step.rot;
            let origin = s.pos + s.rot * step.trans;
            let carried = s.vel + s.omega.cross(&(origin - s.pos));
            s = match &step.link {
                Link::Fixed => BodyState {
                    rot: rot_j,
                    pos: origin,
                    omega: s.omega,
                    vel: carried,
                },
                Link::Revolute { axis, q: qi, v: vi } => {
                    let rel = Rotation3::from_axis_angle(axis, q[*qi]).into_inner();
                    BodyState {
                        rot: rot_j * rel,
                        pos: origin,
                        omega: s.omega + rot_j * (axis.as_ref() * v[*vi]),
                        vel: carried,
                    }
                }
                Link::Prismatic { axis, q: qi, v: vi } => {
                    let a = rot_j * axis;
                    let pos = origin + a * q[*qi];
                    BodyState {
                        rot: rot_j,
                        pos,
                        omega: s.omega,
                        vel: s.vel + s.omega.cross(&(pos - s.pos)) + a * v[*vi],
                    }
                }
                Link::Free { q: qi, v: vi } => {
                    let quat =
                        nalgebra::Quaternion::new(q[qi + 6], q[qi + 3], q[qi + 4], q[qi + 5]);
                    let rel = UnitQuaternion::new_normalize(quat).to_rotation_matrix();
                    let rot = rot_j * rel.into_inner();
                    let pos = origin + rot_j * Vector3::new(q[*qi], q[qi + 1], q[qi + 2]);
                    let lin = Vector3::new(v[*vi], v[vi + 1], v[vi + 2]);
                    let ang = Vector3::new(v[vi + 3], v[vi + 4], v[vi + 5]);
                    BodyState {
                        rot,
                        pos,
                        omega: s.omega + rot * ang,
                        vel: s.vel + s.omega.cross(&(pos - s.pos)) + rot * lin,
                    }
                }
            };
        }
        s
    }
}
