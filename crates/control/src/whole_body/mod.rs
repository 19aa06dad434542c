//! [`Ik`]: whole-body differential IK on any URDF model in a few lines, with the joint
//! position and velocity limits of the URDF kept by default.
//!
//! Tasks are added by frame (URDF link) or joint name and stacked in a
//! [`crate::tasks::TaskStack`]; each [`Ik::step`] is one closed-loop RMRC cycle (4.13)-(4.16)
//! whose joint velocities stay inside the box of [`crate::ik::limits`] by saturation in the null
//! space ([`crate::ik::saturation`]): every joint with a URDF range stays `margin` inside it and
//! below its `<limit velocity>` (or `LimitSettings::max_velocity` where the URDF gives none).
//! Joints without a range (continuous) are not limited. Added tasks are hard (kept exactly
//! while the limits allow) unless given a weight; [`Ik::posture`] is soft (its rows are folded
//! into the joint weight of the solve, [`crate::ik::Rmrc::set_unit_rows`]).
//!
//! Optional null-space terms (4.12), evaluated at each step's configuration: a comfort pose
//! ([`Ik::comfort`], the comfort part of H_J), self-collision avoidance on an SSV model
//! ([`Ik::avoid_self_collision`], ch. 5) and the vertical angular momentum compensation by
//! named reducing joints ([`Ik::compensate_momentum`], 7.3.2).
//!
//! # Example
//!
//! The G1's left foot 5 cm up, the right foot held, with the URDF's limits kept:
//!
//! ```
//! use biped_control::whole_body::Ik;
//! use biped_dynamics::urdf::{load_file, UrdfOptions};
//! use biped_dynamics::{update_placements, Data};
//! use nalgebra::Translation3;
//!
//! let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../dynamics/data/g1_29dof_rev_1_0.urdf");
//! let g1 = load_file(path, &UrdfOptions { floating: true, ..Default::default() })?;
//! let mut ik = Ik::new(&g1)?;
//! let mut q = g1.model.neutral();
//! q[ik.joint_index("left_knee_joint")?.0] = 0.5; // bent: not singular for vertical motion
//! let mut data = Data::new(&g1.model);
//! update_placements(&g1.model, &mut data, &q)?;
//! let pose = |data: &Data, link| data.body_pose(g1.model.body_id(link).unwrap());
//! let target = Translation3::new(0.0, 0.0, 0.05) * pose(&data, "left_ankle_roll_link");
//! ik.frame_pose("left_ankle_roll_link", target)?;
//! ik.frame_pose("right_ankle_roll_link", pose(&data, "right_ankle_roll_link"))?;
//! for _ in 0..100 {
//!     ik.step(&mut q, 0.01)?;
//! }
//! update_placements(&g1.model, &mut data, &q)?;
//! let moved = pose(&data, "left_ankle_roll_link").translation.vector - target.translation.vector;
//! assert!(moved.norm() < 1e-6);
//! assert!(ik.limits().min_margin(&q) >= ik.limits().settings().margin - 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod add;
#[cfg(test)]
mod fold_tests;
mod null_space;

use crate::error::IkError;
use crate::ik::differential::{ClosedLoopIk, CycleInput};
use crate::ik::limits::{JointLimits, JointRange, LimitSettings};
use crate::ik::saturation::SaturationReport;
use crate::ik::task_map::TaskMap;
use crate::ik::weight::Weight;
use crate::tasks::{Frame, Task, TaskHandle, TaskStack};
use biped_dynamics::urdf::UrdfModel;
use nalgebra::DVector;
use null_space::NullSpace;

/// Tuning of [`Ik::step`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IkOptions {
    /// Fraction `K_x dt` of the task error removed per step (in `(0, 2)`; default 0.5).
    pub error_fraction: f64,
    /// Damping `lambda^2` of the solve (damped least squares, 4.4; default 1e-8).
    pub damping: f64,
}

impl Default for IkOptions {
    fn default() -> Self {
        Self {
            error_fraction: 0.5,
            damping: 1e-8,
        }
    }
}

/// What one [`Ik::step`] did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepReport {
    /// Norm of the task error before the step.
    pub error_norm: f64,
    /// Joints held at their limit box by the saturation.
    pub saturation: SaturationReport,
    /// Smallest distance of a segment pair within the activation distance before the step
    /// (`None` without self-collision avoidance or when no pair is that close).
    pub min_distance: Option<f64>,
}

/// Differential IK on a URDF model with joint limits on (see the module docs).
#[derive(Debug, Clone)]
pub struct Ik {
    stack: TaskStack,
    links: Vec<(String, Frame)>,
    joints: Vec<(String, usize, usize)>,
    limits: JointLimits,
    solver: Option<ClosedLoopIk>,
    weight: Weight,
    null_space: NullSpace,
    /// Step tuning.
    pub options: IkOptions,
}

impl Ik {
    /// IK on `urdf` with the default [`LimitSettings`] (0.01 margin) but a regularisation of
    /// `1e-6` (the damping of the walking IK, 1e-3, would leave hard tasks short of their
    /// targets by ~1e-4 against a soft posture).
    pub fn new(urdf: &UrdfModel) -> Result<Self, IkError> {
        let settings = LimitSettings {
            regularisation: 1e-6,
            ..LimitSettings::default()
        };
        Self::with_limits(urdf, settings)
    }

    /// IK on `urdf` keeping its joint ranges and velocity limits with `settings`.
    pub fn with_limits(urdf: &UrdfModel, settings: LimitSettings) -> Result<Self, IkError> {
        let model = &urdf.model;
        let mut ranges = Vec::new();
        let mut velocities = Vec::new();
        let mut joints = Vec::new();
        for j in &urdf.joints {
            let b = model
                .body(j.body)
                .ok_or(IkError::UnknownName(j.name.clone()))?;
            let (qi, vi) = (b.q_index(), b.v_index());
            joints.push((j.name.clone(), qi, vi));
            if let Some([lower, upper]) = j.range.filter(|r| r[0].is_finite() && r[1].is_finite()) {
                ranges.push(JointRange {
                    q_index: qi,
                    v_index: vi,
                    lower,
                    upper,
                });
                if let Some(v) = j.velocity {
                    velocities.push((vi, v));
                }
            }
        }
        let limits = JointLimits::new(ranges, settings)?.with_velocities(&velocities)?;
        let links = urdf
            .links
            .iter()
            .filter_map(|l| {
                let frame = Frame {
                    body: l.body?,
                    offset: l.pose,
                };
                Some((l.link.clone(), frame))
            })
            .collect();
        Ok(Self {
            stack: TaskStack::new(model),
            links,
            joints,
            limits,
            solver: None,
            weight: Weight::Identity,
            null_space: NullSpace::new(model),
            options: IkOptions::default(),
        })
    }

    /// The frame of URDF link `name` (its body and pose in the body).
    pub fn frame(&self, name: &str) -> Result<Frame, IkError> {
        let found = self.links.iter().find(|(n, _)| n == name);
        found
            .map(|(_, f)| *f)
            .ok_or_else(|| IkError::UnknownName(name.to_string()))
    }

    /// `(q_index, v_index)` of URDF joint `name`.
    pub fn joint_index(&self, name: &str) -> Result<(usize, usize), IkError> {
        let found = self.joints.iter().find(|(n, _, _)| n == name);
        found
            .map(|&(_, qi, vi)| (qi, vi))
            .ok_or_else(|| IkError::UnknownName(name.to_string()))
    }

    /// The task stack (targets, weights and kinematics of the last step).
    pub fn tasks(&self) -> &TaskStack {
        &self.stack
    }

    /// Task `h`, e.g. to move its target.
    pub fn task_mut(&mut self, h: TaskHandle) -> Result<&mut Task, IkError> {
        let n = self.stack.tasks().len();
        self.stack.task_mut(h).ok_or(IkError::Dimension {
            what: "task handle",
            expected: n,
            got: h.0,
        })
    }

    /// The joint limits kept.
    pub fn limits(&self) -> &JointLimits {
        &self.limits
    }

    /// Adds any task (the solver is resized at the next step).
    pub fn add(&mut self, task: Task) -> Result<TaskHandle, IkError> {
        self.solver = None;
        self.stack.push(task)
    }

    /// One closed-loop cycle of length `dt`: the joint velocities that remove
    /// `error_fraction` of the task error, inside the joint limits, integrated into `q`.
    pub fn step(&mut self, q: &mut DVector<f64>, dt: f64) -> Result<StepReport, IkError> {
        let f = self.options.error_fraction;
        if !(dt > 0.0 && dt.is_finite() && f > 0.0 && f < 2.0) {
            return Err(IkError::InvalidParameter {
                name: "dt / error_fraction",
                reason: "need dt > 0 and 0 < error_fraction < 2",
            });
        }
        crate::ik::linalg::check_dim("q", self.stack.nq(), q.len())?;
        if self.solver.is_none() {
            self.solver = Some(ClosedLoopIk::with_limits(&self.stack, self.limits.clone())?);
        }
        let solver = self.solver.as_mut().ok_or(IkError::NotPositiveDefinite)?;
        let model = self.stack.model();
        let min_distance = self.null_space.evaluate(model, q)?;
        let input = CycleInput {
            gain: f / dt,
            weight: &self.weight,
            null_space: self
                .null_space
                .is_on()
                .then_some((&self.null_space.grad, 1.0)),
            damping: self.options.damping,
            dt,
        };
        solver.velocities(&mut self.stack, q, &input)?;
        if let Some(m) = &mut self.null_space.momentum {
            let (jlz, target) = (m.vm.jacobian_z(), m.target);
            solver.correct(&self.stack, &input, |sns, p, qdot| {
                m.comp.apply(sns, p, jlz, target, qdot)
            })?;
        }
        solver.integrate(&self.stack, q, dt)?;
        Ok(StepReport {
            error_norm: solver.tasks.error_norm(),
            saturation: solver.limits().map(|s| s.report()).unwrap_or_default(),
            min_distance,
        })
    }

    /// Joint velocities of the last step.
    pub fn velocities(&self) -> Option<&DVector<f64>> {
        self.solver.as_ref().map(|s| &s.qdot)
    }
}
