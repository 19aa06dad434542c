//! Centre of mass, CoM Jacobian, centroidal momentum matrix `A_G`, `J_L` (7.2) and the bias
//! `Adot_G v` against independent routes: mass-weighted sums and body-by-body momenta (7.1)
//! from world velocities, finite differences, the floating-base mass matrix, and momentum
//! conservation of free motion (forward dynamics + RK4).

mod core_support;

use biped_dynamics::dill::{dill, dill_test_state};
use biped_dynamics::{
    center_of_mass, forward_dynamics, forward_kinematics, integrate, mass_matrix, Algorithm,
    BodySpec, Centroidal, Data, JacobianError, JointModel, Model, ModelBuilder, RigidInertia,
};
use core_support::*;
use nalgebra::{DMatrix, DVector, Isometry3, Vector3, Vector6};
use proptest::prelude::*;

/// Body-by-body quantities from the recursive kinematics: total mass, CoM, linear momentum and
/// angular momentum about the CoM, `sum I_i w_i + m_i (c_i - c) x v_ci` (7.1).
struct Direct {
    mass: f64,
    com: Vector3<f64>,
    p: Vector3<f64>,
    l: Vector3<f64>,
}

/// Per body: mass, world CoM, world CoM velocity, spin momentum `I_C w` (world).
type BodyTerms = (f64, Vector3<f64>, Vector3<f64>, Vector3<f64>);

/// Mass-weighted sums over bodies at `(q, v)`, world coordinates.
fn direct(model: &Model, q: &DVector<f64>, v: &DVector<f64>) -> Direct {
    let mut data = Data::new(model);
    forward_kinematics(model, &mut data, q, v, &DVector::zeros(model.nv())).unwrap();
    let bodies: Vec<BodyTerms> = model
        .bodies()
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let (r, vel, inertia) = (data.world_rot[i], data.vel[i], b.inertia());
            let c = data.world_pos[i] + r * inertia.com();
            let vc = r * (vel.lin + vel.ang.cross(&inertia.com()));
            let spin = r * (inertia.inertia_about_com() * vel.ang);
            (inertia.mass(), c, vc, spin)
        })
        .collect();
    let mass: f64 = bodies.iter().map(|b| b.0).sum();
    let com = bodies.iter().map(|b| b.1 * b.0).sum::<Vector3<f64>>() / mass;
    let p = bodies.iter().map(|b| b.2 * b.0).sum();
    let l = bodies
        .iter()
        .map(|(m, c, vc, spin)| spin + (c - com).cross(&(vc * *m)))
        .sum();
    Direct { mass, com, p, l }
}

/// Max-norm error relative to `max(1, |expected|)`.
fn rel_err(got: &[f64], expected: &[f64]) -> f64 {
    let scale = expected.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    got.iter()
        .zip(expected)
        .fold(0.0f64, |m, (g, e)| m.max((g - e).abs()))
        / scale
}

/// `h_G = [L_G; p]` at `(q, v)` as a 6-vector.
fn momentum(
    model: &Model,
    cen: &mut Centroidal,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> Vector6<f64> {
    let mut data = Data::new(model);
    cen.compute(model, &mut data, q, v).unwrap();
    cen.momentum().unwrap().to_vector()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// CoM, its velocity and the momenta of `A_G v` equal the body-by-body sums (7.1).
    #[test]
    fn momentum_equals_body_sums(seed in any::<u64>(), n in 1usize..30) {
        let model = random_model(seed, n, TreeOptions { rotors: true, ..TreeOptions::default() });
        let mut r = rng(seed ^ 0x11);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let d = direct(&model, &q, &v);
        let mut data = Data::new(&model);
        let com = center_of_mass(&model, &mut data, &q, Some(&v)).unwrap();
        prop_assert!((com.mass - d.mass).abs() < 1e-12 * d.mass);
        prop_assert!(rel_err(com.position.as_slice(), d.com.as_slice()) < 1e-12);
        prop_assert!(rel_err((com.velocity * d.mass).as_slice(), d.p.as_slice()) < 1e-12);
        let mut cen = Centroidal::new(&model);
        cen.compute(&model, &mut data, &q, &v).unwrap();
        prop_assert!(rel_err(cen.com().as_slice(), d.com.as_slice()) < 1e-12);
        prop_assert!(rel_err(cen.com_velocity().unwrap().as_slice(), com.velocity.as_slice()) < 1e-11);
        let ag = cen.ag().unwrap();
        let h = ag * &v;
        let expected = [d.l.x, d.l.y, d.l.z, d.p.x, d.p.y, d.p.z];
        prop_assert!(rel_err(h.as_slice(), &expected) < 1e-11, "{h} vs {expected:?}");
        prop_assert!(rel_err(cen.momentum().unwrap().to_vector().as_slice(), &expected) < 1e-11);
        let mut jl = DMatrix::zeros(3, model.nv());
        cen.angular_momentum_jacobian(&mut jl).unwrap();
        let l = &jl * &v;
        prop_assert!(rel_err(l.as_slice(), d.l.as_slice()) < 1e-11);
        let full = ag.clone();
        cen.compute_matrix(&model, &mut data, &q).unwrap();
        prop_assert_eq!(cen.ag().unwrap(), &full);
        prop_assert!(matches!(cen.momentum(), Err(JacobianError::NotComputed(_))));
    }

    /// The CoM Jacobian equals central differences of the CoM along `q (+) e_j t` and the
    /// linear rows of `A_G` divided by the mass.
    #[test]
    fn com_jacobian_matches_differences(seed in any::<u64>(), n in 1usize..16) {
        let model = random_model(seed, n, TreeOptions { rotors: true, ..TreeOptions::default() });
        let mut r = rng(seed ^ 0x22);
        let q = random_q(&model, &mut r);
        let nv = model.nv();
        let mut data = Data::new(&model);
        let mut cen = Centroidal::new(&model);
        let mut jc = DMatrix::zeros(3, nv);
        cen.com_jacobian(&model, &mut data, &q, &mut jc).unwrap();
        let com_at = |qq: &DVector<f64>| direct(&model, qq, &DVector::zeros(nv)).com;
        prop_assert!(rel_err(cen.com().as_slice(), com_at(&q).as_slice()) < 1e-12);
        let h = 1e-6;
        for col in 0..nv {
            let mut e = DVector::zeros(nv);
            e[col] = 1.0;
            let plus = com_at(&integrate(&model, &q, &e, h).unwrap());
            let minus = com_at(&integrate(&model, &q, &e, -h).unwrap());
            let fd = (plus - minus) / (2.0 * h);
            let got: Vec<f64> = jc.column(col).iter().copied().collect();
            prop_assert!(rel_err(&got, fd.as_slice()) < 1e-6, "col {col}: {got:?} vs {fd}");
        }
        cen.compute(&model, &mut data, &q, &DVector::zeros(nv)).unwrap();
        let lin = cen.ag().unwrap().rows(3, 3) / cen.mass();
        prop_assert!(rel_err(lin.as_slice(), jc.as_slice()) < 1e-12);
    }

    /// `A_G a + Adot_G v` equals the central difference of `h_G` along `(q (+) v t, v + a t)`.
    #[test]
    fn bias_matches_momentum_rate(seed in any::<u64>(), n in 1usize..20) {
        let model = random_model(seed, n, TreeOptions { rotors: true, ..TreeOptions::default() });
        let mut r = rng(seed ^ 0x33);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let a = random_vec(model.nv(), 1.0, &mut r);
        let mut cen = Centroidal::new(&model);
        let h = 1e-6;
        let plus = momentum(&model, &mut cen, &integrate(&model, &q, &v, h).unwrap(), &(&v + &a * h));
        let minus = momentum(&model, &mut cen, &integrate(&model, &q, &v, -h).unwrap(), &(&v - &a * h));
        let fd = (plus - minus) / (2.0 * h);
        let mut data = Data::new(&model);
        cen.compute(&model, &mut data, &q, &v).unwrap();
        let got = cen.ag().unwrap() * &a + DVector::from_column_slice(cen.ag_bias().unwrap().to_vector().as_slice());
        prop_assert!(rel_err(got.as_slice(), fd.as_slice()) < 1e-6, "{got} vs {fd}");
    }

    /// Floating base (quaternion root): the root rows of the mass matrix are the momentum about
    /// the root origin in root coordinates, `M[0..3] = A_0^T p`, `M[3..6] = A_0^T L_O`; shifted
    /// to the CoM they equal `A_G`.
    #[test]
    fn floating_base_mass_matrix_rows_equal_ag(seed in any::<u64>(), n in 1usize..25) {
        let model = random_model(seed, n, TreeOptions { root: 0, rotors: true, ..TreeOptions::default() });
        let mut r = rng(seed ^ 0x44);
        let q = random_q(&model, &mut r);
        let mut data = Data::new(&model);
        let m = mass_matrix(&model, &mut data, &q).unwrap().clone();
        let (r0, p0) = (data.world_rot[0], data.world_pos[0]);
        let mut cen = Centroidal::new(&model);
        cen.compute(&model, &mut data, &q, &DVector::zeros(model.nv())).unwrap();
        let ag = cen.ag().unwrap();
        let c = cen.com();
        for col in 0..model.nv() {
            let p = r0 * Vector3::new(m[(0, col)], m[(1, col)], m[(2, col)]);
            let lo = r0 * Vector3::new(m[(3, col)], m[(4, col)], m[(5, col)]);
            let lg = lo - (c - p0).cross(&p);
            let expected = [lg.x, lg.y, lg.z, p.x, p.y, p.z];
            let got: Vec<f64> = ag.column(col).iter().copied().collect();
            prop_assert!(rel_err(&got, &expected) < 1e-10, "col {col}: {got:?} vs {expected:?}");
        }
    }

    /// Free motion of a floating tree (no gravity, no torques): the momentum rate
    /// `A_G qddot + Adot_G v` vanishes for the forward-dynamics accelerations.
    #[test]
    fn free_floating_momentum_rate_is_zero(seed in any::<u64>(), n in 1usize..25) {
        let opts = TreeOptions { root: 0, rotors: true, gravity: Vector3::zeros(), ..TreeOptions::default() };
        let model = random_model(seed, n, opts);
        let mut r = rng(seed ^ 0x55);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let mut data = Data::new(&model);
        let tau = DVector::zeros(model.nv());
        let qdd = forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::Crba).unwrap().clone();
        let mut cen = Centroidal::new(&model);
        cen.compute(&model, &mut data, &q, &v).unwrap();
        let rate = cen.ag().unwrap() * &qdd + DVector::from_column_slice(cen.ag_bias().unwrap().to_vector().as_slice());
        let scale = cen.momentum().unwrap().to_vector().amax().max(1.0);
        prop_assert!(rate.amax() < 1e-9 * scale, "{rate}");
    }
}

/// CoM of Dill(n) at the thesis test state equals the mass-weighted body CoMs.
#[test]
fn dill_com_is_mass_weighted_mean() {
    for n in 1..=6 {
        let model = dill(n).unwrap();
        let (q, v) = dill_test_state(&model);
        let d = direct(&model, &q, &v);
        let mut data = Data::new(&model);
        let com = center_of_mass(&model, &mut data, &q, Some(&v)).unwrap();
        assert!(rel_err(com.position.as_slice(), d.com.as_slice()) < 1e-12);
        assert!(rel_err((com.velocity * d.mass).as_slice(), d.p.as_slice()) < 1e-12);
        let mut cen = Centroidal::new(&model);
        let mut jc = DMatrix::zeros(3, model.nv());
        cen.com_jacobian(&model, &mut data, &q, &mut jc).unwrap();
        let vc = &jc * &v;
        assert!(rel_err(vc.as_slice(), com.velocity.as_slice()) < 1e-12);
    }
}

/// One classical RK4 step of `(q, v)` for vector-space joints (Euler-ZXZ root, no quaternions).
fn rk4(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    h: f64,
) -> (DVector<f64>, DVector<f64>) {
    let tau = DVector::zeros(model.nv());
    let mut f = |qs: &DVector<f64>, vs: &DVector<f64>| {
        forward_dynamics(model, data, qs, vs, &tau, None, Algorithm::Crba)
            .unwrap()
            .clone()
    };
    let step = |qs: &DVector<f64>, dq: &DVector<f64>, t: f64| integrate(model, qs, dq, t).unwrap();
    let a1 = f(q, v);
    let v2 = v + &a1 * (h / 2.0);
    let a2 = f(&step(q, v, h / 2.0), &v2);
    let v3 = v + &a2 * (h / 2.0);
    let a3 = f(&step(q, &v2, h / 2.0), &v3);
    let v4 = v + &a3 * h;
    let a4 = f(&step(q, &v3, h), &v4);
    let dq = (v + &v2 * 2.0 + &v3 * 2.0 + &v4) / 6.0;
    let dv = (&a1 + &a2 * 2.0 + &a3 * 2.0 + &a4) / 6.0;
    (step(q, &dq, h), v + dv * h)
}

/// Free motion (no gravity, no torques, RK4 at 1 ms for 0.5 s) of floating trees with geared
/// rotors conserves the linear momentum and the angular momentum about the CoM.
#[test]
fn free_motion_conserves_centroidal_momentum() {
    let opts = TreeOptions {
        root: 1,
        rotors: true,
        inner_free: false,
        gravity: Vector3::zeros(),
    };
    for seed in [3u64, 4, 5] {
        let model = random_model(seed, 10, opts);
        let mut r = rng(seed);
        let mut q = random_q(&model, &mut r);
        let mut v = random_vec(model.nv(), 1.0, &mut r);
        let mut data = Data::new(&model);
        let mut cen = Centroidal::new(&model);
        let h0 = momentum(&model, &mut cen, &q, &v);
        let mut drift = 0.0f64;
        for _ in 0..500 {
            (q, v) = rk4(&model, &mut data, &q, &v, 1e-3);
            let h = momentum(&model, &mut cen, &q, &v);
            drift = drift.max((h - h0).amax() / h0.amax().max(1e-3));
        }
        println!("seed {seed}: centroidal momentum drift {drift:e}");
        assert!(drift < 1e-8, "seed {seed}: drift {drift:e}");
    }
}

/// A model without mass has no CoM; calls before `compute` and bad shapes are errors.
#[test]
fn bad_inputs_are_errors() {
    let mut b = ModelBuilder::new();
    b.add_body(BodySpec {
        name: "ghost".into(),
        joint_name: "j".into(),
        parent: None,
        joint: JointModel::Revolute {
            axis: Vector3::z_axis(),
        },
        placement: Isometry3::identity(),
        inertia: RigidInertia::zero(),
    })
    .unwrap();
    let ghost = b.build().unwrap();
    let q = DVector::zeros(1);
    let mut data = Data::new(&ghost);
    assert!(matches!(
        center_of_mass(&ghost, &mut data, &q, None),
        Err(JacobianError::ZeroMass)
    ));
    let mut cen = Centroidal::new(&ghost);
    assert!(matches!(cen.ag(), Err(JacobianError::NotComputed(_))));
    assert!(matches!(
        cen.compute(&ghost, &mut data, &q, &q),
        Err(JacobianError::ZeroMass)
    ));
    assert!(matches!(cen.momentum(), Err(JacobianError::NotComputed(_))));
    let model = random_model(9, 5, TreeOptions::default());
    let mut data = Data::new(&model);
    let mut cen = Centroidal::new(&model);
    let q = random_q(&model, &mut rng(9));
    let mut wrong = DMatrix::zeros(3, model.nv() + 1);
    assert!(matches!(
        cen.com_jacobian(&model, &mut data, &q, &mut wrong),
        Err(JacobianError::OutputShape { .. })
    ));
    let bad_v = DVector::from_element(model.nv(), f64::NAN);
    assert!(matches!(
        cen.compute(&model, &mut data, &q, &bad_v),
        Err(JacobianError::Dynamics(_))
    ));
}
