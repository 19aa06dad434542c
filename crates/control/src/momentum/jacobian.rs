//! Angular momentum Jacobian `J_L` about the CoM (7.2), its vertical row `J_Lz`, `L_z` and its
//! rate, and the locked vertical inertia `I_zz^CoG` used by the reference (7.11).
//!
//! `J_L` is the top block of the centroidal momentum matrix `A_G` of
//! [`biped_dynamics::Centroidal`] (world axes, about the CoM), so rotor spin and coupled
//! drive bodies enter exactly. `dL_z/dt` is available two ways: the backward difference of
//! `L_z` over the control cycle ([`LzRate`], first order in `dt`, what a 1 kHz IK loop has),
//! and analytically `J_Lz qddot + (Adot_G v)_z` ([`vertical_momentum_rate`]).

use super::error::{check_finite, check_len, positive, MomentumError};
use biped_dynamics::{update_placements, Centroidal, Data, Model};
use nalgebra::{DMatrix, DVector, Vector3};

/// Preallocated `J_L` (3 x nv) and `J_Lz^T` (nv) of one model, refreshed each cycle.
#[derive(Clone, Debug)]
pub struct VerticalMomentum {
    jl: DMatrix<f64>,
    jlz: DVector<f64>,
}

impl VerticalMomentum {
    /// Zeroed buffers sized for `model`.
    pub fn new(model: &Model) -> Self {
        Self {
            jl: DMatrix::zeros(3, model.nv()),
            jlz: DVector::zeros(model.nv()),
        }
    }

    /// Number of velocity coordinates.
    pub fn nv(&self) -> usize {
        self.jlz.len()
    }

    /// Copies `J_L` (7.2) and its z row out of an already computed `centroidal` (no allocation).
    pub fn update(&mut self, centroidal: &Centroidal) -> Result<(), MomentumError> {
        centroidal.angular_momentum_jacobian(&mut self.jl)?;
        for (dst, col) in self.jlz.iter_mut().zip(self.jl.column_iter()) {
            *dst = col[2];
        }
        Ok(())
    }

    /// Runs the position-level centroidal computation at `q` (kinematics into `data`), then
    /// [`Self::update`].
    pub fn compute(
        &mut self,
        model: &Model,
        data: &mut Data,
        centroidal: &mut Centroidal,
        q: &DVector<f64>,
    ) -> Result<(), MomentumError> {
        centroidal.compute_matrix(model, data, q)?;
        self.update(centroidal)
    }

    /// Angular momentum Jacobian `J_L` about the CoM, world axes (7.2).
    pub fn jacobian(&self) -> &DMatrix<f64> {
        &self.jl
    }

    /// Its vertical row `J_Lz`, stored as a column vector of length nv.
    pub fn jacobian_z(&self) -> &DVector<f64> {
        &self.jlz
    }

    /// Vertical angular momentum about the CoM `L_z = J_Lz qdot` (7.2).
    pub fn lz(&self, v: &DVector<f64>) -> Result<f64, MomentumError> {
        check_len("v", v.len(), self.nv())?;
        check_finite("v", v.iter())?;
        Ok(self.jlz.dot(v))
    }
}

/// Analytic `dL_z/dt = J_Lz qddot + (Adot_G v)_z` after [`Centroidal::compute`] at `(q, v)`.
pub fn vertical_momentum_rate(
    centroidal: &Centroidal,
    jlz: &DVector<f64>,
    qdd: &DVector<f64>,
) -> Result<f64, MomentumError> {
    check_len("qdd", qdd.len(), jlz.len())?;
    check_finite("qdd", qdd.iter())?;
    Ok(jlz.dot(qdd) + centroidal.ag_bias()?.ang.z)
}

/// Backward difference `(L_z,k - L_z,k-1) / dt` over the control cycle: the rate available to
/// a 1 kHz loop without accelerations (error O(dt)); 0 on the first sample.
#[derive(Clone, Debug)]
pub struct LzRate {
    dt: f64,
    previous: Option<f64>,
}

impl LzRate {
    /// Difference quotient for cycle time `dt > 0`.
    pub fn new(dt: f64) -> Result<Self, MomentumError> {
        Ok(Self {
            dt: positive("dt", dt)?,
            previous: None,
        })
    }

    /// Feeds `L_z` of the current cycle and returns the rate estimate.
    pub fn update(&mut self, lz: f64) -> Result<f64, MomentumError> {
        check_finite("lz", [lz].iter())?;
        let rate = self.previous.map_or(0.0, |p| (lz - p) / self.dt);
        self.previous = Some(lz);
        Ok(rate)
    }

    /// Forgets the history (next rate is 0).
    pub fn reset(&mut self) {
        self.previous = None;
    }
}

/// Vertical moment of inertia `I_zz^CoG(q0)` of the locked robot about the vertical axis
/// through its CoM (7.11): `sum_i (R_i I_i R_i^T)_zz + m_i ((x_i - x_C)^2 + (y_i - y_C)^2)`.
pub fn vertical_inertia(
    model: &Model,
    data: &mut Data,
    q0: &DVector<f64>,
) -> Result<f64, MomentumError> {
    update_placements(model, data, q0).map_err(biped_dynamics::JacobianError::from)?;
    let (mut mass, mut moment) = (0.0, Vector3::zeros());
    for (i, body) in model.bodies().iter().enumerate() {
        let m = body.inertia().mass();
        mass += m;
        moment += body_com(data, i, &body.inertia().com()) * m;
    }
    let mass = positive("total mass", mass)?;
    let com = moment / mass;
    let mut izz = 0.0;
    for (i, body) in model.bodies().iter().enumerate() {
        let inertia = body.inertia();
        let rot = &data.world_rot[i];
        let rot_row = rot.row(2).transpose();
        izz += rot_row.dot(&(inertia.inertia_about_com() * rot_row));
        let d = body_com(data, i, &inertia.com()) - com;
        izz += inertia.mass() * (d.x * d.x + d.y * d.y);
    }
    Ok(izz)
}

/// World position of body `i`'s CoM `c` (body coordinates).
fn body_com(data: &Data, i: usize, c: &Vector3<f64>) -> Vector3<f64> {
    data.world_pos[i] + data.world_rot[i] * c
}
