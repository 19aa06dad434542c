//! Centre of mass and centroidal momentum `h_G = [L_G; p]` (7.1) of a recorded frame as a
//! sum over bodies of one kinematics pass, without the centroidal momentum matrix `A_G`:
//! `h_G = sum_i X_G,i^* M_i v_i` (each body's momentum `M_i v_i`, (2.22), moved to the CoM).
//! This equals `A_G v` of (7.2) because both are the total momentum of the same body
//! velocities; `tests/sim_momentum.rs` checks it against
//! [`biped_dynamics::Centroidal::compute`].

use biped_dynamics::{center_of_mass, Data, Force, JacobianError, Model};
use nalgebra::{DVector, Vector3};

/// Centre of mass (world) and centroidal momentum (world axes, moment about the CoM).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CentroidalSample {
    /// Centre of mass `r_C` \[m].
    pub com: Vector3<f64>,
    /// `h_G = [L_G; p]`: angular momentum about the CoM and linear momentum.
    pub momentum: Force,
}

/// CoM and `h_G` at `(q, v)` from one kinematics pass into `data` (no `A_G`, no bias).
pub fn centroidal_sample(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> Result<CentroidalSample, JacobianError> {
    let com = center_of_mass(model, data, q, Some(v))?.position;
    let (mut ang, mut lin) = (Vector3::zeros(), Vector3::zeros());
    for (i, body) in model.bodies().iter().enumerate() {
        let h = body.inertia().apply(&data.vel[i]);
        let rot = &data.world_rot[i];
        let p = rot * h.lin;
        ang += rot * h.ang + (data.world_pos[i] - com).cross(&p);
        lin += p;
    }
    Ok(CentroidalSample {
        com,
        momentum: Force::new(ang, lin),
    })
}
