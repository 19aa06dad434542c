//! Joint-limit and comfort cost H_J (Fig. 4.2): analytic gradient vs central differences,
//! shape (zero in the middle band, steep near limits, finite beyond), Wolfe line search and
//! the null-space rate limiter.

use biped_control::ik::line_search::{wolfe_search, WolfeParams};
use biped_control::ik::{JointCost, JointCostEntry, NullSpaceLimiter};
use biped_control::IkError;
use nalgebra::DVector;
use proptest::prelude::*;

fn cost() -> JointCost {
    let e = |i: usize, lower: f64, upper: f64, comfort: f64| JointCostEntry {
        q_index: i,
        v_index: i,
        lower,
        upper,
        comfort,
        w_comfort: 2.0,
    };
    JointCost::new(
        vec![
            e(0, -1.0, 1.0, 0.2),
            e(1, 0.0, 1.9, 0.5),
            e(2, -0.3, 0.3, 0.0),
        ],
        0.5,
        0.15,
    )
    .unwrap()
}

proptest! {
    #[test]
    fn gradient_matches_central_differences(x in prop::array::uniform3(-2.0f64..2.5)) {
        let c = cost();
        let q = DVector::from_row_slice(&x);
        let mut g = DVector::zeros(3);
        c.gradient_into(&q, &mut g).unwrap();
        let h = 1e-6;
        for i in 0..3 {
            let (mut qp, mut qm) = (q.clone(), q.clone());
            qp[i] += h;
            qm[i] -= h;
            let fd = (c.value(&qp).unwrap() - c.value(&qm).unwrap()) / (2.0 * h);
            // Rounding of the difference grows with |H| (large past the limits).
            let tol = 1e-6 * (1.0 + g[i].abs()) + 1e-9 * c.value(&q).unwrap();
            prop_assert!((fd - g[i]).abs() < tol, "joint {i}: fd {fd} vs {}", g[i]);
        }
        prop_assert!(c.value(&q).unwrap().is_finite());
    }
}

#[test]
fn cost_shape_follows_fig_4_2() {
    let c = JointCost::new(
        vec![JointCostEntry {
            q_index: 0,
            v_index: 0,
            lower: -1.0,
            upper: 1.0,
            comfort: 0.0,
            w_comfort: 1.0,
        }],
        1.0,
        0.1,
    )
    .unwrap();
    let h = |x: f64| c.value(&DVector::from_element(1, x)).unwrap();
    // Pure comfort parabola inside the band |x| <= 0.8: (x / 2)^2 / 2.
    assert!((h(0.6) - 0.5 * 0.09).abs() < 1e-15);
    assert_eq!(h(0.0), 0.0);
    // Steep wall: the limit term grows by orders of magnitude towards the limit.
    let wall = |x: f64| h(x) - 0.5 * (x / 2.0f64).powi(2);
    assert!(wall(0.99) > 100.0 * wall(0.85));
    assert_eq!(wall(0.8), 0.0);
    assert!((wall(-0.95) - wall(0.95)).abs() < 1e-12, "symmetric walls");
    // Beyond the limit: finite and increasing.
    assert!(h(1.5).is_finite() && h(1.5) > h(1.0));
    assert!(matches!(
        c.value(&DVector::from_element(1, f64::NAN)),
        Err(IkError::NonFinite(_))
    ));
    assert!(JointCost::new(vec![], 1.0, 0.6).is_err());
}

#[test]
fn wolfe_step_satisfies_both_conditions() {
    // phi(a) = (a - 3)^2 + 0.1 a^4 along a descent direction from a = 0.
    let f = |a: f64| {
        (
            (a - 3.0).powi(2) + 0.1 * a.powi(4),
            2.0 * (a - 3.0) + 0.4 * a.powi(3),
        )
    };
    let p = WolfeParams {
        c2: 0.1,
        ..Default::default()
    };
    let (phi0, d0) = f(0.0);
    let r = wolfe_search(&p, phi0, d0, |a| Ok(f(a))).unwrap();
    let (fa, da) = f(r.alpha);
    assert!(r.wolfe);
    assert!(fa <= phi0 + p.c1 * r.alpha * d0);
    assert!(da.abs() <= -p.c2 * d0);
    assert!(
        wolfe_search(&p, phi0, 1.0, |a| Ok(f(a))).is_err(),
        "ascent direction"
    );
}

#[test]
fn null_space_limiter_bounds_the_change_rate() {
    let mut lim = NullSpaceLimiter::new(2, 10.0);
    let mut v = DVector::from_vec(vec![0.0, 0.0]);
    lim.apply(&mut v, 1e-3).unwrap();
    let mut jump = DVector::from_vec(vec![3.0, 4.0]);
    lim.apply(&mut jump, 1e-3).unwrap();
    assert!((jump.norm() - 0.01).abs() < 1e-15, "{jump}");
    assert!((jump[0] / jump[1] - 0.75).abs() < 1e-12, "direction kept");
    let mut small = DVector::from_vec(vec![0.006, 0.008]);
    lim.apply(&mut small, 1e-3).unwrap();
    assert_eq!(small, DVector::from_vec(vec![0.006, 0.008]));
}
