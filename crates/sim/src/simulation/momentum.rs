//! Centre of mass and centroidal momentum `h_G = [L_G; p]` (7.1) of a recorded frame as a
//! sum over bodies of one forward-dynamics first pass, without the centroidal momentum matrix
//! `A_G`: `h_G = sum_i X_G,i^* M_i v_i` (each body's momentum `M_i v_i`, (2.22), moved to the
//! CoM; [`biped_dynamics::centroidal_momentum`]).
//! This equals `A_G v` of (7.2) because both are the total momentum of the same body
//! velocities; `tests/sim_momentum.rs` checks it against
//! [`biped_dynamics::Centroidal::compute`].

use biped_dynamics::{centroidal_momentum, Data, Force, JacobianError, Model};
use nalgebra::{DVector, Vector3};

/// Centre of mass (world) and centroidal momentum (world axes, moment about the CoM).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CentroidalSample {
    /// Centre of mass `r_C` \[m].
    pub com: Vector3<f64>,
    /// `h_G = [L_G; p]`: angular momentum about the CoM and linear momentum.
    pub momentum: Force,
}

/// CoM and `h_G` at `(q, v)` from one forward-dynamics first pass into `data`
/// ([`biped_dynamics::centroidal_momentum`]: spin-invariant rotors from their carriers).
pub fn centroidal_sample(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> Result<CentroidalSample, JacobianError> {
    let s = centroidal_momentum(model, data, q, v)?;
    Ok(CentroidalSample {
        com: s.com,
        momentum: s.momentum,
    })
}
