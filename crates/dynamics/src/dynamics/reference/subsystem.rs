//! Step 3 of Algorithm 2.1 for a sub-system node (Algorithm 2.3, lines 2-13): the member
//! loads `M-hat_j`, `f-hat_j` (2.77), the sub-system quantities (2.76), (2.86)-(2.87) and its
//! propagation quantities (2.80)-(2.85).

use super::backward::{child_terms, factor, Impressed, Propagation};
use super::first::Kinematics;
use super::malformed;
use crate::{DynamicsError, Model};
use nalgebra::{DMatrix, DVector, Matrix6, MatrixXx6, Vector6};

/// `M-hat_j` and `f-hat_j` per member (2.77).
type Loads = (Vec<Matrix6<f64>>, Vec<Vector6<f64>>);

/// Sums over the members (Algorithm 2.3, lines 9-11).
struct Sums {
    /// `M_S = sum J-hat^T M-hat J-hat` (2.76a).
    m_s: DMatrix<f64>,
    /// `B_S = sum J-hat^T M-hat C-hat` (2.76b).
    b_s: MatrixXx6<f64>,
    /// `f_S = sum J-hat^T (M-hat b-hat - f-hat)` (2.76c).
    f_s: DVector<f64>,
    /// `M-bar_S = sum C-hat^T M-hat C-hat` (2.86).
    mbar_s: Matrix6<f64>,
    /// `f-bar_S = sum C-hat^T (M-hat b-hat - f-hat)` (2.87).
    fbar_s: Vector6<f64>,
}

/// Algorithm 2.3, lines 2-13, for sub-system `s` (node `n`).
///
/// Signs: line 12-13 read `P = M_S^-1 B_S`, `p = M_S^-1 (f_S - Q_S)`; (2.80)-(2.81) have a
/// leading minus, which the forward recursion `qddot_S = P_S a + p_S` (Algorithm 2.4, line 2)
/// needs, so (2.80)-(2.81) are used. (2.85) reads `k_S = B_S^T p_S - f-bar_S`, line 13
/// `+ f-bar_S`; with `f-bar_S` of (2.87) (already `M-hat b-hat - f-hat`) the sum
/// `sum C-hat^T (M-hat (J-hat p_S + b-hat) - f-hat)` of (2.72) gives `+`, so line 13 is used.
pub(super) fn subsystem_step(
    model: &Model,
    kin: &Kinematics,
    imp: &Impressed,
    props: &[Option<Propagation>],
    (n, s): (usize, usize),
) -> Result<Propagation, DynamicsError> {
    let sub = &model.subsystems()[s];
    let (m_hat, f_hat) = member_loads(model, kin, imp, props, (n, s))?;
    let sums = member_sums(kin, s, sub.v_set().len(), &m_hat, &f_hat);
    let q_s = DVector::from_iterator(sub.v_set().len(), sub.v_set().iter().map(|&x| imp.tau[x]));
    let index = sub.v_set().first().copied().unwrap_or(0);
    let chol = factor(sums.m_s, index)?;
    let p_mat: MatrixXx6<f64> = -chol.solve(&sums.b_s); // (2.80)
    let p_vec = -chol.solve(&(sums.f_s - q_s)); // (2.81)
    Ok(Propagation {
        k_mat: sums.mbar_s + sums.b_s.transpose() * &p_mat, // (2.84)
        k_vec: sums.b_s.transpose() * &p_vec + sums.fbar_s, // (2.85), sign of line 13
        p_mat,
        p_vec,
    })
}

/// Algorithm 2.3, lines 3-8: `M-hat_j = M_j`, `f-hat_j = f_j`, then for every child `k` outside
/// the sub-system `M-hat_p(k) += C_k^T K_k`, `f-hat_p(k) -= C_k^T k_k`. (2.77a) writes
/// `C_k^T M-bar_k` and (2.77b) `+ C_k^T f-bar_k`; the algorithm's `K_k`, `-k_k` are what
/// (2.69)-(2.70) and the example `M-hat_3 = M-bar_3` give, so those are used.
fn member_loads(
    model: &Model,
    kin: &Kinematics,
    imp: &Impressed,
    props: &[Option<Propagation>],
    (n, s): (usize, usize),
) -> Result<Loads, DynamicsError> {
    let members = model.subsystems()[s].members();
    let mut m_hat: Vec<Matrix6<f64>> = members.iter().map(|&j| imp.mass[j]).collect();
    let mut f_hat: Vec<Vector6<f64>> = members.iter().map(|&j| imp.force[j]).collect();
    for child in child_terms(model, kin, props, n)? {
        let m = child
            .attach
            .and_then(|p| members.iter().position(|&j| j == p));
        let m = m.ok_or_else(|| malformed("a sub-system child not attached to a member"))?;
        m_hat[m] += child.ck;
        f_hat[m] -= child.ck_vec;
    }
    Ok((m_hat, f_hat))
}

/// Algorithm 2.3, lines 9-11: the sums (2.76), (2.86), (2.87) over the members.
fn member_sums(
    kin: &Kinematics,
    s: usize,
    dof: usize,
    m_hat: &[Matrix6<f64>],
    f_hat: &[Vector6<f64>],
) -> Sums {
    let mut sums = Sums {
        m_s: DMatrix::zeros(dof, dof),
        b_s: MatrixXx6::zeros(dof),
        f_s: DVector::zeros(dof),
        mbar_s: Matrix6::zeros(),
        fbar_s: Vector6::zeros(),
    };
    for ((hat, m), f) in kin.hats[s].iter().zip(m_hat).zip(f_hat) {
        let (jt, ct) = (hat.jacobian.transpose(), hat.c.transpose());
        let load = m * hat.b - f;
        sums.m_s += &jt * m * &hat.jacobian;
        sums.b_s += &jt * m * hat.c;
        sums.f_s += &jt * load;
        sums.mbar_s += ct * m * hat.c;
        sums.fbar_s += ct * load;
    }
    sums
}
