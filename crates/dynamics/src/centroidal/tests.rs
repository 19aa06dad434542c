//! `Centroidal::compute_matrix_with` against the self-contained `compute_matrix`.

use super::Centroidal;
use crate::dill::{dill, dill_test_state};
use crate::jacobian::{JacobianError, Jacobians};
use crate::Data;

#[test]
fn matrix_with_shared_kinematics_equals_own_pass() {
    for n in [1, 3, 7] {
        let model = dill(n).expect("model");
        let (q, _) = dill_test_state(&model);
        let (mut own, mut shared) = (Centroidal::new(&model), Centroidal::new(&model));
        let mut data = Data::new(&model);
        own.compute_matrix(&model, &mut data, &q).expect("own");
        let mut jac = Jacobians::new(&model);
        let mut data2 = Data::new(&model);
        jac.compute(&model, &mut data2, &q).expect("jac");
        shared
            .compute_matrix_with(&model, &data2, &jac)
            .expect("shared");
        assert_eq!(own.mass(), shared.mass());
        assert!((own.com() - shared.com()).norm() <= 1e-14);
        let (a, b) = (own.ag().expect("ag"), shared.ag().expect("ag"));
        assert!((a - b).amax() <= 1e-13 * (1.0 + a.amax()), "n = {n}");
        assert!(a.amax() > 0.0);
    }
}

#[test]
fn matrix_with_needs_computed_columns_of_the_same_model() {
    let model = dill(3).expect("model");
    let data = Data::new(&model);
    let mut cen = Centroidal::new(&model);
    let jac = Jacobians::new(&model);
    assert!(matches!(
        cen.compute_matrix_with(&model, &data, &jac),
        Err(JacobianError::NotComputed(_))
    ));
    assert!(cen.ag().is_err());
    let other = dill(2).expect("model");
    let jac_other = Jacobians::new(&other);
    assert!(matches!(
        cen.compute_matrix_with(&model, &data, &jac_other),
        Err(JacobianError::WorkspaceMismatch { .. })
    ));
}
