//! Compensation (7.3)-(7.9) solved within the cycle, on Lola Type 2: with the arms free of
//! tasks and `W = E` it is the minimum-norm solution (7.7) (dense pseudo-inverse), it sets
//! `L_z` to `k L_d + (1 - k) L_z` while the tasks keep their velocities, and it stays inside
//! the joint limits' box.

#[path = "momentum_util.rs"]
mod util;

use biped_control::ik::{JointLimits, JointRange, LimitSettings, RmrcProblem, SaturatedRmrc};
use biped_control::momentum::{
    Compensation, InCycleCompensation, MomentumError, VerticalMomentum, LOLA_ARMS, LOLA_ARM_FLEXION,
};
use biped_control::{IkError, Weight};
use nalgebra::{DMatrix, DVector};
use util::{pinv, rel, Lola};

/// `J_Lz^T` at a random state, that state and a random `L_d`.
fn sample(s: &mut Lola) -> (DVector<f64>, DVector<f64>, DVector<f64>, f64) {
    let model = s.lola.model.clone();
    let (q, qdot) = s.state();
    let mut vm = VerticalMomentum::new(&model);
    vm.compute(&model, &mut s.data, &mut s.centroidal, &q)
        .unwrap();
    let l_d = s.vector(1)[0];
    (vm.jacobian_z().clone(), q, qdot, l_d)
}

/// Unit rows on every DoF that `comp` does not reduce (the tasks fix the producing DoFs).
fn producing_rows(comp: &Compensation, n: usize) -> DMatrix<f64> {
    let rows: Vec<usize> = (0..n).filter(|&i| !comp.is_reducing(i)).collect();
    DMatrix::from_fn(rows.len(), n, |a, b| if rows[a] == b { 1.0 } else { 0.0 })
}

/// Limit-keeping solver without damping for `m` rows on `lola`, with its joint ranges if
/// `ranges` (velocity limit `vmax`), else none.
fn solver(s: &Lola, m: usize, ranges: bool, vmax: f64) -> SaturatedRmrc {
    let settings = LimitSettings {
        regularisation: 0.0,
        max_velocity: vmax,
        ..LimitSettings::default()
    };
    let list = match ranges {
        true => (s.lola.limits.iter())
            .map(|l| JointRange {
                q_index: l.q_index,
                v_index: l.v_index,
                lower: l.lower,
                upper: l.upper,
            })
            .collect(),
        false => Vec::new(),
    };
    let n = s.model().nv();
    SaturatedRmrc::new(m, n, JointLimits::new(list, settings).unwrap()).unwrap()
}

/// The cycle's solve of `J qd = xd` (W = E) followed by the compensation; returns the main
/// solution and the compensated one.
fn solve_and_compensate(
    sns: &mut SaturatedRmrc,
    comp: &mut InCycleCompensation,
    (j, xd): (&DMatrix<f64>, &DVector<f64>),
    (q, jlz, l_d): (&DVector<f64>, &DVector<f64>, f64),
) -> (DVector<f64>, DVector<f64>) {
    let w = Weight::Identity;
    let p = RmrcProblem::new(j, j.nrows(), xd, &w);
    let mut qd = DVector::zeros(j.ncols());
    sns.solve(&p, q, 1e-3, &mut qd).unwrap();
    let main = qd.clone();
    comp.apply(sns, &p, jlz, l_d, &mut qd).unwrap();
    (main, qd)
}

#[test]
fn free_arms_give_the_minimum_norm_solution_and_reach_the_reference() {
    let mut s = Lola::new(11);
    for joints in [&LOLA_ARM_FLEXION[..], &LOLA_ARMS[..]] {
        let c = Compensation::new(s.model(), joints).unwrap();
        let r = c.reducing().to_vec();
        let jx = producing_rows(&c, s.model().nv());
        let mut sns = solver(&s, jx.nrows(), false, 10.0);
        let mut comp = InCycleCompensation::new(c, jx.nrows(), 1e9).unwrap();
        for _ in 0..10 {
            let (jlz, q, qdot_p, l_d) = sample(&mut s);
            let xd = &jx * &qdot_p;
            let (main, qd) = solve_and_compensate(&mut sns, &mut comp, (&jx, &xd), (&q, &jlz, l_d));
            // the tasks keep their velocities, L_z reaches the reference (7.5)
            assert!((&jx * &qd - &xd).norm() < 1e-9 * xd.norm().max(1.0));
            assert!(rel(jlz.dot(&qd), l_d) < 1e-9, "{} vs {l_d}", jlz.dot(&qd));
            // Independent: minimum-norm w with J_r w = L_d - J_Lz qd_main, by dense SVD (7.7).
            let j_r = DMatrix::from_fn(1, r.len(), |_, k| jlz[r[k]]);
            let w = pinv(&j_r) * DVector::from_element(1, l_d - jlz.dot(&main));
            for (k, &i) in r.iter().enumerate() {
                assert!((qd[i] - main[i] - w[k]).abs() < 1e-9 * w.norm().max(1.0));
            }
        }
    }
}

#[test]
fn the_gain_removes_its_share_and_the_tasks_react() {
    // Random task rows that involve the arms too: the tasks' reaction to the arm motion is
    // part of the term, so J qd = xd still holds and L_z = k L_d + (1 - k) L_z,main.
    let mut s = Lola::new(12);
    let n = s.model().nv();
    let c = Compensation::lola(s.model())
        .unwrap()
        .with_gain(0.6)
        .unwrap();
    let m = 18;
    let mut sns = solver(&s, m, false, 10.0);
    let mut comp = InCycleCompensation::new(c, m, 1e9).unwrap();
    for _ in 0..5 {
        let j = DMatrix::from_fn(m, n, |_, _| s.vector(1)[0]);
        let xd = s.vector(m);
        let (jlz, q, _, l_d) = sample(&mut s);
        let (main, qd) = solve_and_compensate(&mut sns, &mut comp, (&j, &xd), (&q, &jlz, l_d));
        assert!((&j * &qd - &xd).norm() < 1e-8 * xd.norm().max(1.0));
        let expected = 0.6 * l_d + 0.4 * jlz.dot(&main);
        assert!(
            rel(jlz.dot(&qd), expected) < 1e-8,
            "{} vs {expected}",
            jlz.dot(&qd)
        );
    }
}

#[test]
fn the_term_stays_inside_the_velocity_box_and_under_its_speed_cap() {
    let mut s = Lola::new(13);
    let c = Compensation::lola(s.model()).unwrap();
    let jx = producing_rows(&c, s.model().nv());
    let (vmax, cap) = (0.5, 0.3);
    let mut sns = solver(&s, jx.nrows(), true, vmax);
    let mut comp = InCycleCompensation::new(c, jx.nrows(), cap).unwrap();
    for _ in 0..10 {
        let (jlz, q, qdot_p, _) = sample(&mut s);
        let xd = &jx * (&qdot_p * 0.1);
        // a target far beyond what the arms can give within their box
        let l_d = 100.0;
        let (main, qd) = solve_and_compensate(&mut sns, &mut comp, (&jx, &xd), (&q, &jlz, l_d));
        let (lo, hi) = sns.velocity_box();
        for i in 0..qd.len() {
            assert!(
                qd[i] >= lo[i] - 1e-12 && qd[i] <= hi[i] + 1e-12,
                "joint {i}"
            );
        }
        let term = &qd - &main;
        let arms = comp.compensation().reducing();
        assert!(arms.iter().all(|&i| term[i].abs() <= cap + 1e-12), "{term}");
        // it still moves L_z towards the target
        assert!(jlz.dot(&qd) >= jlz.dot(&main) - 1e-12);
    }
}

#[test]
fn reducing_joints_without_effect_add_nothing() {
    let mut s = Lola::new(14);
    let c = Compensation::lola(s.model()).unwrap();
    let jx = producing_rows(&c, s.model().nv());
    let mut sns = solver(&s, jx.nrows(), false, 10.0);
    let reducing = c.reducing().to_vec();
    let mut comp = InCycleCompensation::new(c, jx.nrows(), 1e9).unwrap();
    let (mut jlz, q, qdot_p, l_d) = sample(&mut s);
    for &i in &reducing {
        jlz[i] = 0.0;
    }
    let xd = &jx * &qdot_p;
    let (main, qd) = solve_and_compensate(&mut sns, &mut comp, (&jx, &xd), (&q, &jlz, l_d));
    assert_eq!(main, qd);
}

#[test]
fn bad_sets_and_inputs_are_typed_errors() {
    let mut s = Lola::new(16);
    let m = s.model().clone();
    assert!(matches!(
        Compensation::new(&m, &["nose"]),
        Err(MomentumError::UnknownJoint(_))
    ));
    assert!(matches!(
        Compensation::new(&m, &["root"]),
        Err(MomentumError::NotOneDof { .. })
    ));
    let dup = ["l_shoulder", "l_shoulder"];
    assert!(matches!(
        Compensation::new(&m, &dup),
        Err(MomentumError::BadReducingSet)
    ));
    assert!(matches!(
        Compensation::new(&m, &[]),
        Err(MomentumError::BadReducingSet)
    ));
    let c = Compensation::lola(&m).unwrap();
    assert!(c.clone().with_gain(f64::NAN).is_err());
    assert!(c.clone().with_gain(-1.0).is_err());
    for speed in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(InCycleCompensation::new(c.clone(), 4, speed).is_err());
    }
    let jx = producing_rows(&c, m.nv());
    let mut sns = solver(&s, jx.nrows(), false, 10.0);
    let mut comp = InCycleCompensation::new(c, jx.nrows(), 1.0).unwrap();
    let (jlz, q, qdot_p, l_d) = sample(&mut s);
    let xd = &jx * &qdot_p;
    let w = Weight::Identity;
    let p = RmrcProblem::new(&jx, jx.nrows(), &xd, &w);
    let mut qd = DVector::zeros(m.nv());
    sns.solve(&p, &q, 1e-3, &mut qd).unwrap();
    let short = DVector::zeros(3);
    let e = comp.apply(&mut sns, &p, &short, l_d, &mut qd);
    assert!(matches!(e, Err(IkError::Dimension { .. })), "{e:?}");
    let mut short_qd = DVector::zeros(3);
    assert!(comp.apply(&mut sns, &p, &jlz, l_d, &mut short_qd).is_err());
}
