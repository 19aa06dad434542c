//! The O(n) forward-dynamics algorithm of section 2.7-2.8 (Algorithms 2.1-2.4) with sub-systems.
//!
//! Propagation quantities in the thesis' notation, per body `i` with joint Jacobian `J_i`:
//! - backward (2.67)-(2.72): `M-bar_i = M_i + sum_j C_j^T K_j`, `f-bar_i = f_i - sum_j C_j^T k_j`,
//!   `P_i = -(J^T M-bar J)^-1 J^T M-bar C_i`, `p_i = (J^T M-bar J)^-1 (Q_i - J^T (M-bar b_i - f-bar_i))`,
//!   `K_i = M-bar_i (C_i + J_i P_i)`, `k_i = M-bar_i (J_i p_i + b_i) - f-bar_i`;
//! - second forward (2.66), (2.34): `qddot_i = P_i a_p(i) + p_i`, `a_i = C_i a_p(i) + J_i qddot_i + b_i`.
//!
//! Zero pruning: for one-DoF joints `U = M-bar J` is a 6-vector and `D = J^T U` a scalar, so
//! `P_i a = -D^-1 U^T (C_i a)` and `C_i^T K_i = C_i^T (M-bar - U D^-1 U^T) C_i` are evaluated
//! without forming `P_i` or `K_i`. The passes run over the rewired body list (2.9): bodies are
//! dispatched by joint type with one `match` per body, sub-systems (2.6-2.8) by
//! [`crate::subsystem`]'s branches, so geared rotors and coupled parts are supported.
//! Spin-invariant Harmonic Drive rotors enter in their parent's frame without kinematics
//! (`subsystem::rotor`), and one-DoF sub-systems of one link plus such rotors take the
//! one-DoF body step with constant rotor terms (`subsystem::link`).

use super::solve::check_pivot;
use crate::check;
use crate::kinematics::{force_of, rotor_transform, six};
use crate::model::coupling::Mechanism;
use crate::model::joint::Joint;
use crate::model::JointModel;
use crate::spatial::{plane, ArticulatedInertia, Force, Motion, Wrench};
use crate::subsystem::rotor::{parent_frame_bias, RotorConstant};
use crate::subsystem::{self, NodeKind};
use crate::{Data, DynamicsError, Model};
use nalgebra::{DVector, Matrix6, Vector3, Vector6};

/// First forward recursion (Algorithm 2.2 with step 2 of Algorithm 2.1): kinematics, body
/// forces `f_i` (gravity, external wrenches, inertial forces) and `M-bar_i = M_i`, `f-bar_i = f_i`.
pub fn forward_pass_1(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    fext: Option<&[Wrench]>,
) -> Result<(), DynamicsError> {
    super::forward_dynamics_kinematics(model, data, q, v)?;
    check::wrenches(model, fext)?;
    dynamic_first_pass(model, data, fext)
}

/// Dynamic half of the first pass after [`super::forward_dynamics_kinematics`]: body forces
/// `f-bar_i = f_i` (2.56) written to `fbar` only,
/// `M-bar_i = M_i` and the sub-system member kinematics; for a
/// spin-invariant rotor `f-bar` holds its parent-frame `C^T (M b - f)` instead
/// ([`crate::subsystem::rotor::parent_frame_bias`]).
fn dynamic_first_pass(
    model: &Model,
    data: &mut Data,
    fext: Option<&[Wrench]>,
) -> Result<(), DynamicsError> {
    // Slices zipped (no per-body bounds checks); rotors are filled by the second loop.
    let bodies = model
        .bodies
        .iter()
        .zip(&data.rotor_constant)
        .zip(&data.mbar_needed);
    let state = data.gravity_body.iter().zip(&data.vel);
    let out = data.mbar.iter_mut().zip(data.fbar.iter_mut());
    for (i, (((body, rc), &needed), ((g, vel), (mbar, fbar)))) in
        bodies.zip(state.zip(out)).enumerate()
    {
        if rc.is_none() {
            *fbar = force_of(&body.inertia, g, &vel.ang, fext, i);
            if needed {
                *mbar = body.inertia.to_articulated();
            }
        }
    }
    for k in 0..data.fast_rotors.len() {
        let i = data.fast_rotors[k];
        if let Some(rc) = &data.rotor_constant[i] {
            data.fbar[i] = rotor_bias(model, data, i, rc, fext)?;
        }
    }
    for s in 0..model.subsystems.len() {
        if data.link_rotors[s].is_none() {
            subsystem::on::hat_kinematics(model, data, s);
        }
    }
    Ok(())
}

/// `C^T (M b - f)` of spin-invariant rotor `i` in its parent's frame, including its external
/// wrench (given in the spun rotor frame, so only then is the spin angle evaluated).
#[inline]
fn rotor_bias(
    model: &Model,
    data: &Data,
    i: usize,
    rc: &RotorConstant,
    fext: Option<&[Wrench]>,
) -> Result<Force, DynamicsError> {
    let body = &model.bodies[i];
    let (w, g) = match body.parent {
        Some(p) => (data.vel[p].ang, data.gravity_body[p]),
        None => (Vector3::zeros(), model.gravity),
    };
    let mut h = parent_frame_bias(rc, &w, &g, data.fd_v[rc.v_index]);
    let Some(f) = fext.map(|f| f[i]).filter(|f| *f != Wrench::zero()) else {
        return Ok(h);
    };
    let x = match &body.joint_model {
        JointModel::Coupled {
            mechanism: Mechanism::HarmonicDrive(rotor),
            ..
        } => rotor_transform(rotor, &data.rotor_frame[i], data.fd_q[body.q_index]),
        _ => None,
    };
    let Some(x) = x else {
        return Err(DynamicsError::Unsupported(
            "external wrench on a rotor with a non-finite spin angle",
        ));
    };
    h -= x.tr_apply_force(&f);
    Ok(h)
}

/// Body forces and the backward and second forward passes (Algorithms 2.1-2.4 after the
/// kinematics of [`super::forward_dynamics_kinematics`]); inputs are checked by the caller.
pub(crate) fn solve<'d>(
    model: &Model,
    data: &'d mut Data,
    tau: &DVector<f64>,
    fext: Option<&[Wrench]>,
) -> Result<&'d DVector<f64>, DynamicsError> {
    dynamic_first_pass(model, data, fext)?;
    backward_unchecked(model, data, tau)?;
    Ok(forward_pass_2(model, data))
}

/// Backward recursion (Algorithm 2.3): `P_i, p_i, K_i, k_i` from the leaves to the root, with
/// generalized forces `tau` (`Q_i`).
pub fn backward_pass(
    model: &Model,
    data: &mut Data,
    tau: &DVector<f64>,
) -> Result<(), DynamicsError> {
    check::data(model, data)?;
    check::vector("tau", tau, model.nv())?;
    backward_unchecked(model, data, tau)
}

/// [`backward_pass`] for inputs already checked by the caller ([`solve`]: no second scan of
/// `tau` for non-finite entries).
fn backward_unchecked(
    model: &Model,
    data: &mut Data,
    tau: &DVector<f64>,
) -> Result<(), DynamicsError> {
    for node in model.nodes.iter().rev() {
        match node.kind {
            NodeKind::Body(i) => body_backward(model, data, i, tau)?,
            NodeKind::Subsystem(s) if data.link_rotors[s].is_some() => {
                subsystem::link::backward(model, data, s, tau)?
            }
            NodeKind::Subsystem(s) => subsystem::on::backward(model, data, s, tau)?,
        }
    }
    Ok(())
}

/// Backward step of body `i` outside sub-systems: `P_i, p_i, K_i, k_i` (2.67)-(2.72).
#[inline]
fn body_backward(
    model: &Model,
    data: &mut Data,
    i: usize,
    tau: &DVector<f64>,
) -> Result<(), DynamicsError> {
    let body = &model.bodies[i];
    // Each arm leaves M-bar_i - U D^-1 U^T in `mbar[i]` (no longer needed) and returns k_i.
    let k = match &body.joint {
        Joint::Revolute(ax) | Joint::Prismatic(ax) => {
            let mbar = &mut data.mbar[i];
            let u = ax.apply_inertia(mbar);
            let d = ax.dot_force(&u);
            if d <= 0.0 || !d.is_finite() {
                return Err(DynamicsError::NotPositiveDefinite {
                    index: body.v_index,
                    pivot: d,
                });
            }
            let dinv = 1.0 / d;
            let b = &data.bias_acc[i];
            let fbar = &data.fbar[i];
            let p = dinv * (tau[body.v_index] - u.dot(b) + ax.dot_force(fbar));
            let k = mbar.apply(b) + u * p - *fbar;
            mbar.sub_outer(&u, dinv);
            data.u[i] = u;
            data.dinv[i] = dinv;
            data.p1[i] = p;
            k
        }
        Joint::Fixed if data.massless_leaf[i] => Force::zero() - data.fbar[i],
        Joint::Fixed => data.mbar[i].apply(&data.bias_acc[i]) - data.fbar[i],
        Joint::EulerZxz | Joint::Quaternion => {
            let free = matches!(body.joint, Joint::Quaternion);
            six_dof_backward(data, i, body.v_index, tau, (body.parent.is_some(), free))?
        }
        Joint::Rotor(_) | Joint::Coupled => {
            return Err(DynamicsError::Unsupported(
                "a coupled body outside a sub-system (the model was not built by ModelBuilder)",
            ))
        }
    };
    if let Some(p) = body.parent {
        let x = &data.x[i];
        let (head, tail) = data.mbar.split_at_mut(i);
        match data.plane_axis[i] {
            _ if data.massless_leaf[i] => {} // M-bar_i = 0: nothing to add.
            Some(k) => tail[0].add_tr_transform_axis_to(k, x, &mut head[p]),
            None => tail[0].add_tr_transform_to(x, &mut head[p]),
        }
        data.fbar[p] -= x.tr_apply_force(&k);
    }
    Ok(())
}

/// Backward step of a 6-DoF joint: returns `M-bar - U D^-1 U^T` and `k_i`.
/// Leaves `M-bar - U D^-1 U^T` in `mbar[i]` and returns `k_i`; a root joint
/// (`propagate = false`) needs only `p_i`, its parent acceleration being zero.
#[inline(never)]
fn six_dof_backward(
    data: &mut Data,
    i: usize,
    vi: usize,
    tau: &DVector<f64>,
    (propagate, free): (bool, bool),
) -> Result<Force, DynamicsError> {
    let mbar = data.mbar[i].to_matrix();
    let j = data.jacobian6[i];
    let (u, d) = if free {
        free_joint_products(&data.mbar[i])
    } else {
        let u = mbar * j;
        let d = j.tr_mul(&u);
        (u, d)
    };
    let chol = d.cholesky().ok_or(DynamicsError::NotPositiveDefinite {
        index: vi,
        pivot: d.determinant(),
    })?;
    let l = chol.l_dirty();
    for c in 0..6 {
        check_pivot(vi + c, l[(c, c)] * l[(c, c)], d[(c, c)])?;
    }
    let hat_f = data.mbar[i].apply(&data.bias_acc[i]) - data.fbar[i];
    let jt_hat = if free {
        free_tr_mul(&hat_f)
    } else {
        j.tr_mul(&hat_f.to_vector())
    };
    let rhs = six(tau, vi) - jt_hat;
    let p = chol.solve(&rhs);
    data.p6[i] = p;
    if !propagate {
        data.pi6[i] = Matrix6::zeros();
        return Ok(Force::zero());
    }
    let pi = chol.solve(&u.transpose());
    let (b, fbar) = (data.bias_acc[i].to_vector(), data.fbar[i].to_vector());
    let k = mbar * (b + j * p) - fbar;
    let ia: Matrix6<f64> = mbar - u * pi;
    data.pi6[i] = pi;
    data.mbar[i] = ArticulatedInertia::from_matrix(&((ia + ia.transpose()) * 0.5));
    Ok(Force::from_vector(&k))
}

/// `U = M-bar J` and `D = J^T M-bar J` for the free joint's constant `J = [0 E; E 0]`
/// ([`crate::model::joint::quaternion_jacobian`]): with `M-bar = [A B; B^T C]`,
/// `U = [B A; C B^T]` and `D = [C B^T; B A]` (block permutations, no products).
fn free_joint_products(m: &ArticulatedInertia) -> (Matrix6<f64>, Matrix6<f64>) {
    let (mut u, mut d) = (Matrix6::zeros(), Matrix6::zeros());
    let bt = m.cross.transpose();
    u.fixed_view_mut::<3, 3>(0, 0).copy_from(&m.cross);
    u.fixed_view_mut::<3, 3>(0, 3).copy_from(&m.ang);
    u.fixed_view_mut::<3, 3>(3, 0).copy_from(&m.lin);
    u.fixed_view_mut::<3, 3>(3, 3).copy_from(&bt);
    d.fixed_view_mut::<3, 3>(0, 0).copy_from(&m.lin);
    d.fixed_view_mut::<3, 3>(0, 3).copy_from(&bt);
    d.fixed_view_mut::<3, 3>(3, 0).copy_from(&m.cross);
    d.fixed_view_mut::<3, 3>(3, 3).copy_from(&m.ang);
    (u, d)
}

/// `J^T f = [f_lin; f_ang]` for the free joint's constant `J = [0 E; E 0]` (a permutation).
#[inline]
fn free_tr_mul(f: &Force) -> Vector6<f64> {
    Vector6::new(f.lin.x, f.lin.y, f.lin.z, f.ang.x, f.ang.y, f.ang.z)
}

/// Second forward recursion (Algorithm 2.4): `qddot` into `data.ddq` and body accelerations.
pub fn forward_pass_2<'d>(model: &Model, data: &'d mut Data) -> &'d DVector<f64> {
    for node in &model.nodes {
        match node.kind {
            NodeKind::Body(i) => body_forward(model, data, i),
            NodeKind::Subsystem(s) if data.link_rotors[s].is_some() => {
                subsystem::link::forward(model, data, s)
            }
            NodeKind::Subsystem(s) => subsystem::on::forward(model, data, s),
        }
    }
    &data.ddq
}

/// Second forward step of body `i` outside sub-systems: (2.66), (2.34).
#[inline]
fn body_forward(model: &Model, data: &mut Data, i: usize) {
    let body = &model.bodies[i];
    let ap = match body.parent {
        Some(p) => plane::apply_motion(&data.x[i], data.plane_axis[i], &data.acc[p]),
        None => Motion::zero(),
    };
    let vi = body.v_index;
    let a = match &body.joint {
        Joint::Revolute(ax) | Joint::Prismatic(ax) | Joint::Rotor(ax) => {
            let qdd = data.p1[i] - data.dinv[i] * data.u[i].dot(&ap);
            data.ddq[vi] = qdd;
            ap + ax.motion(qdd)
        }
        Joint::Fixed | Joint::Coupled => ap,
        Joint::EulerZxz | Joint::Quaternion => {
            six_dof_forward(data, i, vi, (body.parent.is_some(), ap))
        }
    };
    data.acc[i] = a + data.bias_acc[i];
}

/// Second forward step of a 6-DoF joint body `i` (2.66): `qddot_i` into `ddq`, returns
/// `C_i a_p + J_i qddot_i`; out of line (one body per model) to keep the per-body loop small.
#[inline(never)]
fn six_dof_forward(
    data: &mut Data,
    i: usize,
    vi: usize,
    (has_parent, ap): (bool, Motion),
) -> Motion {
    let qdd = if has_parent {
        data.p6[i] - data.pi6[i] * ap.to_vector()
    } else {
        data.p6[i]
    };
    data.ddq.rows_mut(vi, 6).copy_from(&qdd);
    ap + Motion::from_vector(&(data.jacobian6[i] * qdd))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::joint::quaternion_jacobian;

    /// The free joint's block permutations against the dense products `M J`, `J^T M J`.
    #[test]
    fn free_joint_products_match_dense() {
        let l = Matrix6::from_fn(|i, j| {
            if j <= i {
                0.4 + ((5 * i + 3 * j) % 7) as f64
            } else {
                0.0
            }
        });
        let m = ArticulatedInertia::from_matrix(&(l * l.transpose()));
        let (j, dense) = (quaternion_jacobian(), m.to_matrix());
        let (u, d) = free_joint_products(&m);
        assert_eq!(u, dense * j);
        assert_eq!(d, j.transpose() * dense * j);
        let w = Vector6::new(0.3, -1.2, 0.7, 2.1, -0.4, 0.05);
        assert_eq!(free_tr_mul(&Force::from_vector(&w)), j.transpose() * w);
    }

    /// Non-finite `tau` is rejected once by the two-phase entry point (the solve itself does
    /// not scan it again) and by the public backward pass.
    #[test]
    fn non_finite_tau_is_rejected() {
        use crate::model::{BodySpec, JointModel, ModelBuilder};
        use crate::spatial::RigidInertia;
        use nalgebra::{Isometry3, Matrix3};
        let inertia = RigidInertia::new(1.0, Vector3::new(0.1, 0.0, 0.0), Matrix3::identity())
            .expect("valid inertia");
        let mut b = ModelBuilder::new();
        b.add_body(BodySpec {
            name: "link".into(),
            joint_name: "link".into(),
            parent: None,
            joint: JointModel::Revolute {
                axis: Vector3::y_axis(),
            },
            placement: Isometry3::identity(),
            inertia,
        })
        .expect("body");
        let model = b.build().expect("model");
        let mut data = Data::new(&model);
        let (q, v) = (
            DVector::from_element(1, 0.3),
            DVector::from_element(1, -0.2),
        );
        let tau = DVector::from_element(1, f64::NAN);
        crate::forward_dynamics_kinematics(&model, &mut data, &q, &v).expect("kinematics");
        let err = crate::forward_dynamics_solve(
            &model,
            &mut data,
            &tau,
            None,
            super::super::Algorithm::On,
        );
        assert!(matches!(
            err,
            Err(DynamicsError::NonFinite {
                argument: "tau",
                ..
            })
        ));
        let err = backward_pass(&model, &mut data, &tau);
        assert!(matches!(
            err,
            Err(DynamicsError::NonFinite {
                argument: "tau",
                ..
            })
        ));
        let ok = DVector::from_element(1, 0.5);
        assert!(crate::forward_dynamics_solve(
            &model,
            &mut data,
            &ok,
            None,
            super::super::Algorithm::On
        )
        .is_ok());
    }
}
