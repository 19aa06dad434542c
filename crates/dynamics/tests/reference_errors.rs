//! Typed errors of the reference O(n) algorithm (`dynamics::reference`) on bad input: wrong
//! lengths, non-finite entries, a zero quaternion, a mechanism outside its assembly range.

mod loop_support;

use biped_dynamics::dynamics::reference;
use biped_dynamics::model::{FourBar, Mechanism};
use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{dill::dill, DynamicsError, JointModel, Wrench};
use nalgebra::DVector;

/// Bad input gives typed errors, no panic.
#[test]
fn bad_input_is_rejected() {
    let model = dill(2).expect("dill");
    let (q, v, tau) = (DVector::zeros(4), DVector::zeros(4), DVector::zeros(4));
    let short = DVector::zeros(3);
    let err = reference::forward_dynamics(&model, &short, &v, &tau, None);
    assert!(matches!(
        err,
        Err(DynamicsError::DimensionMismatch { argument: "q", .. })
    ));
    let mut nan = v.clone();
    nan[2] = f64::NAN;
    let err = reference::forward_dynamics(&model, &q, &nan, &tau, None);
    assert!(matches!(
        err,
        Err(DynamicsError::NonFinite {
            argument: "v",
            index: 2
        })
    ));
    let err = reference::forward_dynamics(&model, &q, &v, &short, None);
    assert!(matches!(
        err,
        Err(DynamicsError::DimensionMismatch {
            argument: "tau",
            ..
        })
    ));
    let fext = vec![Wrench::zero(); 2];
    let err = reference::forward_dynamics(&model, &q, &v, &tau, Some(&fext));
    assert!(matches!(
        err,
        Err(DynamicsError::DimensionMismatch {
            argument: "fext",
            ..
        })
    ));
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/g1_29dof_rev_1_0.urdf");
    let options = UrdfOptions {
        floating: true,
        ..UrdfOptions::default()
    };
    let floating = load_file(path, &options).expect("bundled URDF").model;
    let err = reference::forward_dynamics(
        &floating,
        &DVector::zeros(floating.nq()),
        &DVector::zeros(floating.nv()),
        &DVector::zeros(floating.nv()),
        None,
    );
    assert!(matches!(err, Err(DynamicsError::ZeroQuaternion { .. })));
}

/// A four-bar whose circles do not meet reports the mechanism error of its body.
#[test]
fn mechanism_errors_are_reported() {
    let bad = FourBar {
        crank: 0.5,
        coupler: 0.1,
        rocker: 0.1,
        ground: 0.2,
        elbow: 1.0,
    };
    let model = loop_support::random_loop_model(3, 6, false, |_, inputs| {
        Some(JointModel::Coupled {
            mechanism: Mechanism::FourBar(bad.clone()),
            inputs: vec![inputs[0]],
        })
    });
    assert!(!model.subsystems().is_empty());
    let n = model.nv();
    let q = DVector::from_element(model.nq(), 0.3);
    let err = reference::forward_dynamics(&model, &q, &DVector::zeros(n), &DVector::zeros(n), None);
    assert!(
        matches!(err, Err(DynamicsError::Mechanism { .. })),
        "{err:?}"
    );
}
