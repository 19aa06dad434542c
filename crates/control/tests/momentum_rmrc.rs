//! The momentum terms through the crate's Klein-Huang solver (`ik::Rmrc`, Alg. 4.3) on Lola
//! Type 2: the compensation vector is a valid `null_space` gradient input (sign of (7.8)),
//! and the minimisation weight gives the same step as a dense solve with `W` inverted densely.

#[path = "momentum_util.rs"]
mod util;

use biped_control::ik::{Rmrc, RmrcProblem};
use biped_control::momentum::{
    Compensation, CompensationLaw, MomentumMinimisation, VerticalMomentum, LOLA_ARM_FLEXION,
};
use biped_control::Weight;
use nalgebra::{DMatrix, DVector};
use util::{rel, Lola};

#[test]
fn compensation_as_rmrc_null_space_input_reaches_the_reference() {
    let mut s = Lola::new(31);
    let model = s.lola.model.clone();
    let n = model.nv();
    let comp = Compensation::new(&model, &LOLA_ARM_FLEXION, CompensationLaw::Exact).unwrap();
    // Tasks fix every producing DoF (q_r := q_free): J_x = S_p, xdot = S_p qdot_p.
    let rows: Vec<usize> = (0..n).filter(|&i| !comp.is_reducing(i)).collect();
    let jx = DMatrix::from_fn(rows.len(), n, |a, b| if rows[a] == b { 1.0 } else { 0.0 });
    let mut vm = VerticalMomentum::new(&model);
    let mut solver = Rmrc::new(rows.len(), n);
    let mut qdot = DVector::zeros(n);
    for _ in 0..5 {
        let (q, qdot_p) = s.state();
        let l_d = s.vector(1)[0];
        vm.compute(&model, &mut s.data, &mut s.centroidal, &q)
            .unwrap();
        let mut y = DVector::zeros(n);
        comp.add_to(vm.jacobian_z(), &qdot_p, l_d, &mut y).unwrap();
        let xdot = &jx * &qdot_p;
        let mut problem = RmrcProblem::new(&jx, rows.len(), &xdot, &Weight::Identity);
        problem.null_space = Some((&y, 1.0));
        solver.solve(&problem, &mut qdot).unwrap();
        assert!(rel(vm.lz(&qdot).unwrap(), l_d) < 1e-8);
        for &i in &rows {
            assert!(
                (qdot[i] - qdot_p[i]).abs() < 1e-9,
                "producing DoFs keep their tasks"
            );
        }
    }
}

#[test]
fn minimisation_weight_in_rmrc_matches_dense_solve() {
    let mut s = Lola::new(32);
    let model = s.lola.model.clone();
    let n = model.nv();
    let m = 14;
    let mut vm = VerticalMomentum::new(&model);
    let minimise = MomentumMinimisation::new(0.5).unwrap();
    let mut w = minimise.weight(n).unwrap();
    let mut solver = Rmrc::new(m, n);
    let mut qdot = DVector::zeros(n);
    for _ in 0..5 {
        let (q, _) = s.state();
        let jx = DMatrix::from_fn(m, n, |_, _| s.vector(1)[0]);
        let xdot = s.vector(m);
        let grad = s.vector(n);
        vm.compute(&model, &mut s.data, &mut s.centroidal, &q)
            .unwrap();
        minimise.update(vm.jacobian_z(), &mut w).unwrap();
        let mut problem = RmrcProblem::new(&jx, m, &xdot, &w);
        problem.null_space = Some((&grad, 0.3));
        solver.solve(&problem, &mut qdot).unwrap();
        // Dense (4.12): qdot = J#_W xdot - alpha N W^-1 grad with W inverted densely.
        let a = vm.jacobian_z();
        let winv = (DMatrix::identity(n, n) * 0.5 + a * a.transpose())
            .try_inverse()
            .unwrap();
        let pinv_w = &winv * jx.transpose() * (&jx * &winv * jx.transpose()).try_inverse().unwrap();
        let null = DMatrix::identity(n, n) - &pinv_w * &jx;
        let dense = &pinv_w * &xdot - null * &winv * &grad * 0.3;
        assert!((&qdot - &dense).norm() < 1e-8 * dense.norm().max(1.0));
    }
}
