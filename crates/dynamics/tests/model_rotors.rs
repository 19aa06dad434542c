//! Motor rotors added to a URDF model (`Model::with_geared_rotors`, thesis 3.1): the rebuilt
//! model without rotors is the original; a rotor of armature `a = N^2 J` adds exactly `a` to
//! its joint's diagonal of `M` and nothing to the rows of the joint's descendants (the rotor
//! rides on the joint's parent); O(n) forward dynamics with the rotor sub-systems agrees with
//! CRBA + Cholesky and the sparse LTL solve.

use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{
    forward_dynamics, mass_matrix, Algorithm, Data, JointModel, Model, RotorSpec,
};
use nalgebra::{DMatrix, DVector, UnitQuaternion, Vector3};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use std::path::Path;

/// The bundled Unitree G1 with a free-floating base.
fn g1() -> Model {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/g1_29dof_rev_1_0.urdf");
    let opts = UrdfOptions {
        floating: true,
        reject_mimic: false,
    };
    load_file(path, &opts).unwrap().model
}

/// A random configuration (unit base quaternion) and velocity.
fn random_state(model: &Model, rng: &mut StdRng) -> (DVector<f64>, DVector<f64>) {
    let mut q = DVector::from_fn(model.nq(), |_, _| rng.random_range(-1.0..1.0));
    let quat = UnitQuaternion::from_scaled_axis(Vector3::new(0.3, -0.2, 0.5));
    q.fixed_rows_mut::<4>(3).copy_from(&quat.coords);
    let v = DVector::from_fn(model.nv(), |_, _| rng.random_range(-2.0..2.0));
    (q, v)
}

fn mm(model: &Model, q: &DVector<f64>) -> DMatrix<f64> {
    mass_matrix(model, &mut Data::new(model), q)
        .unwrap()
        .clone()
}

/// A rotor on every revolute body `k`-th in order: armature 0.01 + 0.001 k, ratio 10 + k.
fn rotors(model: &Model) -> Vec<(RotorSpec, f64)> {
    (0..model.nbodies())
        .filter(|&i| matches!(model.bodies()[i].joint(), JointModel::Revolute { .. }))
        .enumerate()
        .map(|(k, i)| {
            let armature = 0.01 + 0.001 * k as f64;
            let spec = RotorSpec::from_armature(model, i, 10.0 + k as f64, armature).unwrap();
            (spec, armature)
        })
        .collect()
}

fn specs(model: &Model) -> Vec<RotorSpec> {
    rotors(model).into_iter().map(|(s, _)| s).collect()
}

#[test]
fn rebuilt_model_without_rotors_is_the_original() {
    let model = g1();
    let same = model.with_geared_rotors(&[]).unwrap();
    assert_eq!((same.nq(), same.nv()), (model.nq(), model.nv()));
    assert_eq!(same.body_names(), model.body_names());
    let mut rng = StdRng::seed_from_u64(7);
    let (q, _) = random_state(&model, &mut rng);
    assert_eq!(mm(&same, &q), mm(&model, &q));
}

#[test]
fn a_rotor_adds_its_armature_to_its_own_diagonal_only_below_the_parent() {
    let model = g1();
    let rotors = rotors(&model);
    let with = model.with_geared_rotors(&specs(&model)).unwrap();
    assert_eq!(with.nbodies(), model.nbodies() + rotors.len());
    assert_eq!((with.nq(), with.nv()), (model.nq(), model.nv()));
    let mut rng = StdRng::seed_from_u64(11);
    for _ in 0..4 {
        let (q, _) = random_state(&model, &mut rng);
        let dm = mm(&with, &q) - mm(&model, &q);
        for (s, armature) in &rotors {
            let body = &model.bodies()[s.joint];
            let j = body.v_index();
            // The other rotors ride on this joint's descendants and add their own (small)
            // inertia to its diagonal: one rotor at a time.
            let alone = model.with_geared_rotors(std::slice::from_ref(s)).unwrap();
            let d1 = mm(&alone, &q) - mm(&model, &q);
            assert!(
                (d1[(j, j)] - armature).abs() < 1e-12 * armature,
                "{}",
                body.name()
            );
            // The rotor rides on the parent: no coordinate below the joint sees it.
            for k in 0..model.nv() {
                if k != j && descends(&model, k, j) {
                    assert!(d1.row(k).amax() < 1e-14, "row {k} of {}", body.name());
                }
            }
        }
        assert!(dm.iter().all(|x| x.is_finite()));
    }
}

/// True if coordinate `k` lies below coordinate `j` in the tree of DoFs.
fn descends(model: &Model, mut k: usize, j: usize) -> bool {
    while let Some(p) = model.dof_parents()[k] {
        if p == j {
            return true;
        }
        k = p;
    }
    false
}

#[test]
fn on_with_rotor_subsystems_matches_crba_and_sparse() {
    let model = g1().with_geared_rotors(&specs(&g1())).unwrap();
    assert!(!model.subsystems().is_empty());
    let mut rng = StdRng::seed_from_u64(3);
    for _ in 0..5 {
        let (q, v) = random_state(&model, &mut rng);
        let tau = DVector::from_fn(model.nv(), |_, _| rng.random_range(-20.0..20.0));
        let mut data = Data::new(&model);
        let fd = |a, data: &mut Data| {
            forward_dynamics(&model, data, &q, &v, &tau, None, a)
                .unwrap()
                .clone()
        };
        let on = fd(Algorithm::On, &mut data);
        let crba = fd(Algorithm::Crba, &mut data);
        let sparse = fd(Algorithm::Sparse, &mut data);
        let scale = crba.amax().max(1.0);
        assert!((&on - &crba).amax() < 1e-9 * scale, "O(n) vs CRBA");
        assert!((&sparse - &crba).amax() < 1e-9 * scale, "sparse vs CRBA");
    }
}

#[test]
fn bad_rotors_are_errors() {
    use biped_dynamics::ModelError;
    let model = g1();
    let knee = model.body_id("left_knee_link").unwrap();
    let err = |r: Result<RotorSpec, ModelError>| r.unwrap_err().to_string();
    assert!(err(RotorSpec::from_armature(&model, 0, 10.0, 0.01)).contains("revolute"));
    assert!(err(RotorSpec::from_armature(&model, 999, 10.0, 0.01)).contains("no such body"));
    assert!(err(RotorSpec::from_armature(&model, knee, 0.0, 0.01)).contains("gear ratio"));
    assert!(err(RotorSpec::from_armature(&model, knee, 10.0, -0.01)).contains("not positive"));
    assert!(RotorSpec::from_armature(&model, knee, 10.0, f64::NAN).is_err());
    // Two rotors on one joint would share a name.
    let r = RotorSpec::from_armature(&model, knee, 10.0, 0.01).unwrap();
    let twice = model.with_geared_rotors(&[r.clone(), r]).unwrap_err();
    assert!(matches!(twice, ModelError::DuplicateBodyName(_)));
}
