//! Step 3 of Algorithm 2.1, the backward recursion (Algorithm 2.3), rigid-body branch (lines
//! 15-18, (2.67)-(2.72)), and the driver over the rewired body list from the leaves to the root.

use super::first::Kinematics;
use super::subsystem::subsystem_step;
use super::{children, malformed};
use crate::subsystem::NodeKind;
use crate::{DynamicsError, Model};
use nalgebra::{Cholesky, DMatrix, DVector, Dyn, Matrix6, MatrixXx6, Vector6};

/// Propagation quantities of one node: `qddot = P a_p + p` (2.66), and `K`, `k` passed to the
/// parent as `C^T K`, `C^T k` (2.69)-(2.70).
#[derive(Clone, Debug)]
pub(super) struct Propagation {
    /// `P_i` (2.67) or `P_S` (2.80).
    pub(super) p_mat: MatrixXx6<f64>,
    /// `p_i` (2.68) or `p_S` (2.81).
    pub(super) p_vec: DVector<f64>,
    /// `K_i` (2.71) or `K_S` (2.84).
    pub(super) k_mat: Matrix6<f64>,
    /// `k_i` (2.72) or `k_S` (2.85).
    pub(super) k_vec: Vector6<f64>,
}

/// Impressed quantities of step 2: `M_i` (2.22) and `f_i` (2.56) per body, and `Q = tau`.
pub(super) struct Impressed<'a> {
    /// `M_i` per body.
    pub(super) mass: &'a [Matrix6<f64>],
    /// `f_i` per body.
    pub(super) force: &'a [Vector6<f64>],
    /// Generalized forces `Q`.
    pub(super) tau: &'a DVector<f64>,
}

/// Algorithm 2.3: every node from the last to the first, a body by [`body_step`], a
/// sub-system by [`subsystem_step`]; the children of a node are done before it.
pub(super) fn backward(
    model: &Model,
    kin: &Kinematics,
    imp: &Impressed,
) -> Result<Vec<Propagation>, DynamicsError> {
    let nodes = model.nodes();
    let mut props: Vec<Option<Propagation>> = vec![None; nodes.len()];
    for (n, node) in nodes.iter().enumerate().rev() {
        let prop = match node.kind {
            NodeKind::Body(i) => body_step(model, kin, imp, &props, (n, i))?,
            NodeKind::Subsystem(s) => subsystem_step(model, kin, imp, &props, (n, s))?,
        };
        props[n] = Some(prop);
    }
    props
        .into_iter()
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| malformed("a node without propagation quantities"))
}

/// What a child node `c` passes to its parent: `C_c^T K_c`, `C_c^T k_c` (2.69)-(2.70).
pub(super) struct ChildTerm {
    /// `p(c)`: the body `c` hangs from (`None` = the world).
    pub(super) attach: Option<usize>,
    /// `C_c^T K_c`.
    pub(super) ck: Matrix6<f64>,
    /// `C_c^T k_c`.
    pub(super) ck_vec: Vector6<f64>,
}

/// The [`ChildTerm`] of every child node of node `n`, with `C_c = E` for a sub-system (2.88).
pub(super) fn child_terms(
    model: &Model,
    kin: &Kinematics,
    props: &[Option<Propagation>],
    n: usize,
) -> Result<Vec<ChildTerm>, DynamicsError> {
    let mut out = Vec::new();
    for c in children(model, n) {
        let prop = props[c]
            .as_ref()
            .ok_or_else(|| malformed("a child before its parent in the node list"))?;
        let (attach, ct) = match model.nodes()[c].kind {
            NodeKind::Body(j) => (model.bodies()[j].parent(), kin.bodies[j].c.transpose()),
            NodeKind::Subsystem(s) => (model.subsystems()[s].parent(), Matrix6::identity()),
        };
        out.push(ChildTerm {
            attach,
            ck: ct * prop.k_mat,
            ck_vec: ct * prop.k_vec,
        });
    }
    Ok(out)
}

/// Algorithm 2.3, lines 15-18, for body `i` (node `n`): `M-bar_i = M_i + sum C_j^T K_j`,
/// `f-bar_i = f_i - sum C_j^T k_j` (2.69)-(2.70), then (2.67)-(2.72). Line 18 of the
/// algorithm reads `f_i` and `- Q_i` where (2.68) has `f-bar_i` and `+ Q_i`; (2.68) is used.
fn body_step(
    model: &Model,
    kin: &Kinematics,
    imp: &Impressed,
    props: &[Option<Propagation>],
    (n, i): (usize, usize),
) -> Result<Propagation, DynamicsError> {
    let (mut mbar, mut fbar) = (imp.mass[i], imp.force[i]);
    for child in child_terms(model, kin, props, n)? {
        mbar += child.ck;
        fbar -= child.ck_vec;
    }
    let body = &model.bodies()[i];
    let k = &kin.bodies[i];
    let (j, c, b) = (&k.jacobian, &k.c, &k.b);
    let q_i = DVector::from_iterator(
        body.v_set().len(),
        body.v_set().as_slice().iter().map(|&x| imp.tau[x]),
    );
    let d = j.transpose() * mbar * j;
    let (p_mat, p_vec) = if j.ncols() == 0 {
        (MatrixXx6::zeros(0), DVector::zeros(0)) // A fixed joint: `J_i` is empty.
    } else {
        let chol = factor(d, body.v_index())?;
        let p_mat: MatrixXx6<f64> = -chol.solve(&(j.transpose() * mbar * c)); // (2.67)
        let p_vec = -chol.solve(&(j.transpose() * (mbar * b - fbar) - q_i)); // (2.68)
        (p_mat, p_vec)
    };
    Ok(Propagation {
        k_mat: mbar * (c + j * &p_mat),        // (2.71)
        k_vec: mbar * (j * &p_vec + b) - fbar, // (2.72)
        p_mat,
        p_vec,
    })
}

/// Cholesky factor of a (projected) mass matrix; its smallest diagonal entry as the pivot of
/// the error if it is not positive definite (coordinate `index`).
pub(super) fn factor(d: DMatrix<f64>, index: usize) -> Result<Cholesky<f64, Dyn>, DynamicsError> {
    let pivot = d.diagonal().min();
    Cholesky::new(d).ok_or(DynamicsError::NotPositiveDefinite { index, pivot })
}
