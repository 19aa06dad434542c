//! Compensation (7.4)-(7.9) on Lola Type 2: the exact law equals the dense least-squares
//! minimum-norm solution and, fed through the null space of (7.3), makes `J_Lz qdot = L_d`;
//! the normalised law (7.9) is the same direction scaled by `|J_r|` and stays bounded.

#[path = "momentum_util.rs"]
mod util;

use biped_control::momentum::{
    Compensation, CompensationLaw, MomentumError, VerticalMomentum, LOLA_ARMS, LOLA_ARM_FLEXION,
};
use nalgebra::{DMatrix, DVector};
use util::{pinv, rel, Lola};

/// `J_Lz^T` at a random state, a random `qdot` and a random `L_d`.
fn sample(s: &mut Lola) -> (DVector<f64>, DVector<f64>, f64) {
    let model = s.lola.model.clone();
    let (q, qdot) = s.state();
    let mut vm = VerticalMomentum::new(&model);
    vm.compute(&model, &mut s.data, &mut s.centroidal, &q)
        .unwrap();
    let l_d = s.vector(1)[0];
    (vm.jacobian_z().clone(), qdot, l_d)
}

#[test]
fn exact_law_is_the_least_squares_solution_and_tracks_the_reference() {
    let mut s = Lola::new(11);
    for joints in [&LOLA_ARM_FLEXION[..], &LOLA_ARMS[..]] {
        let comp = Compensation::new(s.model(), joints, CompensationLaw::Exact).unwrap();
        let r = comp.reducing().to_vec();
        for _ in 0..10 {
            let (jlz, qdot, l_d) = sample(&mut s);
            let mut y = DVector::zeros(jlz.len());
            let terms = comp.add_to(&jlz, &qdot, l_d, &mut y).unwrap();
            // Independent: minimum-norm w with J_r w = L_d - J_p qdot_p, by dense SVD.
            let j_r = DMatrix::from_fn(1, r.len(), |_, k| jlz[r[k]]);
            let mut producing = jlz.dot(&qdot);
            for &i in &r {
                producing -= jlz[i] * qdot[i];
            }
            assert!(rel(terms.producing, producing) < 1e-12);
            let w = pinv(&j_r) * DVector::from_element(1, l_d - producing);
            for (k, &i) in r.iter().enumerate() {
                assert!((-y[i] - w[k]).abs() < 1e-9 * w.norm().max(1.0));
            }
            // The thesis's qdot_r is the negated arm velocity: J_p qdot_p - J_r qdot_r = L_d (7.5).
            let mut applied = qdot.clone();
            for &i in &r {
                applied[i] = -y[i];
            }
            assert!(rel(jlz.dot(&applied), l_d) < 1e-9);
            assert!(y
                .iter()
                .enumerate()
                .all(|(i, v)| comp.is_reducing(i) || *v == 0.0));
        }
    }
}

#[test]
fn exact_law_through_the_rmrc_null_space_reaches_the_reference() {
    // Tasks fix every producing DoF (the arms are free, q_r = q_free): J_x = S_p. The RMRC
    // solution (7.3) with W = E, qdot = J_x^# xdot - N y, from dense pseudo-inverses.
    let mut s = Lola::new(12);
    let comp = Compensation::new(s.model(), &LOLA_ARM_FLEXION, CompensationLaw::Exact).unwrap();
    for _ in 0..5 {
        let (jlz, qdot_p, l_d) = sample(&mut s);
        let n = jlz.len();
        let rows: Vec<usize> = (0..n).filter(|&i| !comp.is_reducing(i)).collect();
        let jx = DMatrix::from_fn(rows.len(), n, |a, b| if rows[a] == b { 1.0 } else { 0.0 });
        let xdot = &jx * &qdot_p;
        let jx_pinv = pinv(&jx);
        let null = DMatrix::identity(n, n) - &jx_pinv * &jx;
        let mut y = DVector::zeros(n);
        comp.add_to(&jlz, &qdot_p, l_d, &mut y).unwrap();
        let qdot = &jx_pinv * xdot - null * y;
        assert!(
            rel(jlz.dot(&qdot), l_d) < 1e-8,
            "{} vs {l_d}",
            jlz.dot(&qdot)
        );
    }
}

#[test]
fn normalised_law_is_the_exact_direction_scaled_by_the_norm() {
    let mut s = Lola::new(13);
    let exact = Compensation::new(s.model(), &LOLA_ARM_FLEXION, CompensationLaw::Exact).unwrap();
    let norm = Compensation::lola(s.model())
        .unwrap()
        .with_gain(2.0)
        .unwrap();
    assert_eq!(norm.law(), CompensationLaw::Normalised);
    for _ in 0..10 {
        let (jlz, qdot, l_d) = sample(&mut s);
        let (mut ye, mut yn) = (DVector::zeros(jlz.len()), DVector::zeros(jlz.len()));
        let te = exact.add_to(&jlz, &qdot, l_d, &mut ye).unwrap();
        norm.add_to(&jlz, &qdot, l_d, &mut yn).unwrap();
        let j_r: f64 = exact
            .reducing()
            .iter()
            .map(|&i| jlz[i] * jlz[i])
            .sum::<f64>();
        assert!(rel(te.reducing_norm, j_r.sqrt()) < 1e-12);
        assert!((&yn - &ye * (2.0 * te.reducing_norm)).norm() < 1e-9 * yn.norm().max(1.0));
    }
}

#[test]
fn near_singular_reducing_jacobian() {
    let mut s = Lola::new(14);
    let (mut jlz, qdot, l_d) = sample(&mut s);
    let exact = Compensation::new(s.model(), &LOLA_ARM_FLEXION, CompensationLaw::Exact).unwrap();
    let norm = Compensation::lola(s.model()).unwrap();
    let mut y = DVector::zeros(jlz.len());
    for scale in [1e-2, 1e-4, 1e-6] {
        for &i in exact.reducing() {
            jlz[i] *= scale;
        }
        y.fill(0.0);
        norm.add_to(&jlz, &qdot, l_d, &mut y).unwrap();
        // (7.9) is |e| J_r / |J_r|: bounded by the momentum error whatever |J_r|.
        let e = norm.terms(&jlz, &qdot, l_d).unwrap().producing - l_d;
        assert!(rel(y.norm(), e.abs()) < 1e-9);
    }
    for &i in exact.reducing() {
        jlz[i] = 0.0;
    }
    assert!(matches!(
        exact.add_to(&jlz, &qdot, l_d, &mut y),
        Err(MomentumError::Singular { .. })
    ));
    y.fill(0.0);
    norm.add_to(&jlz, &qdot, l_d, &mut y).unwrap();
    assert_eq!(y.norm(), 0.0);
}

#[test]
fn add_to_accumulates_on_the_gradient() {
    let mut s = Lola::new(15);
    let (jlz, qdot, l_d) = sample(&mut s);
    let comp = Compensation::lola(s.model()).unwrap();
    let gradient = s.vector(jlz.len());
    let mut y = gradient.clone();
    comp.add_to(&jlz, &qdot, l_d, &mut y).unwrap();
    let mut alone = DVector::zeros(jlz.len());
    comp.add_to(&jlz, &qdot, l_d, &mut alone).unwrap();
    assert!((y - gradient - alone).norm() < 1e-14);
}

#[test]
fn bad_sets_and_inputs_are_typed_errors() {
    let mut s = Lola::new(16);
    let m = s.model().clone();
    let law = CompensationLaw::Exact;
    assert!(matches!(
        Compensation::new(&m, &["nose"], law),
        Err(MomentumError::UnknownJoint(_))
    ));
    assert!(matches!(
        Compensation::new(&m, &["root"], law),
        Err(MomentumError::NotOneDof { .. })
    ));
    let dup = ["l_shoulder", "l_shoulder"];
    assert!(matches!(
        Compensation::new(&m, &dup, law),
        Err(MomentumError::BadReducingSet)
    ));
    assert!(matches!(
        Compensation::new(&m, &[], law),
        Err(MomentumError::BadReducingSet)
    ));
    let comp = Compensation::lola(&m).unwrap();
    assert!(comp.clone().with_gain(f64::NAN).is_err());
    assert!(comp.clone().with_gain(-1.0).is_err());
    let (jlz, qdot, l_d) = sample(&mut s);
    let mut y = DVector::zeros(jlz.len());
    let short = DVector::zeros(3);
    assert!(matches!(
        comp.add_to(&short, &qdot, l_d, &mut y),
        Err(MomentumError::Dimension { .. })
    ));
    assert!(comp.add_to(&jlz, &short, l_d, &mut y).is_err());
    assert!(comp
        .add_to(&jlz, &qdot, l_d, &mut DVector::zeros(2))
        .is_err());
    assert!(matches!(
        comp.add_to(&jlz, &qdot, f64::NAN, &mut y),
        Err(MomentumError::NonFinite { .. })
    ));
    let mut bad = qdot.clone();
    bad[0] = f64::INFINITY;
    assert!(comp.add_to(&jlz, &bad, l_d, &mut y).is_err());
    assert!(
        y.iter().all(|v| *v == 0.0),
        "failed calls leave y untouched"
    );
}
