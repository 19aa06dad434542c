//! Cross-checks of the three forward-dynamics methods, CRBA and RNEA on random trees.

mod core_support;

use biped_dynamics::{
    forward_dynamics, forward_kinematics, inverse_dynamics, mass_matrix, Algorithm, Data, Force,
    Model, Wrench,
};
use core_support::*;
use nalgebra::{DMatrix, DVector, Vector3};
use proptest::prelude::*;

/// Random state `(q, v, tau, fext)` for a model.
fn random_state(
    model: &Model,
    seed: u64,
) -> (DVector<f64>, DVector<f64>, DVector<f64>, Vec<Wrench>) {
    let mut r = rng(seed ^ 0x5eed);
    let q = random_q(model, &mut r);
    let v = random_vec(model.nv(), 2.0, &mut r);
    let tau = random_vec(model.nv(), 5.0, &mut r);
    let fext = (0..model.nbodies())
        .map(|_| {
            let t = random_vec(3, 2.0, &mut r);
            let f = random_vec(3, 2.0, &mut r);
            Force::new(
                Vector3::new(t[0], t[1], t[2]),
                Vector3::new(f[0], f[1], f[2]),
            )
        })
        .collect();
    (q, v, tau, fext)
}

/// Body Jacobians `Jbar_i` (6 x nv, body coordinates) from the velocity recursion with unit `v`.
fn body_jacobians(model: &Model, q: &DVector<f64>) -> Vec<DMatrix<f64>> {
    let mut data = Data::new(model);
    let mut jac = vec![DMatrix::zeros(6, model.nv()); model.nbodies()];
    let zero = DVector::zeros(model.nv());
    for k in 0..model.nv() {
        let mut e = DVector::zeros(model.nv());
        e[k] = 1.0;
        forward_kinematics(model, &mut data, q, &e, &zero).unwrap();
        for (i, j) in jac.iter_mut().enumerate() {
            j.column_mut(k).copy_from(&data.vel[i].to_vector());
        }
    }
    jac
}

/// Agreement bound of two backward-stable solves of `M a = b`: `1e-10` plus the forward-error
/// bound `c eps cond(M)` with `c = 4` (random trees reach `cond(M) ~ 1e6`, where rounding alone
/// separates the methods by ~1e-10: seed 1383871585184572943, n = 51, measured 9.4e-11 at
/// `cond = 2.5e6`).
fn solve_tolerance(model: &Model, q: &DVector<f64>) -> f64 {
    if model.nv() == 0 {
        return 1e-10; // Only fixed joints: an empty system.
    }
    let mut data = Data::new(model);
    let e = mass_matrix(model, &mut data, q)
        .unwrap()
        .clone()
        .symmetric_eigenvalues();
    1e-10 + 4.0 * f64::EPSILON * e.max() / e.min()
}

fn options(rotors: bool) -> TreeOptions {
    TreeOptions {
        rotors,
        ..TreeOptions::default()
    }
}

/// The tree where the flat 1e-10 bound failed (cond(M) = 2.5e6): the methods agree within
/// [`solve_tolerance`], which is looser than 1e-10 there.
#[test]
fn ill_conditioned_tree_agrees_within_its_bound() {
    let model = random_model(1383871585184572943, 51, options(false));
    let (q, v, tau, _) = random_state(&model, 1383871585184572943);
    let mut data = Data::new(&model);
    let mut solve = |algo| {
        forward_dynamics(&model, &mut data, &q, &v, &tau, None, algo)
            .unwrap()
            .clone()
    };
    let (a_on, a_crba, a_sparse) = (
        solve(Algorithm::On),
        solve(Algorithm::Crba),
        solve(Algorithm::Sparse),
    );
    let tol = solve_tolerance(&model, &q);
    assert!(tol > 1e-10, "{tol}");
    assert!(rel_diff(&a_on, &a_crba) < tol);
    assert!(rel_diff(&a_sparse, &a_crba) < tol);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// O(n), CRBA + Cholesky and sparse LTL agree to 1e-10 relative plus the rounding bound of
    /// the conditioning ([`solve_tolerance`]).
    #[test]
    fn three_methods_agree(seed in any::<u64>(), n in 1usize..60, with_fext in any::<bool>()) {
        let model = random_model(seed, n, options(false));
        let (q, v, tau, fext) = random_state(&model, seed);
        let fext = with_fext.then_some(fext.as_slice());
        let mut data = Data::new(&model);
        let a_on = forward_dynamics(&model, &mut data, &q, &v, &tau, fext, Algorithm::On).unwrap().clone();
        let a_crba = forward_dynamics(&model, &mut data, &q, &v, &tau, fext, Algorithm::Crba).unwrap().clone();
        let a_sparse = forward_dynamics(&model, &mut data, &q, &v, &tau, fext, Algorithm::Sparse).unwrap().clone();
        let tol = solve_tolerance(&model, &q);
        prop_assert!(rel_diff(&a_on, &a_crba) < tol, "On vs Crba {} (tol {tol})", rel_diff(&a_on, &a_crba));
        prop_assert!(rel_diff(&a_sparse, &a_crba) < tol, "Sparse vs Crba {} (tol {tol})", rel_diff(&a_sparse, &a_crba));
    }

    /// With geared rotors (shared coordinates) CRBA and sparse LTL agree, and RNEA inverts both.
    #[test]
    fn rotors_crba_sparse_rnea(seed in any::<u64>(), n in 2usize..40) {
        let model = random_model(seed, n, options(true));
        let (q, v, tau, fext) = random_state(&model, seed);
        let mut data = Data::new(&model);
        let a_crba = forward_dynamics(&model, &mut data, &q, &v, &tau, Some(&fext), Algorithm::Crba).unwrap().clone();
        let a_sparse = forward_dynamics(&model, &mut data, &q, &v, &tau, Some(&fext), Algorithm::Sparse).unwrap().clone();
        prop_assert!(rel_diff(&a_sparse, &a_crba) < 1e-10);
        let tau2 = inverse_dynamics(&model, &mut data, &q, &v, &a_crba, Some(&fext)).unwrap();
        prop_assert!(rel_diff(tau2, &tau) < 1e-9, "{}", rel_diff(tau2, &tau));
    }

    /// `inverse_dynamics(q, v, forward_dynamics(q, v, tau)) = tau` with external wrenches.
    #[test]
    fn inverse_of_forward(seed in any::<u64>(), n in 1usize..60) {
        let model = random_model(seed, n, options(false));
        let (q, v, tau, fext) = random_state(&model, seed);
        let mut data = Data::new(&model);
        let a = forward_dynamics(&model, &mut data, &q, &v, &tau, Some(&fext), Algorithm::On).unwrap().clone();
        let tau2 = inverse_dynamics(&model, &mut data, &q, &v, &a, Some(&fext)).unwrap();
        prop_assert!(rel_diff(tau2, &tau) < 1e-9, "{}", rel_diff(tau2, &tau));
    }

    /// Mass matrix: symmetric, PD, equal to sum_i Jbar_i^T M_i Jbar_i and to columns of RNEA.
    #[test]
    fn mass_matrix_two_routes(seed in any::<u64>(), n in 1usize..40, rotors in any::<bool>()) {
        let mut opts = options(rotors);
        opts.gravity = Vector3::zeros();
        let model = random_model(seed, n, opts);
        let (q, _, _, _) = random_state(&model, seed);
        let mut data = Data::new(&model);
        let m = mass_matrix(&model, &mut data, &q).unwrap().clone();
        let scale = m.amax().max(1.0);
        prop_assert!((&m - m.transpose()).amax() < 1e-12 * scale);
        prop_assert!(m.clone().cholesky().is_some());
        // Route 1: kinetic energy of the bodies, Jbar_i from the velocity recursion.
        let jac = body_jacobians(&model, &q);
        let mut m_ref = DMatrix::zeros(model.nv(), model.nv());
        for (i, body) in model.bodies().iter().enumerate() {
            let mi = nalgebra::DMatrix::from_column_slice(6, 6, body.inertia().to_matrix().as_slice());
            m_ref += jac[i].transpose() * mi * &jac[i];
        }
        prop_assert!((&m - &m_ref).amax() < 1e-10 * scale, "{}", (&m - &m_ref).amax());
        // Route 2: M e_k = RNEA(q, 0, e_k) without gravity.
        let zero = DVector::zeros(model.nv());
        for k in 0..model.nv() {
            let mut e = DVector::zeros(model.nv());
            e[k] = 1.0;
            let col = inverse_dynamics(&model, &mut data, &q, &zero, &e, None).unwrap();
            prop_assert!((col - m.column(k)).amax() < 1e-10 * scale);
        }
    }

    /// External wrenches act as the generalized force `sum_i Jbar_i^T f_i`.
    #[test]
    fn external_wrench_projection(seed in any::<u64>(), n in 1usize..30) {
        let model = random_model(seed, n, options(true));
        let (q, v, _, fext) = random_state(&model, seed);
        let a = random_vec(model.nv(), 1.0, &mut rng(seed));
        let mut data = Data::new(&model);
        let with = inverse_dynamics(&model, &mut data, &q, &v, &a, Some(&fext)).unwrap().clone();
        let without = inverse_dynamics(&model, &mut data, &q, &v, &a, None).unwrap().clone();
        let jac = body_jacobians(&model, &q);
        let mut proj = DVector::zeros(model.nv());
        for (i, f) in fext.iter().enumerate() {
            proj += jac[i].transpose() * DVector::from_column_slice(f.to_vector().as_slice());
        }
        prop_assert!(rel_diff(&(without - with), &proj) < 1e-10);
    }
}

/// Gravity alone: a single free body falls with acceleration g (world), no rotation.
#[test]
fn free_body_falls_with_gravity() {
    for root in [0u8, 1] {
        let model = random_model(
            7,
            1,
            TreeOptions {
                root,
                ..TreeOptions::default()
            },
        );
        let mut r = rng(1);
        let q = random_q(&model, &mut r);
        let v = DVector::zeros(6);
        let tau = DVector::zeros(6);
        let mut data = Data::new(&model);
        for algo in [Algorithm::On, Algorithm::Crba, Algorithm::Sparse] {
            forward_dynamics(&model, &mut data, &q, &v, &tau, None, algo).unwrap();
            // Acceleration of the CoM in the world.
            let b = &model.bodies()[0];
            let a = &data.acc[0];
            let acc_com = a.lin + a.ang.cross(&b.inertia().com());
            let world = data.world_rot[0] * acc_com;
            assert!((world - model.gravity()).norm() < 1e-10, "{algo:?} {world}");
            assert!(a.ang.norm() < 1e-10);
        }
    }
}

/// Finite inputs whose products overflow (a free body of 1e308 kg under gravity): forward and
/// inverse dynamics give the typed error, never an `Ok` holding infinities or NaNs.
#[test]
fn overflowing_inputs_give_a_typed_error() {
    use biped_dynamics::{DynamicsError, JointModel, ModelBuilder, RigidInertia};
    let inertia = RigidInertia::new(
        1e308,
        Vector3::zeros(),
        nalgebra::Matrix3::from_diagonal_element(1e307),
    )
    .expect("finite inertia");
    let mut b = ModelBuilder::new();
    let placement = nalgebra::Isometry3::identity();
    add_named(
        &mut b,
        "heavy",
        None,
        JointModel::FreeQuaternion,
        placement,
        inertia,
    );
    let model = b.build().expect("model");
    let (q, v) = (model.neutral(), DVector::zeros(6));
    let mut data = Data::new(&model);
    let overflow = |r: Result<&DVector<f64>, DynamicsError>| {
        matches!(r, Err(DynamicsError::NonFiniteResult { .. }))
    };
    for algo in [Algorithm::On, Algorithm::Crba, Algorithm::Sparse] {
        let r = forward_dynamics(&model, &mut data, &q, &v, &DVector::zeros(6), None, algo);
        assert!(overflow(r), "{algo:?}");
    }
    let r = inverse_dynamics(&model, &mut data, &q, &v, &DVector::zeros(6), None);
    assert!(overflow(r));
}
