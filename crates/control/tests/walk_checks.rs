//! Cross-checks of the walk building blocks: the allocation-free retract against
//! `biped_dynamics::integrate`, `Rmrc::resolve` against a fresh solve, and the ground wrench
//! of the evaluator at rest against the weight of the robot.

use biped_control::ik::{Rmrc, RmrcProblem, TaskMap, Weight};
use biped_control::pattern::WalkingPattern;
use biped_control::tasks::{standing_configuration, LolaTasks};
use biped_control::walk::{walk_pattern_params, Evaluator, Method, WalkController, WalkParams};
use biped_robots::lola::{self, LolaType};
use nalgebra::{DMatrix, DVector, Vector3};
use rand::{Rng, SeedableRng};

#[test]
fn retract_matches_dynamics_integrate() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let tasks = LolaTasks::new(&lola, 0.2).unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    let q = standing_configuration(&lola);
    let mut out = q.clone();
    for _ in 0..20 {
        let v = DVector::from_fn(lola.model.nv(), |_, _| rng.random_range(-2.0..2.0));
        let step = rng.random_range(-0.1..0.1);
        tasks.retract(&q, &v, step, &mut out).unwrap();
        let reference = biped_dynamics::integrate(&lola.model, &q, &v, step).unwrap();
        assert!((&out - &reference).amax() < 1e-12);
    }
}

#[test]
fn resolve_equals_fresh_solve_and_superposes() {
    let (m, n) = (25, 31);
    let mut rng = rand::rngs::StdRng::seed_from_u64(3);
    let mut r = || rng.random_range(-1.0..1.0);
    let j = DMatrix::from_fn(m, n, |_, _| r());
    let (x1, x2) = (
        DVector::from_fn(m, |_, _| r()),
        DVector::from_fn(m, |_, _| r()),
    );
    let g = DVector::from_fn(n, |_, _| r());
    let w = Weight::Diagonal(DVector::from_fn(n, |_, _| 1.5 + r()));
    let mut solver = Rmrc::new(m, n);
    let (mut a, mut b, mut c) = (DVector::zeros(n), DVector::zeros(n), DVector::zeros(n));
    let p1 = RmrcProblem::new(&j, m, &x1, &w);
    solver.solve(&p1, &mut a).unwrap();
    let p2 = RmrcProblem {
        null_space: Some((&g, 0.5)),
        ..RmrcProblem::new(&j, m, &x2, &w)
    };
    solver.resolve(&p2, &mut b).unwrap();
    Rmrc::new(m, n).solve(&p2, &mut c).unwrap();
    assert!((&b - &c).amax() < 1e-10);
    // superposition: response to (x1 + x2, g) = response to (x1, 0) + response to (x2, g)
    let sum = &x1 + &x2;
    let p3 = RmrcProblem {
        null_space: Some((&g, 0.5)),
        ..RmrcProblem::new(&j, m, &sum, &w)
    };
    Rmrc::new(m, n).solve(&p3, &mut c).unwrap();
    assert!((&a + &b - &c).amax() < 1e-10);
}

#[test]
fn ground_wrench_at_rest_carries_the_weight() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let pattern =
        WalkingPattern::generate(&walk_pattern_params(&lola, 1, 0.2, 0.8).unwrap()).unwrap();
    let ctrl = WalkController::new(&lola, Method::None, WalkParams::default(), &pattern).unwrap();
    assert_eq!(ctrl.qdot().amax(), 0.0);
    let mut eval = Evaluator::new(&lola, 1e-3).unwrap();
    let com = ctrl.tasks().centroidal().com();
    let mass = ctrl.tasks().centroidal().mass();
    let g = lola.model.gravity();
    let a = DVector::zeros(lola.model.nv());
    let point = Vector3::new(com.x, com.y, 0.0);
    let (f, m) = eval.ground_wrench(&ctrl, &a, &point).unwrap();
    assert!(
        (f + g * mass).norm() < 1e-6 * mass,
        "f = {f}, m g = {}",
        g * mass
    );
    assert!(
        m.norm() < 1e-6 * mass,
        "moment about the CoM ground point {m}"
    );
    // about another point the moment is r x f (statics)
    let other = point + Vector3::new(0.1, -0.05, 0.0);
    let (_, m2) = eval.ground_wrench(&ctrl, &a, &other).unwrap();
    assert!((m2 - (point - other).cross(&f)).norm() < 1e-6 * mass);
}

#[test]
fn rmrc_25x31_rank_one_matches_dense_formula() {
    let (m, n) = (25, 31);
    let mut rng = rand::rngs::StdRng::seed_from_u64(11);
    let mut r = || rng.random_range(-1.0..1.0);
    let j = DMatrix::from_fn(m, n, |_, _| r());
    let xd = DVector::from_fn(m, |_, _| r());
    let g = DVector::from_fn(n, |_, _| r());
    let u: Vec<f64> = (0..n).map(|_| r()).collect();
    let mut w = Weight::rank_one(n, 0.003).unwrap();
    w.set_rank_one(0.003, &u).unwrap();
    let p = RmrcProblem {
        null_space: Some((&g, 0.7)),
        ..RmrcProblem::new(&j, m, &xd, &w)
    };
    let mut qd = DVector::zeros(n);
    Rmrc::new(m, n).solve(&p, &mut qd).unwrap();
    // dense (4.12): z = -alpha W^-1 g, qd = W^-1 J^T (J W^-1 J^T)^-1 (xd - J z) + z
    let winv = w.to_dense(n).try_inverse().unwrap();
    let z = -0.7 * &winv * &g;
    let b = &j * &winv * j.transpose();
    let lambda = b.lu().solve(&(&xd - &j * &z)).unwrap();
    let dense = &winv * j.transpose() * lambda + z;
    let scale = dense.amax().max(1.0);
    assert!(
        (&qd - &dense).amax() < 1e-8 * scale,
        "{}",
        (&qd - &dense).amax()
    );
    assert!((&j * &qd - &xd).amax() < 1e-8 * scale);
}

#[test]
fn recorded_joints_are_the_arms_pelvis_and_torso_of_the_model() {
    use biped_control::momentum::LOLA_ARMS;
    use biped_control::walk::run::RECORDED_JOINTS;
    let lola = lola::build(LolaType::Type2).unwrap();
    assert_eq!(&RECORDED_JOINTS[..6], &LOLA_ARMS[..]);
    assert_eq!(&RECORDED_JOINTS[6..], &["pelvis_rotation", "torso"]);
    for name in RECORDED_JOINTS {
        assert!(
            lola.limits.iter().any(|l| l.name == name),
            "{name} is not a joint of the Lola model"
        );
    }
}
