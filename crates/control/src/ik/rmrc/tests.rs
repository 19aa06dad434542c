//! The folded unit rows give the stacked solution to round-off: random problems with trailing
//! soft unit rows (unit, scaled and zeroed coefficients, repeated columns), every weight shape,
//! hard and soft general rows, with and without a null-space term, through `solve` and
//! `resolve`, alone and inside the joint limits' saturation.

use super::{Rmrc, RmrcProblem};
use crate::ik::limits::{JointLimits, JointRange, LimitSettings};
use crate::ik::saturation::SaturatedRmrc;
use crate::ik::weight::Weight;
use nalgebra::{DMatrix, DVector};
use proptest::prelude::*;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// A random problem: `J`, `xd`, softness, weight, gradient, damping and the unit columns.
struct Case {
    j: DMatrix<f64>,
    xd: DVector<f64>,
    soft: Vec<f64>,
    w: Weight,
    grad: Option<(DVector<f64>, f64)>,
    damping: f64,
    columns: Vec<usize>,
}

impl Case {
    fn new(seed: u64) -> Self {
        let mut rng = StdRng::seed_from_u64(seed);
        let n = rng.random_range(4..16);
        let (mg, k) = (rng.random_range(0..n), rng.random_range(1..2 * n));
        let m = mg + k;
        let mut j = DMatrix::from_fn(m, n, |_, _| rng.random_range(-1.0..1.0));
        let mut soft: Vec<f64> = (0..mg)
            .map(|_| match rng.random_bool(0.5) {
                true => 0.0,
                false => 10f64.powf(rng.random_range(-3.0..1.0)),
            })
            .collect();
        let mut columns = Vec::new();
        for r in mg..m {
            let c = rng.random_range(0..n);
            let a = match rng.random_range(0..4) {
                0 => 0.0,
                1 => rng.random_range(-2.0..2.0),
                _ => 1.0,
            };
            j.row_mut(r).fill(0.0);
            j[(r, c)] = a;
            columns.push(c);
            soft.push(10f64.powf(rng.random_range(-3.0..3.0)));
        }
        let diag = DVector::from_fn(n, |_, _| rng.random_range(0.1..10.0));
        let w = match rng.random_range(0..3) {
            0 => Weight::Identity,
            1 => Weight::Diagonal(diag),
            _ => Weight::DiagonalRankOne {
                diag,
                u: DVector::from_fn(n, |_, _| rng.random_range(-2.0..2.0)),
            },
        };
        let grad = rng.random_bool(0.7).then(|| {
            let g = DVector::from_fn(n, |_, _| rng.random_range(-1.0..1.0));
            (g, rng.random_range(0.1..3.0))
        });
        Self {
            xd: DVector::from_fn(m, |_, _| rng.random_range(-1.0..1.0)),
            j,
            soft,
            w,
            grad,
            damping: [0.0, 1e-8, 1e-4][rng.random_range(0..3)],
            columns,
        }
    }

    fn problem(&self) -> RmrcProblem<'_> {
        RmrcProblem {
            null_space: self.grad.as_ref().map(|(g, a)| (g, *a)),
            damping: self.damping,
            softness: Some(&self.soft),
            ..RmrcProblem::new(&self.j, self.j.nrows(), &self.xd, &self.w)
        }
    }
}

/// `|a - b| <= tol (1 + |b|)` in the max norm.
fn close(a: &DVector<f64>, b: &DVector<f64>, tol: f64) -> bool {
    (a - b).amax() <= tol * (1.0 + b.amax())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn folded_unit_rows_solve_and_resolve_as_stacked(seed in any::<u64>()) {
        let case = Case::new(seed);
        let (m, n) = case.j.shape();
        let (mut folded, mut stacked) = (Rmrc::new(m, n), Rmrc::new(m, n));
        folded.set_unit_rows(&case.columns).unwrap();
        let p = case.problem();
        let (mut a, mut b) = (DVector::zeros(n), DVector::zeros(n));
        folded.solve(&p, &mut a).unwrap();
        stacked.solve(&p, &mut b).unwrap();
        prop_assert_eq!(folded.fold.last, Some(m));
        prop_assert!(close(&a, &b, 1e-9), "qdot {a} vs {b}");
        let (la, lb) = (folded.multipliers().rows(0, m), stacked.multipliers().rows(0, m));
        prop_assert!(close(&la.clone_owned(), &lb.clone_owned(), 1e-8), "lambda {la} vs {lb}");
        // another right-hand side and gradient on the same factorisation
        let xd2 = case.xd.map(|x| 0.5 - 2.0 * x);
        let g2 = DVector::from_fn(n, |i, _| (i as f64).sin());
        let p2 = RmrcProblem { xdot: &xd2, null_space: Some((&g2, 0.7)), ..p };
        folded.resolve(&p2, &mut a).unwrap();
        stacked.resolve(&p2, &mut b).unwrap();
        prop_assert!(close(&a, &b, 1e-9), "resolved qdot {a} vs {b}");
    }

    #[test]
    fn folded_unit_rows_saturate_as_stacked(seed in any::<u64>()) {
        let case = Case::new(seed);
        let (m, n) = case.j.shape();
        let mut rng = StdRng::seed_from_u64(seed ^ 0x5eed);
        let ranges = (0..n)
            .map(|i| JointRange { q_index: i, v_index: i, lower: -1.0, upper: 1.0 })
            .collect();
        let settings = LimitSettings { max_velocity: 0.5, ..LimitSettings::default() };
        let limits = JointLimits::new(ranges, settings).unwrap();
        let q = DVector::from_fn(n, |_, _| rng.random_range(-1.0..1.0));
        let mut folded = SaturatedRmrc::new(m, n, limits.clone()).unwrap();
        let mut stacked = SaturatedRmrc::new(m, n, limits).unwrap();
        folded.set_unit_rows(&case.columns).unwrap();
        let p = case.problem();
        let (mut a, mut b) = (DVector::zeros(n), DVector::zeros(n));
        // two cycles: the second warm-starts from the joints held in the first
        for dt in [1e-3, 2e-3] {
            let ra = folded.solve(&p, &q, dt, &mut a).unwrap();
            let rb = stacked.solve(&p, &q, dt, &mut b).unwrap();
            prop_assert_eq!(ra, rb);
            prop_assert_eq!(folded.fixed(), stacked.fixed());
            prop_assert!(close(&a, &b, 1e-8), "qdot {a} vs {b}");
        }
        let xd2 = case.xd.map(|x| 0.3 * x + 0.1);
        let p2 = RmrcProblem { xdot: &xd2, ..p };
        folded.resolve(&p2, &mut a).unwrap();
        stacked.resolve(&p2, &mut b).unwrap();
        prop_assert!(close(&a, &b, 1e-8), "resolved qdot {a} vs {b}");
    }
}

#[test]
fn saturation_cases_do_hold_joints() {
    // the saturation property above must exercise held joints in most cases
    let mut held = 0;
    for seed in 0..64 {
        let case = Case::new(seed);
        let (m, n) = case.j.shape();
        let ranges = (0..n)
            .map(|i| JointRange {
                q_index: i,
                v_index: i,
                lower: -1.0,
                upper: 1.0,
            })
            .collect();
        let settings = LimitSettings {
            max_velocity: 0.5,
            ..LimitSettings::default()
        };
        let mut s = SaturatedRmrc::new(m, n, JointLimits::new(ranges, settings).unwrap()).unwrap();
        s.set_unit_rows(&case.columns).unwrap();
        let mut qdot = DVector::zeros(n);
        let r = s.solve(&case.problem(), &DVector::zeros(n), 1e-3, &mut qdot);
        held += (r.unwrap().fixed > 0) as usize;
    }
    assert!(held > 32, "only {held} of 64 cases held a joint");
}

#[test]
fn hard_unit_rows_and_bad_columns_take_the_stacked_path() {
    let mut case = Case::new(7);
    let (m, n) = case.j.shape();
    let mut s = Rmrc::new(m, n);
    assert!(s.set_unit_rows(&[n]).is_err());
    assert!(s.set_unit_rows(&vec![0; m + 1]).is_err());
    s.set_unit_rows(&case.columns).unwrap();
    case.damping = 0.0;
    *case.soft.last_mut().unwrap() = 0.0;
    s.solve(&case.problem(), &mut DVector::zeros(n)).ok();
    assert_eq!(s.fold.last, None);
}
