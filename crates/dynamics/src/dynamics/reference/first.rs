//! Step 1 of Algorithm 2.1, the first forward recursion (Algorithm 2.2): `C_i`, `v_i`, `J_i`,
//! `b_i` of every body (2.33)-(2.37) and, per sub-system, the member quantities `C-hat_j`,
//! `J-hat_j`, `b-hat_j` relative to the sub-system's parent (lines 6-9).

use super::body::{lower, stack, transform, upper};
use super::joint::relative;
use super::malformed;
use crate::subsystem::{NodeKind, Subsystem};
use crate::{DynamicsError, Model};
use nalgebra::{DVector, Matrix3, Matrix6, Matrix6xX, Vector6};

/// A parent visited after its child.
const PARENT_FIRST: &str = "a parent after its child in the node list";
/// A member whose path to the sub-system's parent leaves the sub-system.
const MEMBER_PATH: &str = "a sub-system member not connected to its parent through members";

/// Kinematic quantities of one body (Algorithm 2.2, lines 6 and 12).
#[derive(Clone, Debug)]
pub(super) struct BodyKinematics {
    /// `C_i` (2.36).
    pub(super) c: Matrix6<f64>,
    /// `A_kI`: world coordinates to body coordinates.
    pub(super) rot_ki: Matrix3<f64>,
    /// `v_i = [omega; rdot_O]` (2.33), body coordinates.
    pub(super) vel: Vector6<f64>,
    /// `J_i` (2.35), one column per entry of the body's index set.
    pub(super) jacobian: Matrix6xX<f64>,
    /// `b_i` (2.37).
    pub(super) b: Vector6<f64>,
}

/// A member's quantities relative to its sub-system's parent: `a_j = C-hat_j a_S + J-hat_j
/// qddot_S + b-hat_j` (2.90).
#[derive(Clone, Debug)]
pub(super) struct Hat {
    /// `C-hat_j`.
    pub(super) c: Matrix6<f64>,
    /// `J-hat_j`, one column per coordinate of `q_S` (the framed part of (2.63)).
    pub(super) jacobian: Matrix6xX<f64>,
    /// `b-hat_j`.
    pub(super) b: Vector6<f64>,
}

/// Results of the first forward recursion.
#[derive(Clone, Debug)]
pub(super) struct Kinematics {
    /// Per body, in body order.
    pub(super) bodies: Vec<BodyKinematics>,
    /// Per sub-system, one entry per member in member order.
    pub(super) hats: Vec<Vec<Hat>>,
}

/// Algorithm 2.2 over the rewired body list: a body node takes line 12, a sub-system node its
/// members' kinematics (line 6) and their hat quantities (lines 7-9).
pub(super) fn first_forward(
    model: &Model,
    q: &[f64],
    v: &[f64],
) -> Result<Kinematics, DynamicsError> {
    let mut bodies: Vec<Option<BodyKinematics>> = vec![None; model.nbodies()];
    let mut hats: Vec<Option<Vec<Hat>>> = vec![None; model.subsystems().len()];
    for node in model.nodes() {
        match node.kind {
            NodeKind::Body(i) => bodies[i] = Some(body_kinematics(model, &bodies, i, q, v)?),
            NodeKind::Subsystem(s) => {
                let sub = &model.subsystems()[s];
                for &j in sub.members() {
                    bodies[j] = Some(body_kinematics(model, &bodies, j, q, v)?);
                }
                hats[s] = Some(hat_kinematics(model, sub, &bodies)?);
            }
        }
    }
    let bodies = bodies.into_iter().collect::<Option<Vec<_>>>();
    let hats = hats.into_iter().collect::<Option<Vec<_>>>();
    match (bodies, hats) {
        (Some(bodies), Some(hats)) => Ok(Kinematics { bodies, hats }),
        _ => Err(malformed("a body or sub-system missing from the node list")),
    }
}

/// `C_i` (2.36), `v_i = C_i v_p + J_i qdot_i` (2.33) and `b_i` (2.37) of body `i`, with
/// `omega_p` and `r_PO` written in the body frame `k`:
/// `b_i = [omega_p x J_R qdot; omega_p x (2 J_T qdot + omega_p x r_PO)] + Jdot_i qdot_i`.
fn body_kinematics(
    model: &Model,
    done: &[Option<BodyKinematics>],
    i: usize,
    q: &[f64],
    v: &[f64],
) -> Result<BodyKinematics, DynamicsError> {
    let body = &model.bodies()[i];
    let rel = relative(body, i, q, v)?;
    let rot_kp = rel.rot_pk.transpose();
    let c = transform(&rot_kp, &rel.r_po);
    let (v_p, rot_pi) = match body.parent() {
        None => (Vector6::zeros(), Matrix3::identity()),
        Some(p) => {
            let parent = done[p].as_ref().ok_or_else(|| malformed(PARENT_FIRST))?;
            (parent.vel, parent.rot_ki)
        }
    };
    let qdot = DVector::from_iterator(
        body.v_set().len(),
        body.v_set().as_slice().iter().map(|&k| v[k]),
    );
    let rel_vel: Vector6<f64> = &rel.jacobian * qdot;
    let (w_p, r) = (rot_kp * upper(&v_p), rot_kp * rel.r_po);
    let (w_rel, v_rel) = (upper(&rel_vel), lower(&rel_vel));
    let b = stack(
        &w_p.cross(&w_rel),
        &w_p.cross(&(v_rel * 2.0 + w_p.cross(&r))),
    );
    Ok(BodyKinematics {
        vel: c * v_p + rel_vel,
        c,
        rot_ki: rot_kp * rot_pi,
        jacobian: rel.jacobian,
        b: b + rel.jdot_qdot,
    })
}

/// Algorithm 2.2, lines 7-9, in member order (parents first): `C-hat_j = C_j C-hat_p(j)`,
/// `J-hat_j = C_j J-hat_p(j) + J_j E_j`, `b-hat_j = C_j b-hat_p(j) + b_j`, starting from
/// `C-hat = E`, `J-hat = 0`, `b-hat = 0` at the sub-system's parent (2.88)-(2.89). `E_j` places
/// the columns of `J_j` at their coordinates in `q_S`. The extracted text lacks the recursive
/// form (2.78) of `J-hat_j`; this one reproduces the framed part of (2.63).
fn hat_kinematics(
    model: &Model,
    sub: &Subsystem,
    bodies: &[Option<BodyKinematics>],
) -> Result<Vec<Hat>, DynamicsError> {
    let n = sub.v_set().len();
    let mut hats: Vec<Hat> = Vec::with_capacity(sub.members().len());
    for &j in sub.members() {
        let kin = bodies[j].as_ref().ok_or_else(|| malformed(PARENT_FIRST))?;
        let body = &model.bodies()[j];
        let (c_p, j_p, b_p) = match body.parent() {
            p if p == sub.parent() => (Matrix6::identity(), Matrix6xX::zeros(n), Vector6::zeros()),
            Some(p) => {
                let m = sub.members().iter().position(|&x| x == p);
                let hat = m
                    .and_then(|m| hats.get(m))
                    .ok_or_else(|| malformed(MEMBER_PATH))?;
                (hat.c, hat.jacobian.clone(), hat.b)
            }
            None => return Err(malformed(MEMBER_PATH)),
        };
        let mut jacobian = kin.c * j_p;
        for (col, k) in body.v_set().as_slice().iter().enumerate() {
            let at = sub.v_set().iter().position(|x| x == k);
            let at = at.ok_or_else(|| malformed(MEMBER_PATH))?;
            for r in 0..6 {
                jacobian[(r, at)] += kin.jacobian[(r, col)];
            }
        }
        hats.push(Hat {
            c: kin.c * c_p,
            jacobian,
            b: kin.c * b_p + kin.b,
        });
    }
    Ok(hats)
}
