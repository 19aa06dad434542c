//! Forward dynamics (three methods), mass matrix and inverse dynamics (thesis 2.5-2.8, 2.10).

mod crba;
pub mod on;
pub mod reference;
mod rnea;
mod solve;

use crate::check;
use crate::kinematics::{
    body_forces, body_kinematics, complete_rotor_kinematics, first_forward,
    first_forward_kinematics, take_fault,
};
use crate::spatial::Wrench;
use crate::{Data, DynamicsError, Model};
pub(crate) use crba::ColumnAncestors;
use nalgebra::{DMatrix, DVector};

/// Forward-dynamics method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Algorithm {
    /// O(n) three-pass algorithm (Algorithms 2.1-2.4), tree case.
    On,
    /// CRBA mass matrix + RNEA bias + dense Cholesky, O(n^3).
    Crba,
    /// CRBA + RNEA bias + Featherstone's reverse sparse `L^T L` factorisation (2.10.1).
    Sparse,
}

/// Generalized accelerations `qddot` for `(q, v, tau)`, gravity and optional external body
/// wrenches (one per body, body frame); result is also in `data.ddq`.
///
/// Equals [`forward_dynamics_kinematics`] followed by [`forward_dynamics_solve`].
///
/// # Example
///
/// The floating G1 at a generic state: the three methods agree, and inverse dynamics of the
/// result gives back the applied torques.
///
/// ```
/// use biped_dynamics::urdf::{load_file, UrdfOptions};
/// use biped_dynamics::{forward_dynamics, inverse_dynamics, nearby_state, Algorithm, Data};
/// use nalgebra::DVector;
///
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/g1_29dof_rev_1_0.urdf");
/// let model = load_file(path, &UrdfOptions { floating: true, ..Default::default() })?.model;
/// let mut data = Data::new(&model);
/// // every coordinate moved a little off the neutral pose, every velocity 1e-3
/// let (q, v) = nearby_state(&model, &model.neutral(), &DVector::zeros(model.nv()))?;
/// let tau = DVector::from_fn(model.nv(), |i, _| 0.1 * (i as f64).sin());
///
/// let on = forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::On)?.clone();
/// for algo in [Algorithm::Crba, Algorithm::Sparse] {
///     let other = forward_dynamics(&model, &mut data, &q, &v, &tau, None, algo)?;
///     assert!((other - &on).amax() < 1e-9 * on.amax());
/// }
/// let back = inverse_dynamics(&model, &mut data, &q, &v, &on, None)?;
/// assert!((back - &tau).amax() < 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn forward_dynamics<'d>(
    model: &Model,
    data: &'d mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    tau: &DVector<f64>,
    fext: Option<&[Wrench]>,
    algo: Algorithm,
) -> Result<&'d DVector<f64>, DynamicsError> {
    forward_dynamics_kinematics(model, data, q, v)?;
    forward_dynamics_solve(model, data, tau, fext, algo)
}

/// First phase of forward dynamics: the kinematic part of the first forward recursion
/// (Algorithm 2.2, (2.33)-(2.37)) for `(q, v)`.
///
/// Valid in `data` after it returns, for every body except the Harmonic Drive rotors: `x[i]`
/// (`C_i`), `world_rot[i]` / `world_pos[i]`, `vel[i]`, `bias_acc[i]`, `gravity_body[i]`, and
/// the mechanisms' loop caches. The kinematics of rotors whose inertia is axisymmetric about
/// their spin axis are skipped (the O(n) solve works with their constant parent-frame
/// inertia, `subsystem::axial`): use [`crate::forward_kinematics`] for those. Forces, torques
/// and external wrenches can then be computed from these kinematics (e.g. contact at the feet,
/// drive torques) and passed to [`forward_dynamics_solve`].
///
/// Reuse: when `data` still holds this function's kinematics (no other kinematics call came
/// since: every other pass clears the mark) for a `q` and `v` bitwise equal to the given ones,
/// it returns `Ok` without recomputing (those inputs passed the checks then), so results are
/// bit-identical to a fresh pass (e.g. sensors, recording and the first Runge-Kutta stage at
/// one state share one pass). `data` serves one model; if you overwrite its public kinematic fields by
/// hand, run another kinematics call (e.g. [`crate::update_placements`]) before this one.
pub fn forward_dynamics_kinematics(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> Result<(), DynamicsError> {
    check::data(model, data)?;
    // The stored (q, v) passed the checks below when their pass ran: equal bits pass them
    // again (a NaN never equals a stored value, so it always reaches the checks).
    if forward_dynamics_kinematics_current(data, q.as_slice(), v.as_slice()) {
        return Ok(());
    }
    check::configuration(model, q)?;
    check::vector("v", v, model.nv())?;
    first_forward_kinematics(model, data, q, v);
    take_fault(data)?;
    data.fd_kinematics = true;
    Ok(())
}

/// True if `data` holds the kinematics of [`forward_dynamics_kinematics`] at `(q, v)`, bitwise
/// equal (no other kinematics call since): a call with them would be skipped, and readers of
/// that pass (e.g. [`crate::centroidal_momentum_current`]) see exactly this state.
pub fn forward_dynamics_kinematics_current(data: &Data, q: &[f64], v: &[f64]) -> bool {
    data.fd_kinematics && same_bits(data.fd_q.as_slice(), q) && same_bits(data.fd_v.as_slice(), v)
}

/// True if `a` and `b` hold the same `f64` bit patterns (`0.0` and `-0.0` differ, which only
/// costs a recomputation); a branch-free fold of the XORed bits (vectorised).
#[inline]
fn same_bits(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .fold(0, |acc, (x, y)| acc | (x.to_bits() ^ y.to_bits()))
            == 0
}

/// Second phase of forward dynamics: body forces (2.56) with `tau` and optional external body
/// wrenches, then the solve by `algo` (for [`Algorithm::On`] the backward and second forward
/// passes, Algorithms 2.3-2.4); `qddot` is returned and also in `data.ddq`.
///
/// Needs the kinematics of a preceding [`forward_dynamics_kinematics`] (or [`forward_dynamics`])
/// on the same `data` with no other kinematics call in between, else
/// [`DynamicsError::KinematicsNotCurrent`]. May be called repeatedly (e.g. for several `tau`).
///
/// # Example
///
/// The two phases with a contact-like force computed in between from the body poses, and
/// the bit-equal one-call form.
///
/// ```
/// use biped_dynamics::{dill::dill, forward_dynamics, forward_dynamics_kinematics};
/// use biped_dynamics::{forward_dynamics_solve, Algorithm, Data, Wrench};
/// use nalgebra::{DVector, Vector3};
///
/// let model = dill(3)?; // 8 revolute bodies
/// let mut data = Data::new(&model);
/// let (q, v) = (DVector::from_element(8, 0.4), DVector::from_element(8, 0.5));
/// let tau = DVector::zeros(8);
///
/// forward_dynamics_kinematics(&model, &mut data, &q, &v)?;
/// // push the last body up with 1 N at its origin, in its own frame
/// let up = data.world_rot[7].transpose() * Vector3::z();
/// let mut fext = vec![Wrench::zero(); model.nbodies()];
/// fext[7] = Wrench::new(Vector3::zeros(), up);
/// let split = forward_dynamics_solve(&model, &mut data, &tau, Some(&fext), Algorithm::On)?.clone();
///
/// let one = forward_dynamics(&model, &mut data, &q, &v, &tau, Some(&fext), Algorithm::On)?;
/// assert_eq!(one, &split);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn forward_dynamics_solve<'d>(
    model: &Model,
    data: &'d mut Data,
    tau: &DVector<f64>,
    fext: Option<&[Wrench]>,
    algo: Algorithm,
) -> Result<&'d DVector<f64>, DynamicsError> {
    check::data(model, data)?;
    check::vector("tau", tau, model.nv())?;
    check::wrenches(model, fext)?;
    if !data.fd_kinematics {
        return Err(DynamicsError::KinematicsNotCurrent);
    }
    if algo == Algorithm::On {
        let ddq = on::solve(model, data, tau, fext)?;
        check::result("qddot", ddq.as_slice())?;
        return Ok(ddq);
    }
    complete_rotor_kinematics(model, data);
    data.dense_workspace(true)?;
    body_forces(model, data, fext);
    rnea::rnea_from_kinematics(model, data, None, true);
    data.ddq.copy_from(tau);
    data.ddq -= &data.nle;
    if algo == Algorithm::Crba {
        crba::crba(model, data, crba::Clear::All);
        let (mass, factor) = (data.mass.as_slice(), data.factor.as_mut_slice());
        factor.copy_from_slice(mass);
        solve::cholesky_in_place(&mut data.factor, &data.mass)?;
        solve::cholesky_solve_in_place(&data.factor, &mut data.ddq);
    } else {
        let clear = data.column_ancestors.sparse_clear(model.nv);
        crba::crba(model, data, clear);
        if clear == crba::Clear::Pattern {
            solve::copy_pattern(&data.mass, &model.dof_ancestors, &mut data.factor);
        } else {
            let (mass, factor) = (data.mass.as_slice(), data.factor.as_mut_slice());
            factor.copy_from_slice(mass);
        }
        solve::ltl_in_place(&mut data.factor, &model.dof_ancestors, &data.mass)?;
        solve::ltl_solve_in_place(&data.factor, &model.dof_ancestors, &mut data.ddq);
    }
    check::result("qddot", data.ddq.as_slice())?;
    let ddq = std::mem::take(&mut data.ddq);
    crate::kinematics::propagate_accelerations(model, data, Some(&ddq));
    data.ddq = ddq;
    Ok(&data.ddq)
}

/// Joint-space mass matrix `M(q)` by CRBA (symmetric, full storage), also in `data.mass`.
///
/// # Example
///
/// Checked column by column against RNEA: without gravity and at rest,
/// `inverse_dynamics(q, 0, e_j)` is the `j`-th column of `M`.
///
/// ```
/// use biped_dynamics::{dill::dill, inverse_dynamics, mass_matrix, Data};
/// use nalgebra::DVector;
///
/// let model = dill(2)?;
/// let mut data = Data::new(&model);
/// let q = DVector::from_vec(vec![0.1, -0.7, 1.2, 0.4]);
/// let m = mass_matrix(&model, &mut data, &q)?.clone();
/// assert!((&m - m.transpose()).amax() == 0.0);
///
/// let bias = inverse_dynamics(&model, &mut data, &q, &DVector::zeros(4), &DVector::zeros(4), None)?
///     .clone(); // gravity torques only
/// for j in 0..4 {
///     let e_j = DVector::from_fn(4, |i, _| if i == j { 1.0 } else { 0.0 });
///     let col = inverse_dynamics(&model, &mut data, &q, &DVector::zeros(4), &e_j, None)? - &bias;
///     assert!((col - m.column(j)).amax() < 1e-12);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn mass_matrix<'d>(
    model: &Model,
    data: &'d mut Data,
    q: &DVector<f64>,
) -> Result<&'d DMatrix<f64>, DynamicsError> {
    check::data(model, data)?;
    check::configuration(model, q)?;
    for i in 0..model.nbodies() {
        body_kinematics(model, data, i, q, None);
    }
    take_fault(data)?;
    data.dense_workspace(false)?;
    crba::crba(model, data, crba::Clear::All);
    check::result("mass matrix", data.mass.as_slice())?;
    Ok(&data.mass)
}

/// Inverse dynamics `tau = M(q) a + h(q, v) - J^T f_ext` by RNEA, also in `data.tau`.
///
/// # Example
///
/// A free 3 kg box hovering at rest needs the generalized force `m g` upwards on its base
/// (free-joint velocities are `[linear; angular]` in the body frame).
///
/// ```
/// use biped_dynamics::{inverse_dynamics, BodySpec, Data, JointModel, ModelBuilder};
/// use biped_dynamics::RigidInertia;
/// use nalgebra::{DVector, Isometry3, Matrix3, Vector3};
///
/// let inertia = RigidInertia::new(3.0, Vector3::zeros(), Matrix3::identity() * 0.05)?;
/// let mut b = ModelBuilder::new();
/// b.add_body(BodySpec::named("box", None, JointModel::FreeQuaternion, Isometry3::identity(), inertia))?;
/// let model = b.build()?;
/// let mut data = Data::new(&model);
/// let zero = DVector::zeros(6);
/// let tau = inverse_dynamics(&model, &mut data, &model.neutral(), &zero, &zero, None)?;
/// let expected = [0.0, 0.0, 3.0 * 9.81, 0.0, 0.0, 0.0];
/// assert!(tau.iter().zip(expected).all(|(t, e)| (t - e).abs() < 1e-12));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn inverse_dynamics<'d>(
    model: &Model,
    data: &'d mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    a: &DVector<f64>,
    fext: Option<&[Wrench]>,
) -> Result<&'d DVector<f64>, DynamicsError> {
    check::data(model, data)?;
    check::configuration(model, q)?;
    check::vector("v", v, model.nv())?;
    check::vector("a", a, model.nv())?;
    check::wrenches(model, fext)?;
    first_forward(model, data, q, v, fext);
    take_fault(data)?;
    rnea::rnea_from_kinematics(model, data, Some(a), false);
    check::result("tau", data.tau.as_slice())?;
    Ok(&data.tau)
}
