//! Step 4 of Algorithm 2.1, the second forward recursion (Algorithm 2.4): `qddot_i = P_i
//! a_p(i) + p_i` (2.66), `a_i = C_i a_p(i) + J_i qddot_i + b_i` (2.34) for bodies; for a
//! sub-system `a_S = a_p(S)` (2.89), `qddot_S = P_S a_S + p_S` (2.79) and `a_j = C-hat_j a_S +
//! J-hat_j qddot_S + b-hat_j` (2.90) for its members with children outside, `P_S`.

use super::backward::Propagation;
use super::first::Kinematics;
use super::{children, malformed, Solution};
use crate::subsystem::NodeKind;
use crate::{DynamicsError, Model};
use nalgebra::{DVector, Vector6};

/// Generalized accelerations `qddot` and the body accelerations `a_i` it formed (bodies
/// outside sub-systems and members in `P_S`).
pub(super) fn second_forward(
    model: &Model,
    kin: &Kinematics,
    props: &[Propagation],
) -> Result<Solution, DynamicsError> {
    let mut qdd = DVector::zeros(model.nv());
    let mut acc: Vec<Option<Vector6<f64>>> = vec![None; model.nbodies()];
    for (n, (node, prop)) in model.nodes().iter().zip(props).enumerate() {
        let (parent, v_set) = match node.kind {
            NodeKind::Body(i) => (
                model.bodies()[i].parent(),
                model.bodies()[i].v_set().as_slice(),
            ),
            NodeKind::Subsystem(s) => (
                model.subsystems()[s].parent(),
                model.subsystems()[s].v_set(),
            ),
        };
        // a_0 = 0 for the inertially fixed environment.
        let a_p = match parent {
            None => Vector6::zeros(),
            Some(p) => acc[p].ok_or_else(|| malformed("a parent without acceleration"))?,
        };
        let qdd_i = &prop.p_mat * a_p + &prop.p_vec; // (2.66), (2.79)
        for (&k, x) in v_set.iter().zip(qdd_i.iter()) {
            qdd[k] = *x;
        }
        match node.kind {
            NodeKind::Body(i) => {
                let k = &kin.bodies[i];
                acc[i] = Some(k.c * a_p + &k.jacobian * &qdd_i + k.b); // (2.34)
            }
            NodeKind::Subsystem(s) => {
                let sub = &model.subsystems()[s];
                for j in outside_parents(model, n) {
                    let m = sub.members().iter().position(|&x| x == j);
                    let hat = &kin.hats[s][m.ok_or_else(|| malformed("P_S outside N_S"))?];
                    acc[j] = Some(hat.c * a_p + &hat.jacobian * &qdd_i + hat.b);
                    // (2.90)
                }
            }
        }
    }
    Ok(Solution { qddot: qdd, acc })
}

/// `P_S` (Fig. 2.11) of the sub-system at node `n`: the members its child nodes hang from.
fn outside_parents(model: &Model, n: usize) -> Vec<usize> {
    let mut out: Vec<usize> = children(model, n)
        .filter_map(|c| match model.nodes()[c].kind {
            NodeKind::Body(j) => model.bodies()[j].parent(),
            NodeKind::Subsystem(s) => model.subsystems()[s].parent(),
        })
        .collect();
    out.sort_unstable();
    out.dedup();
    out
}
