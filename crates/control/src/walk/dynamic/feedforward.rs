//! Feedforward torques of the planned motion: inverse dynamics (RNEA) of the floating-base
//! model with the ground wrench the motion needs distributed over the support feet.
//!
//! The free-joint entries of RNEA at `(q, qd, qdd)` without external forces are the wrench the
//! ground must supply (see [`crate::walk::evaluate`]). In single support the stance foot takes
//! all of it; in double support it is split by the position of the motion's own ZMP between
//! the feet ([`Feedforward::foot_wrenches`]). A foot in toe-off ([`Contact::Toe`]: heel up,
//! toe segment flat) carries its share on the toe segment, so the toe joint's feedforward holds
//! the load the ground puts on the toe. With these wrenches as
//! `f_ext` RNEA's free-joint entries vanish and its joint entries are the actuated joints'
//! torques (`tau = M qdd + h - J^T f_ext`).

use crate::pattern::{Contact, PatternSample, Phase};
use crate::walk::error::{model_err, WalkError};
use crate::walk::evaluate::{body, floating_root, wrench};
use biped_dynamics::{inverse_dynamics, BodyId, Data, Model, Wrench};
use biped_robots::lola::LolaModel;
use nalgebra::{DVector, Vector2, Vector3};

/// Preallocated RNEA feedforward (own dynamics workspace).
#[derive(Debug, Clone)]
pub struct Feedforward {
    model: Model,
    data: Data,
    root: BodyId,
    feet: [BodyId; 2],
    toes: Option<[BodyId; 2]>,
    fext: Vec<Wrench>,
    ground: (Vector3<f64>, Vector3<f64>),
    shares: [f64; 2],
}

impl Feedforward {
    /// Feedforward for `lola` (feet `l_foot`, `r_foot`, the bodies carrying the soles, and
    /// their toe segments `l_toe`, `r_toe`).
    pub fn new(lola: &LolaModel) -> Result<Self, WalkError> {
        let m = &lola.model;
        let id = |n: &str| body(m, n);
        let feet = [id("l_foot")?, id("r_foot")?];
        let toes = [id("l_toe")?, id("r_toe")?];
        Self::for_bodies(m.clone(), feet, Some(toes))
    }

    /// Feedforward for `model` whose `[left, right]` bodies `feet` carry the ground wrench
    /// with the feet flat and `toes` (if the feet have toe segments) in toe-off, each at its
    /// origin.
    pub fn for_bodies(
        model: Model,
        feet: [BodyId; 2],
        toes: Option<[BodyId; 2]>,
    ) -> Result<Self, WalkError> {
        let root = floating_root(&model)?;
        let nb = model.nbodies();
        if feet.iter().chain(toes.iter().flatten()).any(|&b| b >= nb) {
            return Err(model_err("a foot or toe frame's body is not in the model"));
        }
        Ok(Self {
            toes,
            data: Data::new(&model),
            fext: vec![Wrench::zero(); model.nbodies()],
            ground: (Vector3::zeros(), Vector3::zeros()),
            shares: [0.5, 0.5],
            model,
            root,
            feet,
        })
    }

    /// Shares of `[left, right]` in `phase`: the stance foot takes all in single support; in
    /// double support `w_left` is the position of `zmp` projected on the segment from the
    /// right foot `right` to the left foot `left`, clamped to \[0, 1].
    pub fn shares(
        phase: Phase,
        zmp: Vector2<f64>,
        left: Vector2<f64>,
        right: Vector2<f64>,
    ) -> [f64; 2] {
        match phase {
            Phase::LeftStance => [1.0, 0.0],
            Phase::RightStance => [0.0, 1.0],
            Phase::Double => {
                let d = left - right;
                let w = if d.norm_squared() > 1e-12 {
                    ((zmp - right).dot(&d) / d.norm_squared()).clamp(0.0, 1.0)
                } else {
                    0.5
                };
                [w, 1.0 - w]
            }
        }
    }

    /// Support wrenches `[left, right]` (body frame, about the body origin, with the body that
    /// carries each: the foot, or its toe segment in toe-off) of the ground wrench of the motion
    /// `(q, qd, qdd)` in the support phase of `s`: carrier `i` takes `F_i = w_i F` at its
    /// origin `p_i` ([`Self::shares`] of the motion's own ZMP between the carriers) and the
    /// share `w_i` of the residual moment `M_0 - sum p_i x F_i` (small: the ZMP lies near the
    /// segment), so that the wrenches sum to the required one and each foot's centre of pressure
    /// stays near its sole. The last RNEA's kinematics stay in the workspace.
    pub fn foot_wrenches(
        &mut self,
        q: &DVector<f64>,
        qd: &DVector<f64>,
        qdd: &DVector<f64>,
        s: &PatternSample,
    ) -> Result<[(BodyId, Wrench); 2], WalkError> {
        let (f, m0) = wrench(
            &self.model,
            &mut self.data,
            self.root,
            (q, qd, qdd),
            &Vector3::zeros(),
        )?;
        self.ground = (f, m0);
        let carrier = [0, 1].map(|i| match (s.feet[i].contact, &self.toes) {
            (Contact::Toe, Some(toes)) => toes[i],
            _ => self.feet[i],
        });
        let p = carrier.map(|b| self.data.world_pos[b]);
        let zmp = self.zmp().unwrap_or_else(|| 0.5 * (p[0] + p[1]).xy());
        let w = Self::shares(s.phase, zmp, p[0].xy(), p[1].xy());
        self.shares = w;
        let fi = w.map(|wi| f * wi);
        let residual = m0 - p[0].cross(&fi[0]) - p[1].cross(&fi[1]);
        Ok([0, 1].map(|i| {
            let rt = self.data.world_rot[carrier[i]].transpose();
            (carrier[i], Wrench::new(rt * (residual * w[i]), rt * fi[i]))
        }))
    }

    /// Vertical loads `[left, right]` of the last [`Self::foot_wrenches`] \[N].
    pub fn planned_loads(&self) -> [f64; 2] {
        self.shares.map(|w| w * self.ground.0.z)
    }

    /// ZMP of the last ground wrench (force `F`, moment `M_0` about the world origin) on
    /// the ground plane `z = 0`: `(-M_0y / F_z, M_0x / F_z)`; `None` when `F_z <= 0`.
    pub fn zmp(&self) -> Option<Vector2<f64>> {
        let (f, m) = self.ground;
        (f.z > 1e-9).then(|| Vector2::new(-m.y / f.z, m.x / f.z))
    }

    /// Generalized forces of the planned motion with the distributed ground wrench: the
    /// actuated joints' feedforward torques (the free-joint entries are ~0 by construction).
    pub fn compute(
        &mut self,
        q: &DVector<f64>,
        qd: &DVector<f64>,
        qdd: &DVector<f64>,
        s: &PatternSample,
    ) -> Result<&DVector<f64>, WalkError> {
        let feet = self.foot_wrenches(q, qd, qdd, s)?;
        self.with_wrenches(q, qd, qdd, &feet)
    }

    /// Generalized forces with explicit external wrenches (body frame, about the body origin)
    /// on the bodies they name, e.g. the measured contact wrenches of every foot and toe; a
    /// body out of range is an error.
    pub fn with_wrenches(
        &mut self,
        q: &DVector<f64>,
        qd: &DVector<f64>,
        qdd: &DVector<f64>,
        wrenches: &[(BodyId, Wrench)],
    ) -> Result<&DVector<f64>, WalkError> {
        self.fext.fill(Wrench::zero());
        for &(b, w) in wrenches {
            let slot = self
                .fext
                .get_mut(b)
                .ok_or_else(|| WalkError::InvalidParameter {
                    name: "wrenches",
                    reason: format!("body {b} out of range ({} bodies)", self.model.nbodies()),
                })?;
            *slot += w;
        }
        inverse_dynamics(&self.model, &mut self.data, q, qd, qdd, Some(&self.fext))
            .map_err(model_err)
    }
}
