//! Kinematics against independent routes: finite differences of integrated configurations,
//! pose composition with nalgebra isometries, and the integrate/difference pair.

mod core_support;

use biped_dynamics::{
    difference, forward_kinematics, integrate, update_placements, Data, JointModel, Model,
};
use core_support::*;
use nalgebra::{DVector, Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

/// World angular and linear velocity of every body origin at `(q, v)`.
fn world_velocities(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> Vec<(Vector3<f64>, Vector3<f64>)> {
    let mut data = Data::new(model);
    forward_kinematics(model, &mut data, q, v, &DVector::zeros(model.nv())).unwrap();
    (0..model.nbodies())
        .map(|i| {
            (
                data.world_rot[i] * data.vel[i].ang,
                data.world_rot[i] * data.vel[i].lin,
            )
        })
        .collect()
}

/// World poses of every body at `q`.
fn poses(model: &Model, q: &DVector<f64>) -> Vec<(Matrix3<f64>, Vector3<f64>)> {
    let mut data = Data::new(model);
    update_placements(model, &mut data, q).unwrap();
    (0..model.nbodies())
        .map(|i| (data.world_rot[i], data.world_pos[i]))
        .collect()
}

/// Relative error with an absolute floor of 1.
fn close(a: &Vector3<f64>, b: &Vector3<f64>, tol: f64) -> bool {
    (a - b).norm() <= tol * a.norm().max(b.norm()).max(1.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Body velocities (2.33) equal central differences of poses along `q (+) v t`.
    #[test]
    fn velocities_match_finite_differences(seed in any::<u64>(), n in 1usize..25) {
        let model = random_model(seed, n, TreeOptions { rotors: true, ..TreeOptions::default() });
        let mut r = rng(seed);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let h = 1e-6;
        let plus = poses(&model, &integrate(&model, &q, &v, h).unwrap());
        let minus = poses(&model, &integrate(&model, &q, &v, -h).unwrap());
        let mut data = Data::new(&model);
        forward_kinematics(&model, &mut data, &q, &v, &DVector::zeros(model.nv())).unwrap();
        for i in 0..model.nbodies() {
            let r0 = data.world_rot[i];
            let rdot = (plus[i].0 - minus[i].0) / (2.0 * h);
            let w_body = vee(&(r0.transpose() * rdot));
            let v_body = r0.transpose() * (plus[i].1 - minus[i].1) / (2.0 * h);
            prop_assert!(close(&w_body, &data.vel[i].ang, 1e-6), "body {i}: {w_body} vs {}", data.vel[i].ang);
            prop_assert!(close(&v_body, &data.vel[i].lin, 1e-6), "body {i}: {v_body} vs {}", data.vel[i].lin);
        }
    }

    /// Conventional accelerations (2.34)/(2.37) equal central differences of world velocities
    /// along the trajectory with generalized velocity `v + a t`.
    #[test]
    fn accelerations_match_finite_differences(seed in any::<u64>(), n in 1usize..25) {
        let model = random_model(seed, n, TreeOptions { rotors: true, ..TreeOptions::default() });
        let mut r = rng(seed);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let a = random_vec(model.nv(), 1.0, &mut r);
        let h = 1e-5;
        let state = |t: f64| {
            let dq = &v * t + &a * (0.5 * t * t);
            let qt = integrate(&model, &q, &dq, 1.0).unwrap();
            world_velocities(&model, &qt, &(&v + &a * t))
        };
        let (plus, minus) = (state(h), state(-h));
        let mut data = Data::new(&model);
        forward_kinematics(&model, &mut data, &q, &v, &a).unwrap();
        for i in 0..model.nbodies() {
            let rt = data.world_rot[i].transpose();
            let dw = rt * (plus[i].0 - minus[i].0) / (2.0 * h);
            let dv = rt * (plus[i].1 - minus[i].1) / (2.0 * h);
            prop_assert!(close(&dw, &data.acc[i].ang, 1e-6), "body {i}: {dw} vs {}", data.acc[i].ang);
            prop_assert!(close(&dv, &data.acc[i].lin, 1e-6), "body {i}: {dv} vs {}", data.acc[i].lin);
        }
    }

    /// World poses equal the composition placement * joint(q) with nalgebra isometries.
    #[test]
    fn poses_match_isometry_composition(seed in any::<u64>(), n in 1usize..30) {
        let model = random_model(seed, n, TreeOptions { rotors: true, ..TreeOptions::default() });
        let q = random_q(&model, &mut rng(seed));
        let got = poses(&model, &q);
        let mut world: Vec<Isometry3<f64>> = Vec::new();
        for body in model.bodies() {
            let qi = body.q_index();
            let joint = match body.joint() {
                JointModel::Revolute { axis } => Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(axis, q[qi])),
                JointModel::GearedRotor { axis, ratio, .. } => Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(axis, ratio * q[qi])),
                JointModel::Prismatic { axis } => Isometry3::from_parts(Translation3::from(axis.into_inner() * q[qi]), UnitQuaternion::identity()),
                JointModel::Fixed => Isometry3::identity(),
                JointModel::Coupled { mechanism, inputs } => {
                    let qin: Vec<f64> = inputs.iter().map(|&b| q[model.bodies()[b].q_index()]).collect();
                    biped_dynamics::mechanism::Coupling::motion(mechanism, &qin, &vec![0.0; qin.len()]).unwrap().pose
                }
                JointModel::FreeEulerZxz => {
                    let r = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), q[qi + 3])
                        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), q[qi + 4])
                        * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), q[qi + 5]);
                    Isometry3::from_parts(Translation3::new(q[qi], q[qi + 1], q[qi + 2]), r)
                }
                JointModel::FreeQuaternion => {
                    let r = UnitQuaternion::new_normalize(nalgebra::Quaternion::new(q[qi + 6], q[qi + 3], q[qi + 4], q[qi + 5]));
                    Isometry3::from_parts(Translation3::new(q[qi], q[qi + 1], q[qi + 2]), r)
                }
            };
            let parent = body.parent().map_or(Isometry3::identity(), |p| world[p]);
            world.push(parent * body.placement() * joint);
        }
        for (i, w) in world.iter().enumerate() {
            prop_assert!((rot(w) - got[i].0).amax() < 1e-12);
            prop_assert!((w.translation.vector - got[i].1).amax() < 1e-12);
        }
    }

    /// `difference(q, integrate(q, v, dt)) = v dt` and `integrate(q, difference(q, q1)) = q1`.
    #[test]
    fn integrate_difference_roundtrip(seed in any::<u64>(), n in 1usize..20) {
        let model = random_model(seed, n, TreeOptions::default());
        let mut r = rng(seed);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let q1 = integrate(&model, &q, &v, 0.7).unwrap();
        let d = difference(&model, &q, &q1).unwrap();
        prop_assert!(rel_diff(&d, &(&v * 0.7)) < 1e-10);
        let q2 = integrate(&model, &q, &d, 1.0).unwrap();
        let p1 = poses(&model, &q1);
        let p2 = poses(&model, &q2);
        for i in 0..model.nbodies() {
            prop_assert!((p1[i].0 - p2[i].0).amax() < 1e-12 && (p1[i].1 - p2[i].1).amax() < 1e-12);
        }
    }
}

/// The neutral configuration has identity quaternions and the joints list is in coordinate order.
#[test]
fn neutral_and_joint_list() {
    let model = random_model(
        3,
        20,
        TreeOptions {
            root: 0,
            rotors: true,
            ..TreeOptions::default()
        },
    );
    let q = model.neutral();
    assert_eq!(q.len(), model.nq());
    assert_eq!(q.rows(3, 4).as_slice(), &[0.0, 0.0, 0.0, 1.0]);
    let mut next_q = 0;
    let mut next_v = 0;
    for j in model.joints() {
        assert_eq!((j.q_index, j.v_index), (next_q, next_v));
        next_q += j.nq;
        next_v += j.nv;
    }
    assert_eq!((next_q, next_v), (model.nq(), model.nv()));
    assert_eq!(model.body_id("body5"), Some(5));
    assert_eq!(model.body_names()[7], "body7");
}
