//! The null-space term of an [`super::Ik`] step (4.12): the self-collision avoidance gradient
//! (ch. 5) and the angular momentum compensation `qdot_r` (7.3.2, (7.8)), evaluated at the
//! configuration of the step.

use crate::avoidance::CollisionAvoidance;
use crate::error::IkError;
use crate::momentum::{Compensation, VerticalMomentum};
use biped_dynamics::{Centroidal, Data, Jacobians, Model};
use nalgebra::DVector;

/// Vertical angular momentum compensation by the reducing joints.
#[derive(Debug, Clone)]
pub(super) struct MomentumTerm {
    pub comp: Compensation,
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

    /// Whether any term is on.
    pub fn is_on(&self) -> bool {
        self.avoidance.is_some() || self.momentum.is_some() || self.comfort.is_some()
    }

    /// `y` at `q` (with the previous step's joint velocities `qdot_prev` for the producing
    /// momentum); returns the smallest active segment distance, if any.
    pub fn evaluate(
        &mut self,
        model: &Model,
        q: &DVector<f64>,
        qdot_prev: &DVector<f64>,
    ) -> Result<Option<f64>, IkError> {
        self.grad.fill(0.0);
        if let Some(c) = &self.comfort {
            for &(qi, vi) in &c.joints {
                self.grad[vi] += c.gain * (q[qi] - c.q0[qi]);
            }
        }
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
            (m.comp
                .add_to(m.vm.jacobian_z(), qdot_prev, m.target, &mut self.grad))
            .map_err(|e| err(what, e))?;
        }
        Ok(min_distance)
    }
}
