//! First forward recursion of the O(n) algorithm (Algorithm 2.2 with step 2 of Algorithm 2.1):
//! body forces, `M-bar_i = M_i` and the parent-frame bias of spin-invariant rotors (of the
//! lumped ones only the spin torque and their load on their own coordinate).

use crate::check;
use crate::kinematics::{coupled_transform, force_of, rotor_transform};
use crate::model::coupling::Mechanism;
use crate::model::JointModel;
use crate::spatial::{Force, Wrench};
use crate::subsystem;
use crate::subsystem::axial::{parent_frame_bias, AxialMember};
use crate::{Data, DynamicsError, Model};
use nalgebra::{DVector, Vector3};

/// First forward recursion (Algorithm 2.2 with step 2 of Algorithm 2.1): kinematics, body
/// forces `f_i` (gravity, external wrenches, inertial forces) and `M-bar_i = M_i`, `f-bar_i = f_i`.
pub fn forward_pass_1(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    fext: Option<&[Wrench]>,
) -> Result<(), DynamicsError> {
    super::super::forward_dynamics_kinematics(model, data, q, v)?;
    check::wrenches(model, fext)?;
    dynamic_first_pass(model, data, fext)
}

/// Dynamic half of the first pass after [`super::super::forward_dynamics_kinematics`]: body forces
/// `f-bar_i = f_i` (2.56) written to `fbar` only,
/// `M-bar_i = M_i` and the sub-system member kinematics; for a rider or slider `f-bar` holds its
/// parent-frame `C^T (M b - f)` instead ([`crate::subsystem::axial::parent_frame_bias`]), a
/// lumped axial member's rigid-body forces are in its carrier's (`Data::force_inertia`) and
/// only its spin torque and load are added ([`AxialMember::spin_load`]).
pub(super) fn dynamic_first_pass(
    model: &Model,
    data: &mut Data,
    fext: Option<&[Wrench]>,
) -> Result<(), DynamicsError> {
    // Slices zipped (no per-body bounds checks); rotors are filled by the second loop.
    let bodies = (data.force_inertia.iter())
        .zip(&data.axial_member)
        .zip(&data.mbar_init);
    let state = data.gravity_body.iter().zip(&data.vel);
    let out = data.mbar.iter_mut().zip(data.fbar.iter_mut());
    for (i, (((inertia, rc), init), ((g, vel), (mbar, fbar)))) in
        bodies.zip(state.zip(out)).enumerate()
    {
        if rc.is_none() {
            *fbar = force_of(inertia, g, &vel.ang, fext, i);
            if let Some(init) = init {
                mbar.set_from(init);
            }
        }
    }
    for (i, rc) in &data.axial_members {
        if rc.lumped() {
            let (h, load) = lumped_load(model, data, *i, rc, fext)?;
            data.fbar[rc.carrier] -= h;
            data.axial_load[*i] = load;
            continue;
        }
        let h = rotor_bias(model, data, *i, rc, fext)?;
        data.fbar[*i] = h;
        if rc.rider {
            // Lumped into the carrier: f-hat = M b - f gains the rider's h.
            data.fbar[rc.carrier] -= h;
        }
    }
    for s in 0..model.subsystems.len() {
        if data.link_rotors[s].is_none() {
            subsystem::on::hat_kinematics(model, data, s);
        }
    }
    Ok(())
}

/// Lumped axial member `i` ([`AxialMember::lumped`]): the share of its `C^T (M b - f)` that
/// its carrier's `f-bar` lacks (its rigid-body forces are in the carrier's,
/// `Data::force_inertia`: the spin torque less its external wrench) and its load
/// `s . C^T (M b - f)` on its own coordinate.
#[inline]
fn lumped_load(
    model: &Model,
    data: &Data,
    i: usize,
    rc: &AxialMember,
    fext: Option<&[Wrench]>,
) -> Result<(Force, f64), DynamicsError> {
    let (w, g) = carrier_state(model, data, i, rc);
    let (_, qd, sigma) = rc.state(data, i);
    let (torque, load) = rc.spin_load(&w, &g, (qd, sigma));
    let h = Force::new(torque, Vector3::zeros());
    Ok(match external(fext, i) {
        Some(f) => {
            let f = carrier_wrench(model, data, i, rc, f)?;
            (h - f, load - rc.s.dot(&f))
        }
        None => (h, load),
    })
}

/// Angular velocity and gravity in the carrier frame of axial member `i`.
#[inline(always)]
fn carrier_state(
    model: &Model,
    data: &Data,
    i: usize,
    rc: &AxialMember,
) -> (Vector3<f64>, Vector3<f64>) {
    match model.bodies[i].parent {
        Some(_) => (data.vel[rc.carrier].ang, data.gravity_body[rc.carrier]),
        None => (Vector3::zeros(), model.gravity),
    }
}

/// `C^T (M b - f)` of axial member `i` in its carrier's frame, including its external
/// wrench ([`carrier_wrench`]).
#[inline]
fn rotor_bias(
    model: &Model,
    data: &Data,
    i: usize,
    rc: &AxialMember,
    fext: Option<&[Wrench]>,
) -> Result<Force, DynamicsError> {
    let (w, g) = carrier_state(model, data, i, rc);
    let h = parent_frame_bias(rc, &w, &g, rc.state(data, i));
    Ok(match external(fext, i) {
        Some(f) => h - carrier_wrench(model, data, i, rc, f)?,
        None => h,
    })
}

/// The external wrench of body `i`, `None` if there is none or it is zero.
#[inline(always)]
fn external(fext: Option<&[Wrench]>, i: usize) -> Option<Wrench> {
    fext.map(|f| f[i]).filter(|f| !is_zero(f))
}

/// The external wrench `f` of axial member `i` (given in the spun rotor frame, so only here is
/// the spin angle evaluated) in its carrier's frame; out of line, as it is rare.
#[inline(never)]
fn carrier_wrench(
    model: &Model,
    data: &Data,
    i: usize,
    rc: &AxialMember,
    f: Wrench,
) -> Result<Force, DynamicsError> {
    let body = &model.bodies[i];
    let x = match &body.joint_model {
        JointModel::Coupled {
            mechanism: Mechanism::HarmonicDrive(rotor),
            ..
        } => rotor_transform(rotor, &data.rotor_frame[i], data.fd_q[body.q_index]),
        _ => coupled_transform(body, data.unplaced[i], data.fd_q.as_slice()),
    };
    let Some(x) = x else {
        return Err(DynamicsError::Unsupported(
            "external wrench on a rotor with a non-finite spin angle",
        ));
    };
    let f = x.tr_apply_force(&f);
    // A rider's wrench moves on from the common parent into its carrier's frame.
    Ok(match rc.rider {
        true => data.x[rc.carrier].inv_tr_apply_force(&f),
        false => f,
    })
}

/// True if every component of `f` is zero: an OR of the six bit patterns settles the usual
/// all-`+0.0` wrench without six float comparisons; any set bit (also of a `-0.0`) falls
/// back to the comparison.
#[inline(always)]
fn is_zero(f: &Wrench) -> bool {
    let (a, l) = (&f.ang, &f.lin);
    let bits = [a.x, a.y, a.z, l.x, l.y, l.z].map(f64::to_bits);
    bits.iter().fold(0, |acc, b| acc | b) == 0 || *f == Wrench::zero()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bit test agrees with the float comparison, also for `-0.0`, tiny and NaN entries.
    #[test]
    fn is_zero_matches_comparison() {
        for c in 0..6 {
            for x in [0.0, -0.0, 5e-324, -1.0, f64::NAN, f64::INFINITY] {
                let mut v = nalgebra::Vector6::zeros();
                v[c] = x;
                let f = Wrench::from_vector(&v);
                assert_eq!(is_zero(&f), f == Wrench::zero(), "entry {c} = {x}");
            }
        }
    }
}
