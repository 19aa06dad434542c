//! The null-space term of an [`super::Ik`] step (4.12) and the methods that switch its parts
//! on: a comfort pose, the self-collision avoidance gradient (ch. 5) and the angular momentum
//! compensation (7.3.2), evaluated at the configuration of the step; the compensation adds
//! its term after the step's solve ([`crate::momentum::InCycleCompensation`]).

use super::Ik;
use crate::avoidance::{AvoidanceParams, CollisionAvoidance, RepulsiveLaw};
use crate::error::IkError;
use crate::ik::TaskMap;
use crate::momentum::{Compensation, InCycleCompensation, VerticalMomentum};
use biped_dynamics::{Centroidal, Data, Jacobians, Model};
use biped_ssv::CollisionModel;
use nalgebra::DVector;

/// Vertical angular momentum compensation by the reducing joints.
#[derive(Debug, Clone)]
pub(super) struct MomentumTerm {
    pub comp: InCycleCompensation,
    pub cen: Centroidal,
    pub vm: VerticalMomentum,
    /// Desired `L_z` \[N m s].
    pub target: f64,
}

/// Comfort cost `gain / 2 sum (q_i - q0_i)^2` over the joints `(q_index, v_index)`.
#[derive(Debug, Clone)]
pub(super) struct ComfortTerm {
    pub joints: Vec<(usize, usize)>,
    pub q0: DVector<f64>,
    pub gain: f64,
}

/// Buffers and parts of the null-space term.
#[derive(Debug, Clone)]
pub(super) struct NullSpace {
    data: Data,
    jac: Jacobians,
    /// `y` of (4.12) with `alpha_N = 1`.
    pub grad: DVector<f64>,
    /// Avoidance and its gain `alpha_N`.
    pub avoidance: Option<(CollisionAvoidance, f64)>,
    /// Momentum compensation.
    pub momentum: Option<MomentumTerm>,
    /// Comfort pose.
    pub comfort: Option<ComfortTerm>,
}

fn err(what: &str, e: impl std::fmt::Display) -> IkError {
    IkError::Kinematics(format!("{what}: {e}"))
}

impl NullSpace {
    /// Empty (no term) for `model`.
    pub fn new(model: &Model) -> Self {
        Self {
            data: Data::new(model),
            jac: Jacobians::new(model),
            grad: DVector::zeros(model.nv()),
            avoidance: None,
            momentum: None,
            comfort: None,
        }
    }

    /// Whether any gradient term is on (the compensation adds no gradient).
    pub fn is_on(&self) -> bool {
        self.avoidance.is_some() || self.comfort.is_some()
    }

    /// `y` at `q` (and `J_Lz` for the compensation); returns the smallest active segment
    /// distance, if any.
    pub fn evaluate(&mut self, model: &Model, q: &DVector<f64>) -> Result<Option<f64>, IkError> {
        self.grad.fill(0.0);
        let min_distance = self.evaluate_dynamic_terms(model, q)?;
        // after the avoidance term, which scales the gradient by its gain
        if let Some(c) = &self.comfort {
            for &(qi, vi) in &c.joints {
                self.grad[vi] += c.gain * (q[qi] - c.q0[qi]);
            }
        }
        Ok(min_distance)
    }

    /// Adds the avoidance part of `y` and updates `J_Lz` (the parts that need the Jacobians).
    fn evaluate_dynamic_terms(
        &mut self,
        model: &Model,
        q: &DVector<f64>,
    ) -> Result<Option<f64>, IkError> {
        if self.avoidance.is_none() && self.momentum.is_none() {
            return Ok(None);
        }
        let what = "null-space term";
        self.jac
            .compute(model, &mut self.data, q)
            .map_err(|e| err(what, e))?;
        let mut min_distance = None;
        if let Some((avoid, gain)) = &mut self.avoidance {
            let what = "self-collision avoidance";
            let summary = (avoid.gradient(model, &self.data, &self.jac, &mut self.grad))
                .map_err(|e| err(what, e))?;
            self.grad *= *gain;
            min_distance = summary.min_distance;
        }
        if let Some(m) = &mut self.momentum {
            let what = "momentum compensation";
            m.cen
                .compute_matrix_with(model, &self.data, &self.jac)
                .map_err(|e| err(what, e))?;
            m.vm.update(&m.cen).map_err(|e| err(what, e))?;
        }
        Ok(min_distance)
    }
}

impl Ik {
    /// Keeps the robot's segments apart: each step adds `gain` times the gradient of the
    /// repulsive potential `law` of the pairs of `collision` closer than its activation
    /// distance (5.5)-(5.9) as null-space term (4.12). `collision` names its bodies after the
    /// model's (as `biped ssv fit` writes them).
    pub fn avoid_self_collision(
        &mut self,
        collision: CollisionModel,
        law: RepulsiveLaw,
        gain: f64,
    ) -> Result<(), IkError> {
        if !(gain > 0.0 && gain.is_finite()) {
            return Err(IkError::InvalidParameter {
                name: "avoidance gain",
                reason: "must be finite and > 0",
            });
        }
        let model = self.stack.model();
        let avoid = CollisionAvoidance::new(model, collision, AvoidanceParams { law })
            .map_err(|e| IkError::Kinematics(format!("self-collision avoidance: {e}")))?;
        self.null_space.avoidance = Some((avoid, gain));
        Ok(())
    }

    /// Compensates the vertical angular momentum with the `reducing` joints (7.3.2): after
    /// each step's solve their motion along `J_{L,r,z}^T`, with the tasks' reaction, sets
    /// `L_z` to the target of [`Self::set_momentum_target`] (default 0), the term's joint
    /// speeds capped at the limits' velocity limit ([`crate::momentum::in_cycle`]).
    pub fn compensate_momentum(&mut self, reducing: &[&str]) -> Result<(), IkError> {
        let model = self.stack.model();
        let comp = Compensation::new(model, reducing)
            .map_err(|e| IkError::Kinematics(format!("momentum compensation: {e}")))?;
        let speed = self.limits.settings().max_velocity;
        let comp = InCycleCompensation::new(comp, self.stack.max_rows(), speed)?;
        self.null_space.momentum = Some(MomentumTerm {
            comp,
            cen: Centroidal::new(model),
            vm: VerticalMomentum::new(model),
            target: 0.0,
        });
        Ok(())
    }

    /// Moves every joint with a range towards its entry in `q0` in the null space of the tasks
    /// (the comfort part of H_J, Fig. 4.2): the gradient `gain (q - q0)` joins the null-space
    /// term. Unlike [`Self::posture`] it never competes with the tasks.
    pub fn comfort(&mut self, q0: &DVector<f64>, gain: f64) -> Result<(), IkError> {
        crate::ik::linalg::check_dim("comfort pose", self.stack.nq(), q0.len())?;
        if !(gain > 0.0 && gain.is_finite()) {
            return Err(IkError::InvalidParameter {
                name: "comfort gain",
                reason: "must be finite and > 0",
            });
        }
        let joints = (self.limits.ranges().iter())
            .map(|r| (r.q_index, r.v_index))
            .collect();
        self.null_space.comfort = Some(ComfortTerm {
            joints,
            q0: q0.clone(),
            gain,
        });
        Ok(())
    }

    /// The desired vertical angular momentum `L_d` of the compensation \[N m s].
    pub fn set_momentum_target(&mut self, lz: f64) {
        if let Some(m) = &mut self.null_space.momentum {
            m.target = lz;
        }
    }
}
