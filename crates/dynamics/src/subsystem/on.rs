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

use super::axial::{AxialKind, Carried};
use super::chol::{cholesky, solve};
pub(crate) use super::rigid::add_rigid_congruence;
use super::rigid::{Axisymmetric, RigidSum};
use super::MAX_SUBSYSTEM_DOF as MAX;
use crate::kinematics::joint_column;
use crate::spatial::{ArticulatedInertia, Force, Motion, SpatialTransform};
use crate::{Data, DynamicsError, Model};
use nalgebra::DVector;

/// Calls `$f::<N>(args)` with `N` = the sub-system's DoF count for 1 and 2 (the Harmonic Drive
/// rotors, knees and ankles: fully unrolled, no work on unused columns) and `N = MAX` otherwise.
macro_rules! by_dof {
    ($n:expr, $f:ident($($a:expr),*)) => {
        match $n {
            1 => $f::<1>($($a),*),
            2 => $f::<2>($($a),*),
            _ => $f::<MAX>($($a),*),
        }
    };
}

/// Number of columns handled by the `N`-specialised branch: `N` itself for the unrolled sizes,
/// the sub-system's actual DoF count for the general (`N = MAX`) branch.
#[inline(always)]
fn dof<const N: usize>(model: &Model, s: usize) -> usize {
    if N < MAX {
        N
    } else {
        model.subsystems[s].v_set.len()
    }
}

/// Member kinematics `C-hat_j`, `J-hat_j`, `b-hat_j` of sub-system `s` (2.77)-(2.79), after
/// the first forward recursion filled `x`, `bias_acc` and the joint Jacobians.
pub(crate) fn hat_kinematics(model: &Model, data: &mut Data, s: usize) {
    by_dof!(
        model.subsystems[s].v_set.len(),
        hat_kinematics_n(model, data, s)
    )
}

/// [`hat_kinematics`] for sub-systems of at most `N` coordinates. Each column of `J-hat_j` is
/// summed in registers and stored once (accumulating in a stack array and copying it over
/// stalls on store forwarding).
#[inline]
fn hat_kinematics_n<const N: usize>(model: &Model, data: &mut Data, s: usize) {
    let sub = &model.subsystems[s];
    let n = dof::<N>(model, s);
    for (m, &j) in sub.members.iter().enumerate() {
        if data.axial_member[j].is_some() {
            continue; // Spin-invariant rotor: works in the parent frame, no member kinematics.
        }
        let body = &model.bodies[j];
        let inner = body.parent.filter(|_| body.parent != sub.parent);
        if let Some(pp) = inner {
            let x = &data.x[j];
            let (cp, bp) = hat_transform_bias(model, data, s, pp);
            (data.cbar[j], data.bbar[j]) = (x.compose(cp), x.apply_motion(bp) + data.bias_acc[j]);
        }
        let own = &sub.columns[m][..body.v_set.len()];
        for c in 0..n {
            let mut col = match inner {
                Some(pp) => data.x[j].apply_motion(&data.jbar[pp][c]),
                None => Motion::zero(),
            };
            for (k, _) in own.iter().enumerate().filter(|(_, &pos)| pos == c) {
                col += joint_column(data, j, &body.joint, k);
            }
            data.jbar[j][c] = col;
        }
    }
}

/// `C-hat_j`, `b-hat_j` of member `j` of sub-system `s` (2.77), (2.79): for a member attached
/// to `p_S` its own `C_j`, `b_j` read in place (not copied to `cbar`, `bbar`), else the
/// products stored by [`hat_kinematics`].
#[inline(always)]
fn hat_transform_bias<'d>(
    model: &Model,
    data: &'d Data,
    s: usize,
    j: usize,
) -> (&'d SpatialTransform, &'d Motion) {
    if model.bodies[j].parent == model.subsystems[s].parent {
        (&data.x[j], &data.bias_acc[j])
    } else {
        (&data.cbar[j], &data.bbar[j])
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
    by_dof!(
        model.subsystems[s].v_set.len(),
        backward_n(model, data, s, tau)
    )
}

/// [`backward`] for sub-systems of at most `N` coordinates.
#[inline]
fn backward_n<const N: usize>(
    model: &Model,
    data: &mut Data,
    s: usize,
    tau: &DVector<f64>,
) -> Result<(), DynamicsError> {
    let sub = &model.subsystems[s];
    let n = dof::<N>(model, s);
    let mut ms = [[0.0; N]; N];
    let mut bs = [Force::zero(); N];
    let mut rhs = [0.0; N];
    for (r, &v) in rhs.iter_mut().zip(&sub.v_set) {
        *r = tau.as_slice()[v];
    }
    // K_S's congruences: rigid ones summed compactly, added to `kc` once at the end.
    let (mut kc, mut rigid_kc) = (ArticulatedInertia::zero(), RigidSum::zero());
    let mut fc = Force::zero();
    let kinds = sub.rigid_member.iter().zip(&sub.axisymmetric_member);
    for (m, (&j, (&rigid, &axisymmetric))) in sub.members.iter().zip(kinds).enumerate() {
        if let Some(rc) = &data.axial_member[j] {
            if rc.rider {
                continue; // Lumped into its carrier (below).
            }
            // Axial member: its load s . h, h = C^T (M b - f) in the parent frame; a lumped
            // one's forces are in the parent's f-bar already (`Data::force_inertia`).
            let sh = match rc.lumped() {
                true => data.axial_load[j],
                false => {
                    let h = data.fbar[j];
                    fc += h;
                    rc.s.dot(&h)
                }
            };
            match rc.kind {
                // Constant K, B_S row and M_S diagonal entry, one column only.
                AxialKind::Geared => {
                    let c = rc.column;
                    ms[c][c] += rc.sks;
                    bs[c] += rc.ks;
                    rhs[c] -= sh;
                    // Its constant K is in the parent's `mbar` from the start (`mbar_init`).
                }
                // Column c of J-hat is s rho_c (see `super::axial`).
                AxialKind::Screw | AxialKind::Slider => {
                    let rho = axial_rho::<N>(model, data, &sub.columns[m], j);
                    let on = (&mut ms, &mut bs, &mut rhs);
                    add_axial(on, n, &rho, &rc.ks, rc.sks, sh);
                    if rc.kind == AxialKind::Slider {
                        // Its K moves with its CoM; a rotor's constant K is in `mbar_init`.
                        let c = rc.state(data, j).0;
                        rigid_kc += RigidSum::at(rc.mass, &c, &rc.inertia_com);
                    }
                }
            }
            continue;
        }
        let m = &data.mbar[j];
        let carried = data.carried[j].as_ref();
        let lumped = carried.map(|cr| cr.lumped(model, data));
        let inertia = lumped.as_ref().unwrap_or(&model.bodies[j].inertia);
        let axisymmetric = carried.map_or(axisymmetric, |cr| cr.axisymmetric);
        let ((cj, bj), jj, fj) = (
            hat_transform_bias(model, data, s, j),
            &data.jbar[j],
            &data.fbar[j],
        );
        let on = (&mut ms, &mut bs, &mut rhs);
        // A rigid member's M-hat is its rigid-body inertia: the compact form (2.22), shorter
        // still for an axisymmetric one.
        let hat_f = match (axisymmetric, rigid) {
            (true, _) => {
                let ax = Axisymmetric::of(inertia);
                add_member(on, n, jj, cj, bj, fj, |a| ax.apply(a))
            }
            (false, true) => add_member(on, n, jj, cj, bj, fj, |a| inertia.apply(a)),
            (false, false) => add_member(on, n, jj, cj, bj, fj, |a| m.apply(a)),
        };
        if let Some(cr) = carried {
            let on = (&mut ms, &mut bs, &mut rhs);
            add_riders(on, n, (model, data), cr, (jj, cj, bj));
        }
        if sub.parent.is_some() {
            if rigid {
                rigid_kc += RigidSum::congruence(inertia, cj);
            } else if let (Some(k), true) =
                (data.plane_axis[j], model.bodies[j].parent == sub.parent)
            {
                // C-hat_j = C_j for a member on the sub-system's parent.
                m.add_tr_transform_axis_to(k, cj, &mut kc);
            } else {
                m.add_tr_transform_to(cj, &mut kc);
            }
            fc += cj.tr_apply_force(&hat_f);
        }
    }
    rigid_kc.add_to(&mut kc);
    cholesky(&mut ms, n, &sub.v_set)?;
    solve(&ms, n, &mut rhs);
    for r in 0..n {
        data.sub_l[s][r][..=r].copy_from_slice(&ms[r][..=r]);
    }
    data.sub_b[s][..n].copy_from_slice(&bs[..n]);
    data.sub_p[s][..n].copy_from_slice(&rhs[..n]);
    let Some(p) = sub.parent else { return Ok(()) };
    // K_S = sum C^T M C - W^T W with W = L^-1 B_S (forward substitution over force columns).
    let mut w = bs;
    for c in 0..n {
        for k in 0..c {
            let wk = w[k];
            w[c] -= wk * ms[c][k];
        }
        w[c] = w[c] * ms[c][c]; // The factor's diagonal is stored inverted.
    }
    sub_gram(&mut kc, &w, n);
    for (b, r) in bs.iter().zip(&rhs).take(n) {
        fc += *b * *r;
    }
    data.mbar[p] += kc;
    data.fbar[p] -= fc;
    Ok(())
}

/// `k -= W W^T` for the force columns `w[..n]` of `W`, the `B_S^T M_S^-1 B_S` of `K_S` (2.76)
/// in one pass (symmetric blocks on one triangle, mirrored).
#[inline(always)]
fn sub_gram<const N: usize>(k: &mut ArticulatedInertia, w: &[Force; N], n: usize) {
    for i in 0..3 {
        for j in 0..3 {
            let cross: f64 = w[..n].iter().map(|u| u.ang[i] * u.lin[j]).sum();
            k.cross[(i, j)] -= cross;
        }
        for j in i..3 {
            let ang: f64 = w[..n].iter().map(|u| u.ang[i] * u.ang[j]).sum();
            let lin: f64 = w[..n].iter().map(|u| u.lin[i] * u.lin[j]).sum();
            k.ang[(i, j)] -= ang;
            k.lin[(i, j)] -= lin;
            if j != i {
                k.ang[(j, i)] -= ang;
                k.lin[(j, i)] -= lin;
            }
        }
    }
}

/// Adds member `j`'s terms of (2.76) to `M_S`, `B_S` and the right-hand side `Q_S - f_S`:
/// `J-hat^T M-hat J-hat`, `C-hat^T M-hat J-hat` and `-J-hat^T f-hat`, with `M-hat` applied by
/// `apply` (monomorphised per inertia kind); returns `f-hat = M-hat b-hat - f-bar` (member frame).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn add_member<const N: usize>(
    (ms, bs, rhs): (&mut [[f64; N]; N], &mut [Force; N], &mut [f64; N]),
    n: usize,
    jj: &[Motion; MAX],
    cj: &SpatialTransform,
    bj: &Motion,
    fj: &Force,
    apply: impl Fn(&Motion) -> Force,
) -> Force {
    let hat_f = apply(bj) - *fj;
    for c in 0..n {
        let mj = apply(&jj[c]);
        for r in c..n {
            ms[r][c] += jj[r].dot(&mj);
        }
        bs[c] += cj.tr_apply_force(&mj);
        rhs[c] -= jj[c].dot(&hat_f);
    }
    hat_f
}

/// Adds the riders' own columns of (2.76) for a carrier member with `J-hat`, `C-hat`, `b-hat`
/// = `(jj, cj, bj)` whose lumped inertia [`add_member`] applied: rider `r` moves with the
/// carrier plus `s rho_r qdot`, so with `u = K s` (carrier frame) it adds
/// `J_r . u rho_c + rho_r J_c . u + rho_r rho_c s^T K s` to `M_S`, `C-hat^T u rho_c` to `B_S`
/// and `-rho_c (u . b-hat + s . h)` to the right-hand side (`h` its bias, in `fbar`).
#[inline(always)]
fn add_riders<const N: usize>(
    (ms, bs, rhs): (&mut [[f64; N]; N], &mut [Force; N], &mut [f64; N]),
    n: usize,
    (model, data): (&Model, &Data),
    carried: &Carried,
    (jj, cj, bj): (&[Motion; MAX], &SpatialTransform, &Motion),
) {
    for &(r, mr) in &carried.riders {
        let sub_columns = &model.subsystems[carried.subsystem].columns[mr];
        let Some(rc) = &data.axial_member[r] else {
            continue;
        };
        let u = rc.ks;
        let rho = axial_rho::<N>(model, data, sub_columns, r);
        let e = bj.dot(&u) + rc.s.dot(&data.fbar[r]);
        let cu = cj.tr_apply_force(&u);
        let mut ju = [0.0; N];
        for c in 0..n {
            ju[c] = jj[c].dot(&u);
        }
        for c in 0..n {
            for k in c..n {
                ms[k][c] += ju[k] * rho[c] + rho[k] * ju[c];
            }
        }
        add_axial((ms, bs, rhs), n, &rho, &cu, rc.sks, e);
    }
}

/// `rho` of axial member `j` (3.32): its row `d x / d q_in` scattered to the sub-system's
/// columns `cols` (the member's column of `J-hat` is `s rho`).
#[inline(always)]
fn axial_rho<const N: usize>(
    model: &Model,
    data: &Data,
    cols: &[usize; crate::model::MAX_INDEX_SET],
    j: usize,
) -> [f64; N] {
    let mut rho = [0.0; N];
    let row = &data.axial_motion[j].row;
    for (&c, &x) in cols.iter().zip(row).take(model.bodies[j].v_set.len()) {
        rho[c] += x;
    }
    rho
}

/// Adds an axial column `s rho` to (2.76) with `ks` its `C-hat^T M s`, `sks = s^T M s` and
/// `load` its bias load: `sks rho rho^T` to `M_S` (lower triangle), `ks rho^T` to `B_S` and
/// `-rho load` to the right-hand side.
#[inline(always)]
fn add_axial<const N: usize>(
    (ms, bs, rhs): (&mut [[f64; N]; N], &mut [Force; N], &mut [f64; N]),
    n: usize,
    rho: &[f64; N],
    ks: &Force,
    sks: f64,
    load: f64,
) {
    for c in 0..n {
        bs[c] += *ks * rho[c];
        rhs[c] -= rho[c] * load;
        let src = rho[c] * sks;
        for k in c..n {
            ms[k][c] += rho[k] * src;
        }
    }
}

/// Second forward step of sub-system `s` (Algorithm 2.4, (2.90)): `qddot_S = P_S a_p + p_S`
/// into `ddq`, and accelerations of the members with children outside (`P_S`) only.
pub(crate) fn forward(model: &Model, data: &mut Data, s: usize) {
    by_dof!(model.subsystems[s].v_set.len(), forward_n(model, data, s))
}

/// [`forward`] for sub-systems of at most `N` coordinates.
#[inline]
fn forward_n<const N: usize>(model: &Model, data: &mut Data, s: usize) {
    let sub = &model.subsystems[s];
    let n = dof::<N>(model, s);
    let ap = sub.parent.map_or(Motion::zero(), |p| data.acc[p]);
    let mut y = [0.0; N];
    for (yc, b) in y.iter_mut().zip(&data.sub_b[s]).take(n) {
        *yc = b.dot(&ap);
    }
    solve(&data.sub_l[s], n, &mut y);
    let mut qdd = [0.0; N];
    for c in 0..n {
        qdd[c] = data.sub_p[s][c] - y[c];
        data.ddq.as_mut_slice()[sub.v_set[c]] = qdd[c];
    }
    for &j in &sub.with_outside_children {
        let (cj, bj) = hat_transform_bias(model, data, s, j);
        let mut a = cj.apply_motion(&ap) + *bj;
        for (col, q) in data.jbar[j].iter().zip(&qdd).take(n) {
            a += *col * *q;
        }
        data.acc[j] = a;
    }
}

#[cfg(test)]
mod tests;
