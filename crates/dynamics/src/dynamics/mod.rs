//! Forward dynamics (three methods), mass matrix and inverse dynamics (thesis 2.5-2.8, 2.10).

mod crba;
pub mod on;
mod rnea;
mod solve;

use crate::check;
use crate::kinematics::{body_kinematics, first_forward, take_fault};
use crate::spatial::Wrench;
use crate::{Data, DynamicsError, Model};
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
pub fn forward_dynamics<'d>(
    model: &Model,
    data: &'d mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    tau: &DVector<f64>,
    fext: Option<&[Wrench]>,
    algo: Algorithm,
) -> Result<&'d DVector<f64>, DynamicsError> {
    match algo {
        Algorithm::On => on::forward_dynamics(model, data, q, v, tau, fext),
        Algorithm::Crba | Algorithm::Sparse => {
            check::data(model, data)?;
            check::configuration(model, q)?;
            check::vector("v", v, model.nv())?;
            check::vector("tau", tau, model.nv())?;
            check::wrenches(model, fext)?;
            first_forward(model, data, q, v, fext);
            take_fault(data)?;
            rnea::rnea_from_kinematics(model, data, None, true);
            crba::crba(model, data);
            data.factor.copy_from(&data.mass);
            data.ddq.copy_from(tau);
            data.ddq -= &data.nle;
            if algo == Algorithm::Crba {
                solve::cholesky_in_place(&mut data.factor)?;
                solve::cholesky_solve_in_place(&data.factor, &mut data.ddq);
            } else {
                solve::ltl_in_place(&mut data.factor, &model.dof_parent, &data.mass)?;
                solve::ltl_solve_in_place(&data.factor, &model.dof_parent, &mut data.ddq);
            }
            let ddq = std::mem::take(&mut data.ddq);
            crate::kinematics::propagate_accelerations(model, data, Some(&ddq));
            data.ddq = ddq;
            Ok(&data.ddq)
        }
    }
}

/// Joint-space mass matrix `M(q)` by CRBA (symmetric, full storage), also in `data.mass`.
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
    crba::crba(model, data);
    Ok(&data.mass)
}

/// Inverse dynamics `tau = M(q) a + h(q, v) - J^T f_ext` by RNEA, also in `data.tau`.
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
    Ok(&data.tau)
}
