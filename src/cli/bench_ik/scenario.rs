//! The benchmarked IK problem: both feet pose, CoM and pelvis orientation (hard), a soft
//! posture task (or the comfort term), joint position and velocity limits; the CoM sways sideways and the left foot steps
//! (`scripts/ik_peers.py`'s `targets()`), integrated over steps of 1 ms. The full set adds
//! self-collision avoidance on the robot's SSV model and vertical momentum compensation by the
//! description's reducing joints.

use super::bounds::JointBounds;
use biped_control::avoidance::RepulsiveLaw;
use biped_control::tasks::{Frame, TaskHandle, TaskKind};
use biped_control::whole_body::{Ik, StepReport};
use biped_dynamics::{center_of_mass, Data};
use biped_robots::description::Robot;
use nalgebra::{DVector, Isometry3, Matrix3, Vector3};
use std::f64::consts::PI;

/// Integration step \[s] (a 1 kHz control cycle).
pub const DT: f64 = 1e-3;
/// Period of the left foot's step \[s]; its target jumps back to the start at each period.
const STEP_PERIOD: f64 = 0.8;
/// Weight of the soft posture task (the hard tasks are kept exactly while the limits allow).
const POSTURE_WEIGHT: f64 = 1e-2;
/// Gain `[1/s]` of the comfort term that replaces the posture task with `--posture comfort`.
const COMFORT_GAIN: f64 = 10.0;
/// Gain of the self-collision avoidance term (as in the allocation test of `Ik`).
const AVOIDANCE_GAIN: f64 = 100.0;

/// Which task set is solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TaskSet {
    /// Feet, CoM, pelvis orientation, posture and joint limits (what the peers solve).
    Peer,
    /// The peer set plus self-collision avoidance and momentum compensation.
    Full,
}

/// How the joints are pulled towards the start pose.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Posture {
    /// A soft posture task, as the peers' posture task (folded into the joint weight).
    Task,
    /// The comfort gradient in the null space of the tasks (never competes with the tasks).
    Comfort,
}

/// The CoM and left-foot targets of cycle `k` (`targets()` of `scripts/ik_peers.py`).
pub fn targets(
    k: usize,
    com0: &Vector3<f64>,
    foot0: &Vector3<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    let t = k as f64 * DT;
    let com = com0 + Vector3::new(0.05 * t, 0.04 * (2.0 * PI * t / 1.6).sin(), 0.0);
    let phase = ((t % STEP_PERIOD) / STEP_PERIOD).clamp(0.0, 1.0);
    let foot = foot0 + Vector3::new(0.1 * phase, 0.0, 0.05 * (PI * phase).sin());
    (com, foot)
}

/// Cycles after a jump of the foot target (and at the start) not counted in the tracking
/// check: the jump of 0.1 m takes the velocity-limited legs a few dozen cycles.
pub const SETTLE_CYCLES: usize = 150;

/// Whether cycle `k` is far enough from a jump of the foot target to be tracked.
pub fn settled(k: usize) -> bool {
    let period = (STEP_PERIOD / DT).round() as usize;
    k < period || k % period >= SETTLE_CYCLES
}

/// The IK of one task set on a robot, its configuration and the targets it moves.
pub struct Scenario {
    /// The IK.
    pub ik: Ik,
    /// The current configuration.
    pub q: DVector<f64>,
    data: Data,
    feet: [(TaskHandle, Frame, Isometry3<f64>); 2],
    com: (TaskHandle, Vector3<f64>),
    pelvis: (Frame, Matrix3<f64>),
    bounds: JointBounds,
}

/// Tracking errors of one cycle after its step.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Errors {
    /// Largest foot position error \[m].
    pub position: f64,
    /// Largest foot or pelvis orientation error \[rad].
    pub orientation: f64,
    /// CoM position error \[m].
    pub com: f64,
}

fn pose(data: &Data, f: &Frame) -> Isometry3<f64> {
    data.body_pose(f.body) * f.offset
}

fn angle(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    let c = ((a.transpose() * b).trace() - 1.0) / 2.0;
    c.clamp(-1.0, 1.0).acos()
}

impl Scenario {
    /// Builds task set `set` on `robot`, starting at its comfort pose (bent knees: a straight
    /// leg is singular for vertical foot motion).
    pub fn new(robot: &Robot, set: TaskSet, posture: Posture) -> Result<Self, String> {
        let model = &robot.urdf.model;
        let q = robot.comfort.clone();
        let mut data = Data::new(model);
        let com0 = center_of_mass(model, &mut data, &q, None)
            .map_err(|e| format!("centre of mass: {e}"))?
            .position;
        let mut ik = Ik::new(&robot.urdf).map_err(|e| e.to_string())?;
        let mut foot = |name: &str| -> Result<_, String> {
            let frame = ik.frame(name).map_err(|e| format!("foot frame: {e}"))?;
            let target = pose(&data, &frame);
            let h = ik.frame_pose(name, target).map_err(|e| e.to_string())?;
            Ok((h, frame, target))
        };
        let feet = [
            foot(&robot.description.feet[0].frame)?,
            foot(&robot.description.feet[1].frame)?,
        ];
        let com = ik.com(com0).map_err(|e| e.to_string())?;
        let root = (robot.urdf.links.first()).ok_or("the URDF has no link")?;
        let frame = ik.frame(&root.link).map_err(|e| e.to_string())?;
        let pelvis = pose(&data, &frame)
            .rotation
            .to_rotation_matrix()
            .into_inner();
        ik.frame_orientation(&root.link, pelvis)
            .map_err(|e| e.to_string())?;
        match posture {
            Posture::Task => ik.posture(&q, POSTURE_WEIGHT).map(|_| ()),
            Posture::Comfort => ik.comfort(&q, COMFORT_GAIN),
        }
        .map_err(|e| e.to_string())?;
        if set == TaskSet::Full {
            add_full_terms(robot, &mut ik)?;
        }
        let bounds = JointBounds::new(robot, &ik, &q);
        Ok(Self {
            ik,
            q,
            data,
            feet,
            com: (com, com0),
            pelvis: (frame, pelvis),
            bounds,
        })
    }

    /// Moves the targets to cycle `k` and makes one IK step of [`DT`].
    pub fn step(&mut self, k: usize) -> Result<StepReport, String> {
        let (com, foot) = targets(k, &self.com.1, &self.feet[0].2.translation.vector);
        if let Ok(task) = self.ik.task_mut(self.com.0) {
            if let TaskKind::Com { target } = &mut task.kind {
                *target = com;
            }
        }
        if let Ok(task) = self.ik.task_mut(self.feet[0].0) {
            if let TaskKind::Pose { target, .. } = &mut task.kind {
                target.translation.vector = foot;
            }
        }
        self.ik.step(&mut self.q, DT).map_err(|e| e.to_string())
    }

    /// Tracking errors at the current configuration against the targets of cycle `k`.
    pub fn errors(&mut self, k: usize) -> Result<Errors, String> {
        let model = self.ik.tasks().model();
        let c = center_of_mass(model, &mut self.data, &self.q, None)
            .map_err(|e| format!("centre of mass: {e}"))?;
        let (com, foot) = targets(k, &self.com.1, &self.feet[0].2.translation.vector);
        let mut e = Errors {
            com: (c.position - com).norm(),
            ..Errors::default()
        };
        for (i, (_, frame, start)) in self.feet.iter().enumerate() {
            let now = pose(&self.data, frame);
            let want = if i == 0 {
                foot
            } else {
                start.translation.vector
            };
            e.position = e.position.max((now.translation.vector - want).norm());
            let (a, b) = (
                now.rotation.to_rotation_matrix(),
                start.rotation.to_rotation_matrix(),
            );
            e.orientation = e.orientation.max(angle(a.matrix(), b.matrix()));
        }
        let now = pose(&self.data, &self.pelvis.0)
            .rotation
            .to_rotation_matrix();
        e.orientation = e.orientation.max(angle(now.matrix(), &self.pelvis.1));
        Ok(e)
    }

    /// Smallest distance of a joint to its range now, or an error naming the joint that
    /// came closer than allowed (see [`JointBounds`]).
    pub fn check_limits(&self, slack: f64) -> Result<f64, String> {
        self.bounds.check(&self.q, slack)
    }

    /// Largest excess of a joint velocity of the last step over its limit (<= 0: kept).
    pub fn velocity_excess(&self) -> f64 {
        let Some(qdot) = self.ik.velocities() else {
            return 0.0;
        };
        let limits = self.ik.limits();
        (limits.ranges().iter().zip(limits.velocity_limits()))
            .map(|(r, v)| qdot[r.v_index].abs() - v)
            .fold(f64::NEG_INFINITY, f64::max)
    }
}

/// Self-collision avoidance on the robot's SSV model and momentum compensation by its reducing
/// joints; an error if the description has no collision model or no reducing joint.
fn add_full_terms(robot: &Robot, ik: &mut Ik) -> Result<(), String> {
    let file = &robot.description.file;
    let collision = robot.collision.as_ref().ok_or_else(|| {
        format!(
            "{file}: no [collision] model: the full task set needs one (`biped ssv fit` makes one)"
        )
    })?;
    let law = RepulsiveLaw::Blended { s0: 1.0, t: 0.5 };
    ik.avoid_self_collision(collision.model.clone(), law, AVOIDANCE_GAIN)
        .map_err(|e| format!("{file}: {e}"))?;
    let reducing: Vec<&str> = robot
        .description
        .reducing
        .iter()
        .map(String::as_str)
        .collect();
    if reducing.is_empty() {
        return Err(format!(
            "{file}: [momentum] reducing is empty: the full task set needs reducing joints"
        ));
    }
    ik.compensate_momentum(&reducing)
        .map_err(|e| format!("{file}: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn targets_follow_the_peer_script() {
        let (c0, f0) = (Vector3::new(0.1, 0.2, 0.3), Vector3::new(-0.1, 0.1, -0.7));
        // t = 0.2 s: a quarter of the sway period 1.6 s is 0.4 s, a quarter of the step 0.8 s
        let (c, f) = targets(200, &c0, &f0);
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert!((c - c0 - Vector3::new(0.01, 0.04 * s, 0.0)).norm() < 1e-12);
        assert!((f - f0 - Vector3::new(0.025, 0.0, 0.05 * s)).norm() < 1e-12);
        // t = 1.2 s: sway at its right extreme, the second step half done
        let (c, f) = targets(1200, &c0, &f0);
        assert!((c - c0 - Vector3::new(0.06, -0.04, 0.0)).norm() < 1e-12);
        assert!((f - f0 - Vector3::new(0.05, 0.0, 0.05)).norm() < 1e-12);
    }

    #[test]
    fn cycles_right_after_a_foot_jump_are_not_tracked() {
        assert!(settled(0) && settled(799));
        assert!(!settled(800) && !settled(949));
        assert!(settled(950) && settled(1599) && !settled(1600));
    }
}
