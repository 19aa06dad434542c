//! The minimisation weight through the crate's Klein-Huang solver (`ik::Rmrc`, Alg. 4.3) on
//! Lola Type 2 gives the same step as a dense solve with `W` inverted densely (the
//! compensation through the solver: `momentum_compensation.rs`).

#[path = "momentum_util.rs"]
mod util;

use biped_control::ik::{Rmrc, RmrcProblem};
use biped_control::momentum::{MomentumMinimisation, VerticalMomentum};
use nalgebra::{DMatrix, DVector};
use util::Lola;

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
