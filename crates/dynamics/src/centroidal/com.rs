//! Centre of mass and its velocity as mass-weighted sums over bodies (no workspace needed).

use crate::jacobian::JacobianError;
use crate::kinematics::body_kinematics;
use crate::{check, Data, Model};
use nalgebra::{DVector, Vector3};

/// Total mass, centre of mass and its velocity (world) of a model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CenterOfMass {
    /// Total mass `m = sum_i m_i`.
    pub mass: f64,
    /// Centre of mass `r_C = sum_i m_i r_Ci / m` in world coordinates.
    pub position: Vector3<f64>,
    /// Its velocity `sum_i m_i rdot_Ci / m` (zero when no `v` was given).
    pub velocity: Vector3<f64>,
}

/// Centre of mass at `q` (and its velocity if `v` is given); runs the kinematics into `data`.
pub fn center_of_mass(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: Option<&DVector<f64>>,
) -> Result<CenterOfMass, JacobianError> {
    check::data(model, data)?;
    check::configuration(model, q)?;
    if let Some(v) = v {
        check::vector("v", v, model.nv())?;
    }
    let (mut mass, mut moment, mut momentum) = (0.0, Vector3::zeros(), Vector3::zeros());
    for (i, body) in model.bodies().iter().enumerate() {
        body_kinematics(model, data, i, q, v);
        let inertia = body.inertia();
        let m = inertia.mass();
        let rot = &data.world_rot[i];
        let c = inertia.com();
        mass += m;
        moment += (data.world_pos[i] + rot * c) * m;
        let vel = &data.vel[i];
        momentum += rot * (vel.lin + vel.ang.cross(&c)) * m;
    }
    crate::kinematics::take_fault(data)?;
    if mass <= 0.0 {
        return Err(JacobianError::ZeroMass);
    }
    Ok(CenterOfMass {
        mass,
        position: moment / mass,
        velocity: momentum / mass,
    })
}
