//! Centre of mass and centroidal momentum `h_G = [L_G; p]` (7.1) from the first pass of the
//! forward dynamics ([`crate::forward_dynamics_kinematics`]), without the rotor kinematics it
//! skips and without `A_G`.
//!
//! `h_G = sum_i X_G,i^* M_i v_i`: each body's momentum (2.22) moved to the CoM, which equals
//! `A_G v` of (7.2) (both are the total momentum of the same body velocities). Ordinary bodies
//! use their world pose and velocity from the pass. A spin-invariant Harmonic Drive rotor
//! (3.1)-(3.2) (`subsystem::axial`) has no pose there; its momentum is formed in
//! its carrier's (parent's) frame from constants of the model: CoM `c` fixed in the carrier,
//! inertia `I_c` about it constant in carrier axes (axisymmetry), so with the carrier velocity
//! `[w_p; v_p]` and the spin column `s` (`s.ang = N` times the axis, carrier axes) its linear
//! momentum is `m (v_p + w_p x c)` and its angular momentum about its CoM
//! `I_c (w_p + s.ang qd)` (carrier motion plus the spin term `I N qd` about the axis).
//! Rotors without that symmetry are ordinary bodies of the pass (the general path). The ankle's
//! roller-screw rotors and nuts (axial members, `subsystem::axial`) are formed the same way from
//! the spin rate or the travel the pass recorded (a nut's CoM moves along its axis).

use crate::jacobian::JacobianError;
use crate::subsystem::axial::{AxialKind, AxialMember};
use crate::{forward_dynamics_kinematics, Data, Force, Model};
use nalgebra::{DVector, Matrix3, Vector3};

/// Total mass, centre of mass and centroidal momentum `h_G` (world axes), (7.1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CentroidalMomentum {
    /// Total mass `m = sum_i m_i`.
    pub mass: f64,
    /// Centre of mass `r_C` in world coordinates.
    pub com: Vector3<f64>,
    /// `h_G = [L_G; p]`: angular momentum about the CoM and linear momentum, world axes.
    pub momentum: Force,
}

/// CoM and `h_G` at `(q, v)`: runs [`forward_dynamics_kinematics`] into `data`, then
/// [`centroidal_momentum_current`]. `data` then holds that pass (a following
/// [`crate::forward_dynamics_solve`] may use it).
pub fn centroidal_momentum(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> Result<CentroidalMomentum, JacobianError> {
    forward_dynamics_kinematics(model, data, q, v)?;
    centroidal_momentum_current(model, data)
}

/// CoM and `h_G` from the kinematics of the last [`forward_dynamics_kinematics`] on `data`
/// (its `q`, `v`); [`crate::DynamicsError::KinematicsNotCurrent`] if another kinematics call
/// came since, [`JacobianError::ZeroMass`] for a massless model.
pub fn centroidal_momentum_current(
    model: &Model,
    data: &Data,
) -> Result<CentroidalMomentum, JacobianError> {
    crate::check::data(model, data)?;
    if !data.fd_kinematics {
        return Err(crate::DynamicsError::KinematicsNotCurrent.into());
    }
    // One pass about a reference point near the bodies (the first body's origin, so no
    // cancellation far from the world origin), then the shift to the CoM: L_G = L_r - (G - r) x p.
    let r = data
        .world_pos
        .first()
        .copied()
        .unwrap_or_else(Vector3::zeros);
    let (mut mass, mut moment) = (0.0, Vector3::zeros());
    let (mut ang, mut lin) = (Vector3::zeros(), Vector3::zeros());
    for (i, body) in model.bodies().iter().enumerate() {
        let (rot, pos, h, c, m) = match (&data.axial_member[i], body.parent()) {
            (Some(rc), Some(_)) => axial_momentum(rc, data, i),
            _ => {
                let inertia = body.inertia();
                let h = inertia.apply(&data.vel[i]);
                let c = inertia.com();
                (&data.world_rot[i], data.world_pos[i], h, c, inertia.mass())
            }
        };
        // `h` about the frame origin `pos`, CoM `c` in frame coordinates.
        let rc = rot * c;
        let p = rot * h.lin;
        mass += m;
        moment += (pos - r + rc) * m;
        lin += p;
        ang += rot * h.ang + (pos - r).cross(&p);
    }
    if mass <= 0.0 {
        return Err(JacobianError::ZeroMass);
    }
    let com_r = moment / mass;
    ang -= com_r.cross(&lin);
    Ok(CentroidalMomentum {
        mass,
        com: r + com_r,
        momentum: Force::new(ang, lin),
    })
}

/// An axial member's carrier pose, its momentum in carrier axes (moment about the carrier
/// origin), its CoM in carrier coordinates and its mass (see [`crate::subsystem::axial`]): it
/// turns at `w_p + s.ang qd`; a rotor's CoM moves with the carrier, a slider's also along `s.lin`.
#[inline]
fn axial_momentum<'d>(
    rc: &AxialMember,
    data: &'d Data,
    i: usize,
) -> (&'d Matrix3<f64>, Vector3<f64>, Force, Vector3<f64>, f64) {
    let p = rc.carrier;
    let vel = &data.vel[p];
    let (c, qd, _) = rc.state(data, i);
    let w = vel.ang + rc.s.ang * qd;
    let mut v = vel.lin + vel.ang.cross(&c);
    if rc.kind == AxialKind::Slider {
        v += rc.s.lin * qd;
    }
    let lin = v * rc.mass;
    let h = Force::new(rc.inertia_com * w + c.cross(&lin), lin);
    (&data.world_rot[p], data.world_pos[p], h, c, rc.mass)
}
