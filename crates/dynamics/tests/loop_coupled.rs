//! Coupled parts (linear gears, a nonlinear four-bar coupler) on random trees: the mechanism
//! kinematics against finite differences, O(n) with sub-systems against CRBA / sparse / RNEA,
//! and a torque-free simulation that conserves energy and keeps the loop closed.

mod loop_support;

use biped_dynamics::mechanism::Coupling;
use biped_dynamics::model::{FourBar, LinearCoupling, Mechanism};
use biped_dynamics::{
    forward_dynamics, inverse_dynamics, mass_matrix, update_placements, Algorithm, BodySpec, Data,
    JointModel, Model, ModelBuilder, RigidInertia,
};
use loop_support::*;
use nalgebra::{DVector, Isometry3, Matrix3, Vector3, Vector6};
use rand::Rng;

/// Pose, Jacobian and bias of a mechanism against central differences along `q + qd t`.
fn check_mechanism(m: &Mechanism, q: &[f64], qd: &[f64]) {
    let h = 1e-6;
    let at = |t: f64| {
        let qt: Vec<f64> = q.iter().zip(qd).map(|(a, b)| a + b * t).collect();
        m.motion(&qt, qd).unwrap()
    };
    let (m0, mp, mm) = (at(0.0), at(h), at(-h));
    let twist = |m: &biped_dynamics::mechanism::CoupledMotion| {
        let mut t = Vector6::zeros();
        for (c, col) in m.jacobian.iter().enumerate().take(qd.len()) {
            t += col * qd[c];
        }
        t
    };
    // omega~ = R^T Rdot, v = R^T rdot.
    let r0 = m0.pose.rotation.to_rotation_matrix().into_inner();
    let rdot = (mp.pose.rotation.to_rotation_matrix().into_inner()
        - mm.pose.rotation.to_rotation_matrix().into_inner())
        / (2.0 * h);
    let w = r0.transpose() * rdot;
    let omega = Vector3::new(w[(2, 1)], w[(0, 2)], w[(1, 0)]);
    let pdot = (mp.pose.translation.vector - mm.pose.translation.vector) / (2.0 * h);
    let mut fd = Vector6::new(omega.x, omega.y, omega.z, 0.0, 0.0, 0.0);
    fd.fixed_rows_mut::<3>(3)
        .copy_from(&(r0.transpose() * pdot));
    assert!(
        (twist(&m0) - fd).amax() < 1e-6,
        "J vs FD: {} vs {}",
        twist(&m0),
        fd
    );
    let bias_fd = (twist(&mp) - twist(&mm)) / (2.0 * h);
    assert!(
        (m0.bias - bias_fd).amax() < 1e-5 * (1.0 + bias_fd.amax()),
        "bias vs FD"
    );
}

#[test]
fn mechanisms_match_finite_differences() {
    let mut rng = rng(7);
    for _ in 0..50 {
        let n = rng.random_range(1..=3);
        let q: Vec<f64> = (0..n).map(|_| rng.random_range(-3.0..3.0)).collect();
        let qd: Vec<f64> = (0..n).map(|_| rng.random_range(-3.0..3.0)).collect();
        let lin = Mechanism::Linear(LinearCoupling {
            axis: random_axis(&mut rng),
            ratios: (0..n).map(|_| rng.random_range(-5.0..5.0)).collect(),
        });
        check_mechanism(&lin, &q, &qd);
        check_mechanism(&Mechanism::FourBar(four_bar(1.0)), &q[..1], &qd[..1]);
        check_mechanism(&Mechanism::FourBar(four_bar(-1.0)), &q[..1], &qd[..1]);
    }
}

#[test]
fn coupled_parts_on_random_trees_all_methods_agree() {
    let mut with_coupled = 0;
    for seed in 0..60 {
        let model = random_loop_model(
            seed,
            4 + (seed as usize % 20),
            seed % 2 == 0,
            random_coupling,
        );
        with_coupled += usize::from(!model.subsystems().is_empty());
        let mut rng = rng(seed + 1000);
        let mut data = Data::new(&model);
        for _ in 0..3 {
            let q = random_q(&model, &mut rng);
            let v = random_vec(model.nv(), 2.0, &mut rng);
            let tau = random_vec(model.nv(), 5.0, &mut rng);
            let on = check_methods(seed, &model, &mut data, &q, &v, &tau, None);
            let back = inverse_dynamics(&model, &mut data, &q, &v, &on, None).unwrap();
            assert!(rel_diff(back, &tau) < 1e-9, "seed {seed}: RNEA(O(n))");
        }
    }
    assert!(
        with_coupled > 30,
        "only {with_coupled} models had coupled parts"
    );
}

/// Crank (revolute about z at the world origin) with a four-bar coupler part and a pendulum
/// hanging from the crank; gravity along -y in the mechanism plane.
fn four_bar_model() -> Model {
    let mut b = ModelBuilder::new();
    b.set_gravity(Vector3::new(0.0, -9.81, 0.0));
    let inertia = |m: f64, c: Vector3<f64>, r: f64| {
        RigidInertia::new(m, c, Matrix3::identity() * (m * r * r)).unwrap()
    };
    let spec = |name: &str, parent, joint, placement, inertia| BodySpec {
        name: name.into(),
        joint_name: format!("{name}_joint"),
        parent,
        joint,
        placement,
        inertia,
    };
    let crank = b
        .add_body(spec(
            "crank",
            None,
            JointModel::Revolute {
                axis: Vector3::z_axis(),
            },
            Isometry3::identity(),
            inertia(0.5, Vector3::new(0.03, 0.0, 0.0), 0.02),
        ))
        .unwrap();
    b.add_body(spec(
        "coupler",
        None,
        JointModel::Coupled {
            mechanism: Mechanism::FourBar(four_bar(1.0)),
            inputs: vec![crank],
        },
        Isometry3::identity(),
        inertia(0.8, Vector3::new(0.1, 0.0, 0.0), 0.05),
    ))
    .unwrap();
    b.add_body(spec(
        "pendulum",
        Some(crank),
        JointModel::Revolute {
            axis: Vector3::z_axis(),
        },
        Isometry3::translation(0.05, 0.0, 0.0),
        inertia(0.3, Vector3::new(0.0, -0.1, 0.0), 0.03),
    ))
    .unwrap();
    b.build().unwrap()
}

/// Kinetic plus potential energy.
fn energy(model: &Model, data: &mut Data, q: &DVector<f64>, v: &DVector<f64>) -> f64 {
    let kin = 0.5 * v.dot(&(mass_matrix(model, data, q).unwrap() * v));
    update_placements(model, data, q).unwrap();
    let pot: f64 = model
        .bodies()
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let c = data.world_pos[i] + data.world_rot[i] * b.inertia().com();
            -b.inertia().mass() * model.gravity().dot(&c)
        })
        .sum();
    kin + pot
}

/// Distance error of the loop closure `|B - O_B| - L_r` from the coupler's world pose.
fn closure_error(data: &Data, m: &FourBar) -> f64 {
    let b = data.world_pos[1] + data.world_rot[1] * Vector3::new(m.coupler, 0.0, 0.0);
    ((b - Vector3::new(m.ground, 0.0, 0.0)).norm() - m.rocker).abs()
}

#[test]
fn four_bar_simulation_conserves_energy_and_closure() {
    let model = four_bar_model();
    assert_eq!(model.subsystem_names(), vec![vec!["crank", "coupler"]]);
    let mut data = Data::new(&model);
    let mut q = DVector::from_vec(vec![0.3, -0.4]);
    let mut v = DVector::from_vec(vec![4.0, -1.0]);
    let tau = DVector::zeros(2);
    let e0 = energy(&model, &mut data, &q, &v);
    let dt = 1e-3;
    let mut f = |q: &DVector<f64>, v: &DVector<f64>| {
        forward_dynamics(&model, &mut data, q, v, &tau, None, Algorithm::On)
            .unwrap()
            .clone()
    };
    for _ in 0..2000 {
        let a1 = f(&q, &v);
        let (q2, v2) = (&q + &v * (dt / 2.0), &v + &a1 * (dt / 2.0));
        let a2 = f(&q2, &v2);
        let (q3, v3) = (&q + &v2 * (dt / 2.0), &v + &a2 * (dt / 2.0));
        let a3 = f(&q3, &v3);
        let (q4, v4) = (&q + &v3 * dt, &v + &a3 * dt);
        let a4 = f(&q4, &v4);
        q += (&v + &v2 * 2.0 + &v3 * 2.0 + &v4) * (dt / 6.0);
        v += (&a1 + &a2 * 2.0 + &a3 * 2.0 + &a4) * (dt / 6.0);
    }
    let mut data = Data::new(&model);
    let e1 = energy(&model, &mut data, &q, &v);
    assert!(
        (e1 - e0).abs() < 1e-7 * e0.abs().max(1.0),
        "energy drift {} -> {}",
        e0,
        e1
    );
    assert!(closure_error(&data, &four_bar(1.0)) < 1e-12);
    // The crank made at least part of a revolution: the test exercised the loop.
    assert!((q[0] - 0.3).abs() > 0.5, "crank barely moved: {}", q[0]);
}

/// A four-bar driven outside its assembly range gives a typed mechanism error from every
/// entry point (never NaN, never a panic), and works again once back in range.
#[test]
fn mechanism_out_of_range_is_a_typed_error() {
    // Coupler + rocker (0.2) span the gap |O_B - A| = 0.15 when the crank points towards O_B
    // (q = 0) but not the gap 0.25 when it points away (q = pi).
    let bar = FourBar {
        crank: 0.05,
        coupler: 0.1,
        rocker: 0.1,
        ground: 0.2,
        elbow: 1.0,
    };
    let inertia = RigidInertia::new(
        1.0,
        Vector3::new(0.02, 0.0, 0.0),
        Matrix3::identity() * 1e-3,
    )
    .expect("valid inertia");
    let mut b = ModelBuilder::new();
    let crank = b
        .add_body(BodySpec {
            name: "crank".into(),
            joint_name: "q".into(),
            parent: None,
            joint: JointModel::Revolute {
                axis: Vector3::z_axis(),
            },
            placement: Isometry3::identity(),
            inertia,
        })
        .expect("crank");
    b.add_body(BodySpec {
        name: "coupler".into(),
        joint_name: "coupler".into(),
        parent: None,
        joint: JointModel::Coupled {
            mechanism: Mechanism::FourBar(bar),
            inputs: vec![crank],
        },
        placement: Isometry3::identity(),
        inertia,
    })
    .expect("coupler");
    let model: Model = b.build().expect("model");
    let mut data = Data::new(&model);
    let (v, tau) = (DVector::from_element(1, 0.3), DVector::zeros(1));
    let bad = DVector::from_element(1, std::f64::consts::PI);
    let good = DVector::zeros(1);
    let is_mechanism_error = |e: biped_dynamics::DynamicsError| {
        matches!(e, biped_dynamics::DynamicsError::Mechanism { body: 1, .. })
    };
    for algo in [Algorithm::On, Algorithm::Crba, Algorithm::Sparse] {
        let err = forward_dynamics(&model, &mut data, &bad, &v, &tau, None, algo).unwrap_err();
        assert!(is_mechanism_error(err), "{algo:?}");
        let qdd =
            forward_dynamics(&model, &mut data, &good, &v, &tau, None, algo).expect("in range");
        assert!(qdd.iter().all(|x| x.is_finite()));
    }
    assert!(is_mechanism_error(
        mass_matrix(&model, &mut data, &bad).unwrap_err()
    ));
    let err = inverse_dynamics(&model, &mut data, &bad, &v, &tau, None).unwrap_err();
    assert!(is_mechanism_error(err));
}
