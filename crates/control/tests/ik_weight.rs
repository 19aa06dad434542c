//! `Weight::solve_into` (Sherman-Morrison (7.13)-(7.15)) against the dense inverse, and
//! typed errors for invalid weights.

use biped_control::ik::Weight;
use biped_control::IkError;
use nalgebra::DVector;
use proptest::prelude::*;

fn vecs(n: usize) -> impl Strategy<Value = (Vec<f64>, Vec<f64>, Vec<f64>)> {
    (
        prop::collection::vec(0.01f64..10.0, n),
        prop::collection::vec(-5.0f64..5.0, n),
        prop::collection::vec(-3.0f64..3.0, n),
    )
}

proptest! {
    #[test]
    fn sherman_morrison_matches_dense_inverse((d, u, x) in (1usize..32).prop_flat_map(vecs)) {
        let n = d.len();
        let (d, u, x) = (DVector::from_vec(d), DVector::from_vec(u), DVector::from_vec(x));
        for w in [Weight::Identity, Weight::Diagonal(d.clone()), Weight::DiagonalRankOne { diag: d.clone(), u: u.clone() }] {
            let dense = w.to_dense(n);
            let reference = dense.clone().try_inverse().unwrap() * &x;
            let mut out = DVector::zeros(n);
            w.solve_into(&x, &mut out).unwrap();
            // Residual check W out = x is independent of the inverse's conditioning.
            prop_assert!((&dense * &out - &x).norm() <= 1e-9 * (1.0 + x.norm()) * (1.0 + u.norm_squared()));
            prop_assert!((&out - &reference).norm() <= 1e-7 * (1.0 + reference.norm()));
        }
    }
}

#[test]
fn set_rank_one_updates_in_place_and_matches_construction() {
    let mut w = Weight::rank_one(3, 0.5).unwrap();
    w.set_rank_one(0.2, &[1.0, -2.0, 0.5]).unwrap();
    let d = w.to_dense(3);
    assert_eq!(d[(0, 1)], -2.0);
    assert!((d[(1, 1)] - 4.2).abs() < 1e-15);
    assert!(matches!(
        w.set_rank_one(0.2, &[1.0]),
        Err(IkError::Dimension { .. })
    ));
    assert!(matches!(
        w.set_rank_one(0.0, &[1.0, 2.0, 3.0]),
        Err(IkError::NonPositiveWeight { .. })
    ));
    assert!(Weight::Identity.set_rank_one(1.0, &[1.0]).is_err());
}

#[test]
fn invalid_weights_are_errors_not_nan() {
    let x = DVector::from_element(2, 1.0);
    let mut out = DVector::zeros(2);
    let bad = Weight::Diagonal(DVector::from_vec(vec![1.0, -1.0]));
    assert!(matches!(
        bad.solve_into(&x, &mut out),
        Err(IkError::NonPositiveWeight { index: 1, .. })
    ));
    let nan = Weight::DiagonalRankOne {
        diag: DVector::from_element(2, 1.0),
        u: DVector::from_vec(vec![f64::NAN, 0.0]),
    };
    assert!(nan.solve_into(&x, &mut out).is_err());
    let short = Weight::Diagonal(DVector::from_element(3, 1.0));
    assert!(matches!(
        short.solve_into(&x, &mut out),
        Err(IkError::Dimension { .. })
    ));
}
