//! Sub-system branches of the O(n) algorithm (Algorithms 2.2-2.4, eqs. (2.75)-(2.90)).
//!
//! Member quantities relative to the parent `p_S` (2.77)-(2.79), computed member by member in
//! body order: `C-hat_j = C_j C-hat_p(j)`, `J-hat_j = C_j J-hat_p(j) + J_j E_j`,
//! `b-hat_j = C_j b-hat_p(j) + b_j` (members attached to `p_S` start from `C_j`, `J_j E_j`, `b_j`).
//! With `M-hat_j`, `f-hat_j` the members' `M-bar_j`, `f-bar_j` (children outside already
//! folded in by the backward pass), the sub-system quantities are (2.76)
//! `M_S = sum J-hat^T M-hat J-hat`, `B_S = sum J-hat^T M-hat C-hat`,
//! `f_S = sum J-hat^T (M-hat b-hat - f-hat)`, and
//! `P_S = -M_S^-1 B_S`, `p_S = M_S^-1 (Q_S - f_S)`,
//! `K_S = sum C-hat^T M-hat C-hat - B_S^T M_S^-1 B_S`, `k_S = B_S^T p_S + sum C-hat^T (M-hat b-hat - f-hat)`.

use super::MAX_SUBSYSTEM_DOF as MAX;
use crate::kinematics::joint_column;
use crate::spatial::{ArticulatedInertia, Force, Motion};
use crate::{Data, DynamicsError, Model};
use nalgebra::DVector;

/// Member kinematics `C-hat_j`, `J-hat_j`, `b-hat_j` of sub-system `s` (2.77)-(2.79), after
/// the first forward recursion filled `x`, `bias_acc` and the joint Jacobians.
pub(crate) fn hat_kinematics(model: &Model, data: &mut Data, s: usize) {
    let sub = &model.subsystems[s];
    let n = sub.v_set.len();
    for (m, &j) in sub.members.iter().enumerate() {
        let body = &model.bodies[j];
        let x = data.x[j];
        let mut cols = [Motion::zero(); MAX];
        match body.parent {
            Some(pp) if body.parent != sub.parent => {
                data.cbar[j] = x.compose(&data.cbar[pp]);
                for (c, col) in cols.iter_mut().enumerate().take(n) {
                    *col = x.apply_motion(&data.jbar[pp][c]);
                }
                data.bbar[j] = x.apply_motion(&data.bbar[pp]) + data.bias_acc[j];
            }
            _ => {
                data.cbar[j] = x;
                data.bbar[j] = data.bias_acc[j];
            }
        }
        for (k, &pos) in sub.columns[m].iter().take(body.v_set.len()).enumerate() {
            cols[pos] += joint_column(data, j, &body.joint, k);
        }
        data.jbar[j] = cols;
    }
}

/// Backward step of sub-system `s` (Algorithm 2.3, sub-system branch): factorises `M_S`,
/// stores `B_S` and `p_S`, and adds `K_S`, `k_S` to the parent's `M-bar`, `f-bar`.
pub(crate) fn backward(
    model: &Model,
    data: &mut Data,
    s: usize,
    tau: &DVector<f64>,
) -> Result<(), DynamicsError> {
    let sub = &model.subsystems[s];
    let n = sub.v_set.len();
    let mut ms = [[0.0; MAX]; MAX];
    let mut bs = [Force::zero(); MAX];
    let mut rhs = [0.0; MAX];
    for (c, r) in rhs.iter_mut().enumerate().take(n) {
        *r = tau[sub.v_set[c]];
    }
    let mut kc = ArticulatedInertia::zero();
    let mut fc = Force::zero();
    for &j in &sub.members {
        let m = &data.mbar[j];
        let (cj, jj) = (&data.cbar[j], &data.jbar[j]);
        let hat_f = m.apply(&data.bbar[j]) - data.fbar[j];
        for c in 0..n {
            let mj = m.apply(&jj[c]);
            for r in c..n {
                ms[r][c] += jj[r].dot(&mj);
            }
            bs[c] += cj.tr_apply_force(&mj);
            rhs[c] -= jj[c].dot(&hat_f);
        }
        if sub.parent.is_some() {
            m.add_tr_transform_to(cj, &mut kc);
            fc += cj.tr_apply_force(&hat_f);
        }
    }
    cholesky(&mut ms, n, &sub.v_set)?;
    solve(&ms, n, &mut rhs);
    data.sub_l[s] = ms;
    data.sub_b[s] = bs;
    data.sub_p[s] = rhs;
    let Some(p) = sub.parent else { return Ok(()) };
    // K_S = sum C^T M C - W^T W with W = L^-1 B_S (forward substitution over force columns).
    let mut w = bs;
    for c in 0..n {
        for k in 0..c {
            let wk = w[k];
            w[c] -= wk * ms[c][k];
        }
        w[c] = w[c] * (1.0 / ms[c][c]);
        kc.sub_outer(&w[c], 1.0);
    }
    for (c, b) in bs.iter().enumerate().take(n) {
        fc += *b * rhs[c];
    }
    data.mbar[p] += kc;
    data.fbar[p] -= fc;
    Ok(())
}

/// Second forward step of sub-system `s` (Algorithm 2.4, (2.90)): `qddot_S = P_S a_p + p_S`
/// into `ddq`, and accelerations of the members with children outside (`P_S`) only.
pub(crate) fn forward(model: &Model, data: &mut Data, s: usize) {
    let sub = &model.subsystems[s];
    let n = sub.v_set.len();
    let ap = sub.parent.map_or(Motion::zero(), |p| data.acc[p]);
    let mut y = [0.0; MAX];
    for (c, yc) in y.iter_mut().enumerate().take(n) {
        *yc = data.sub_b[s][c].dot(&ap);
    }
    solve(&data.sub_l[s], n, &mut y);
    let mut qdd = [0.0; MAX];
    for c in 0..n {
        qdd[c] = data.sub_p[s][c] - y[c];
        data.ddq[sub.v_set[c]] = qdd[c];
    }
    for &j in &sub.with_outside_children {
        let mut a = data.cbar[j].apply_motion(&ap) + data.bbar[j];
        for (c, q) in qdd.iter().enumerate().take(n) {
            a += data.jbar[j][c] * *q;
        }
        data.acc[j] = a;
    }
}

/// In-place Cholesky `M_S = L L^T` of the leading `n x n` block (lower triangle used).
fn cholesky(m: &mut [[f64; MAX]; MAX], n: usize, v_set: &[usize]) -> Result<(), DynamicsError> {
    for c in 0..n {
        let scale = m[c][c].abs();
        let d = m[c][c] - m[c][..c].iter().map(|x| x * x).sum::<f64>();
        if d <= 1e-14 * scale.max(f64::MIN_POSITIVE) || !d.is_finite() {
            return Err(DynamicsError::NotPositiveDefinite {
                index: v_set[c],
                pivot: d,
            });
        }
        let l = d.sqrt();
        m[c][c] = l;
        for r in c + 1..n {
            let dot: f64 = m[r][..c].iter().zip(&m[c][..c]).map(|(a, b)| a * b).sum();
            m[r][c] = (m[r][c] - dot) / l;
        }
    }
    Ok(())
}

/// Solves `L L^T x = b` in place with the factor of [`cholesky`].
fn solve(l: &[[f64; MAX]; MAX], n: usize, b: &mut [f64; MAX]) {
    for c in 0..n {
        for k in 0..c {
            b[c] -= l[c][k] * b[k];
        }
        b[c] /= l[c][c];
    }
    for c in (0..n).rev() {
        for k in c + 1..n {
            b[c] -= l[k][c] * b[k];
        }
        b[c] /= l[c][c];
    }
}
