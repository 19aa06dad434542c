//! The 6-DoF joint steps (Euler ZXZ and free joints) of the O(n) backward and second forward
//! passes (2.67)-(2.72), (2.66), kept out of line: one such body per model.

use crate::dynamics::solve::check_pivot;
use crate::kinematics::six;
use crate::spatial::{ArticulatedInertia, Force, Motion};
use crate::{Data, DynamicsError};
use nalgebra::{DVector, Matrix6, Vector6};

/// Backward step of a 6-DoF joint: returns `M-bar - U D^-1 U^T` and `k_i`.
/// Leaves `M-bar - U D^-1 U^T` in `mbar[i]` and returns `k_i`; a root joint
/// (`propagate = false`) needs only `p_i`, its parent acceleration being zero.
#[inline(never)]
pub(super) fn six_dof_backward(
    data: &mut Data,
    i: usize,
    vi: usize,
    tau: &DVector<f64>,
    (propagate, free): (bool, bool),
) -> Result<Force, DynamicsError> {
    let j = &data.jacobian6[i];
    // `U = M-bar J`: a product only for a general `J`, else built below and only if needed.
    let mbar_j = (!free).then(|| data.mbar[i].to_matrix() * j);
    let d = match &mbar_j {
        Some(u) => j.tr_mul(u),
        None => free_joint_d(&data.mbar[i]),
    };
    let l = cholesky6(&d, vi)?;
    let hat_f = data.mbar[i].apply(&data.bias_acc[i]) - data.fbar[i];
    let jt_hat = if free {
        free_tr_mul(&hat_f)
    } else {
        j.tr_mul(&hat_f.to_vector())
    };
    let rhs = six(tau, vi) - jt_hat;
    let p = cholesky6_solve(&l, rhs);
    data.p6[i] = p;
    if !propagate {
        // `pi6[i]` stays unset: the second forward step reads it only for a joint with parent.
        return Ok(Force::zero());
    }
    let u = mbar_j.unwrap_or_else(|| free_joint_u(&data.mbar[i]));
    let mut pi = u.transpose();
    for c in 0..6 {
        let x = cholesky6_solve(&l, pi.column(c).into_owned());
        pi.set_column(c, &x);
    }
    let mbar = data.mbar[i].to_matrix();
    let (b, fbar) = (data.bias_acc[i].to_vector(), data.fbar[i].to_vector());
    let k = mbar * (b + j * p) - fbar;
    let ia: Matrix6<f64> = mbar - u * pi;
    data.pi6[i] = pi;
    data.mbar[i] = ArticulatedInertia::from_matrix(&((ia + ia.transpose()) * 0.5));
    Ok(Force::from_vector(&k))
}

/// Lower Cholesky factor `L` of the joint-space inertia `D = L L^T` (2.67) with the
/// reciprocals of its diagonal (one division per column instead of one per entry and solve
/// step), every pivot checked against its diagonal entry ([`check_pivot`], index `vi + c`):
/// fixed 6x6 loops, no generic factorisation object.
fn cholesky6(d: &Matrix6<f64>, vi: usize) -> Result<(Matrix6<f64>, [f64; 6]), DynamicsError> {
    let (mut l, mut inv) = (Matrix6::zeros(), [0.0; 6]);
    for j in 0..6 {
        let mut pivot = d[(j, j)];
        for k in 0..j {
            pivot -= l[(j, k)] * l[(j, k)];
        }
        check_pivot(vi + j, pivot, d[(j, j)])?;
        let ljj = pivot.sqrt();
        l[(j, j)] = ljj;
        inv[j] = 1.0 / ljj;
        for i in j + 1..6 {
            let mut s = d[(i, j)];
            for k in 0..j {
                s -= l[(i, k)] * l[(j, k)];
            }
            l[(i, j)] = s * inv[j];
        }
    }
    Ok((l, inv))
}

/// `D^-1 b` from the factor of [`cholesky6`]: `L y = b`, then `L^T x = y`.
fn cholesky6_solve((l, inv): &(Matrix6<f64>, [f64; 6]), mut b: Vector6<f64>) -> Vector6<f64> {
    for i in 0..6 {
        for k in 0..i {
            b[i] -= l[(i, k)] * b[k];
        }
        b[i] *= inv[i];
    }
    for i in (0..6).rev() {
        for k in i + 1..6 {
            b[i] -= l[(k, i)] * b[k];
        }
        b[i] *= inv[i];
    }
    b
}

/// `U = M-bar J` for the free joint's constant `J = [0 E; E 0]`
/// ([`crate::model::joint::quaternion_jacobian`]): with `M-bar = [A B; B^T C]`,
/// `U = [B A; C B^T]` (a block permutation, no products).
fn free_joint_u(m: &ArticulatedInertia) -> Matrix6<f64> {
    let mut u = Matrix6::zeros();
    u.fixed_view_mut::<3, 3>(0, 0).copy_from(&m.cross);
    u.fixed_view_mut::<3, 3>(0, 3).copy_from(&m.ang);
    u.fixed_view_mut::<3, 3>(3, 0).copy_from(&m.lin);
    u.fixed_view_mut::<3, 3>(3, 3)
        .copy_from(&m.cross.transpose());
    u
}

/// `D = J^T M-bar J = [C B^T; B A]` for the free joint (see [`free_joint_u`]).
fn free_joint_d(m: &ArticulatedInertia) -> Matrix6<f64> {
    let mut d = Matrix6::zeros();
    d.fixed_view_mut::<3, 3>(0, 0).copy_from(&m.lin);
    d.fixed_view_mut::<3, 3>(0, 3)
        .copy_from(&m.cross.transpose());
    d.fixed_view_mut::<3, 3>(3, 0).copy_from(&m.cross);
    d.fixed_view_mut::<3, 3>(3, 3).copy_from(&m.ang);
    d
}

/// `J^T f = [f_lin; f_ang]` for the free joint's constant `J = [0 E; E 0]` (a permutation).
#[inline]
fn free_tr_mul(f: &Force) -> Vector6<f64> {
    Vector6::new(f.lin.x, f.lin.y, f.lin.z, f.ang.x, f.ang.y, f.ang.z)
}

/// Second forward step of a 6-DoF joint body `i` (2.66): `qddot_i` into `ddq`, returns
/// `C_i a_p + J_i qddot_i`; out of line (one body per model) to keep the per-body loop small.
#[inline(never)]
pub(super) fn six_dof_forward(
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

    /// The fixed 6x6 Cholesky against nalgebra's factorisation and solve, and its pivot
    /// check on a singular matrix.
    #[test]
    fn cholesky6_matches_nalgebra() {
        let a = Matrix6::from_fn(|i, j| ((2 * i + 5 * j) % 7) as f64 * 0.4 - 1.1);
        let d = a * a.transpose() + Matrix6::identity() * 0.3;
        let factor = cholesky6(&d, 0).expect("positive definite");
        let l = factor.0;
        assert!((l * l.transpose() - d).amax() < 1e-13 * d.amax());
        for (c, inv) in factor.1.iter().enumerate() {
            assert!((inv * l[(c, c)] - 1.0).abs() < 1e-15);
        }
        let b = Vector6::new(0.3, -1.2, 0.7, 2.1, -0.4, 0.05);
        let expect = d.cholesky().expect("spd").solve(&b);
        assert!((cholesky6_solve(&factor, b) - expect).amax() < 1e-12 * expect.amax());
        let mut singular = d;
        singular.set_row(4, &d.row(1));
        singular.set_column(4, &d.column(1));
        singular[(4, 4)] = d[(1, 1)];
        assert!(matches!(
            cholesky6(&singular, 10),
            Err(DynamicsError::NotPositiveDefinite { index: 14, .. })
        ));
    }

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
        assert_eq!(free_joint_u(&m), dense * j);
        assert_eq!(free_joint_d(&m), j.transpose() * dense * j);
        let w = Vector6::new(0.3, -1.2, 0.7, 2.1, -0.4, 0.05);
        assert_eq!(free_tr_mul(&Force::from_vector(&w)), j.transpose() * w);
    }
}
