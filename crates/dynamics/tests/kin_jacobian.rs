//! Body and point Jacobians (5.7) and their derivatives against independent routes: central
//! differences of world poses along `q (+) e_j t` (every column), differences of `J` along the
//! motion `q (+) v t` (for `Jdot`), and accelerations of the recursive kinematics (2.34).

mod core_support;

use biped_dynamics::{
    forward_kinematics, integrate, update_placements, Data, JacobianError, JacobianFrame,
    Jacobians, Model,
};
use core_support::*;
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use proptest::prelude::*;

const FRAMES: [JacobianFrame; 3] = [
    JacobianFrame::Body,
    JacobianFrame::WorldAligned,
    JacobianFrame::World,
];

/// World poses of all bodies at `q` (position kinematics only).
fn poses(model: &Model, q: &DVector<f64>) -> Vec<(Matrix3<f64>, Vector3<f64>)> {
    let mut data = Data::new(model);
    update_placements(model, &mut data, q).unwrap();
    (0..model.nbodies())
        .map(|i| (data.world_rot[i], data.world_pos[i]))
        .collect()
}

/// Body velocity `[omega; rdot_O]` of a pose moving from `minus` to `plus` in time `2h`,
/// expressed in `frame` (the pose at the midpoint is `mid`).
fn fd_velocity(
    frame: JacobianFrame,
    mid: &(Matrix3<f64>, Vector3<f64>),
    plus: &(Matrix3<f64>, Vector3<f64>),
    minus: &(Matrix3<f64>, Vector3<f64>),
    h: f64,
) -> [f64; 6] {
    let rdot = (plus.0 - minus.0) / (2.0 * h);
    let w = vee(&(rdot * mid.0.transpose()));
    let pdot = (plus.1 - minus.1) / (2.0 * h);
    let (a, l) = match frame {
        JacobianFrame::WorldAligned => (w, pdot),
        JacobianFrame::World => (w, pdot - w.cross(&mid.1)),
        JacobianFrame::Body => (mid.0.transpose() * w, mid.0.transpose() * pdot),
    };
    [a.x, a.y, a.z, l.x, l.y, l.z]
}

/// Max-norm error relative to `max(1, |expected|)`.
fn rel_err(got: &[f64], expected: &[f64]) -> f64 {
    let scale = expected.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    got.iter()
        .zip(expected)
        .fold(0.0f64, |m, (g, e)| m.max((g - e).abs()))
        / scale
}

/// `q (+) w t` for a unit direction `w`.
fn moved(model: &Model, q: &DVector<f64>, w: &DVector<f64>, t: f64) -> DVector<f64> {
    integrate(model, q, w, t).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Every column of every body Jacobian (three frames) and of point Jacobians equals the
    /// central difference of the pose along `q (+) e_j t`.
    #[test]
    fn jacobian_columns_match_pose_differences(seed in any::<u64>(), n in 1usize..14) {
        let model = random_model(seed, n, TreeOptions { rotors: true, ..TreeOptions::default() });
        let mut r = rng(seed ^ 0x5eed);
        let q = random_q(&model, &mut r);
        let point = Vector3::new(0.3, -0.2, 0.1);
        let mut data = Data::new(&model);
        let mut jac = Jacobians::new(&model);
        jac.compute(&model, &mut data, &q).unwrap();
        let mid = poses(&model, &q);
        let mut j6 = DMatrix::zeros(6, model.nv());
        let mut j3 = DMatrix::zeros(3, model.nv());
        let h = 1e-6;
        for col in 0..model.nv() {
            let mut e = DVector::zeros(model.nv());
            e[col] = 1.0;
            let plus = poses(&model, &moved(&model, &q, &e, h));
            let minus = poses(&model, &moved(&model, &q, &e, -h));
            let at = |s: &(Matrix3<f64>, Vector3<f64>)| (s.0, s.1 + s.0 * point);
            for i in 0..model.nbodies() {
                for frame in FRAMES {
                    jac.body_jacobian(i, frame, &mut j6).unwrap();
                    let fd = fd_velocity(frame, &mid[i], &plus[i], &minus[i], h);
                    let got: Vec<f64> = j6.column(col).iter().copied().collect();
                    prop_assert!(rel_err(&got, &fd) < 1e-6, "body {i} col {col} {frame:?}: {got:?} vs {fd:?}");
                    jac.frame_jacobian(i, &point, frame, &mut j6).unwrap();
                    let fd = fd_velocity(frame, &at(&mid[i]), &at(&plus[i]), &at(&minus[i]), h);
                    let got: Vec<f64> = j6.column(col).iter().copied().collect();
                    prop_assert!(rel_err(&got, &fd) < 1e-6, "frame on {i} col {col} {frame:?}");
                }
                jac.point_jacobian(i, &point, &mut j3).unwrap();
                let p = |s: &(Matrix3<f64>, Vector3<f64>)| s.1 + s.0 * point;
                let fd = (p(&plus[i]) - p(&minus[i])) / (2.0 * h);
                let got: Vec<f64> = j3.column(col).iter().copied().collect();
                prop_assert!(rel_err(&got, fd.as_slice()) < 1e-6, "point on {i} col {col}");
            }
        }
    }

    /// `Jdot` (all frames, and of point Jacobians) equals the central difference of `J` along
    /// the motion `q (+) v t`.
    #[test]
    fn jacobian_derivatives_match_differences(seed in any::<u64>(), n in 1usize..16) {
        let model = random_model(seed, n, TreeOptions { rotors: true, ..TreeOptions::default() });
        let mut r = rng(seed ^ 0xd07);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let point = Vector3::new(-0.1, 0.25, 0.2);
        let h = 1e-6;
        let mut data = Data::new(&model);
        let (mut at, mut plus, mut minus) =
            (Jacobians::new(&model), Jacobians::new(&model), Jacobians::new(&model));
        at.compute_with_derivatives(&model, &mut data, &q, &v).unwrap();
        plus.compute(&model, &mut data, &moved(&model, &q, &v, h)).unwrap();
        minus.compute(&model, &mut data, &moved(&model, &q, &v, -h)).unwrap();
        let nv = model.nv();
        let (mut d, mut jp, mut jm) = (DMatrix::zeros(6, nv), DMatrix::zeros(6, nv), DMatrix::zeros(6, nv));
        let (mut d3, mut jp3, mut jm3) = (DMatrix::zeros(3, nv), DMatrix::zeros(3, nv), DMatrix::zeros(3, nv));
        for i in 0..model.nbodies() {
            for frame in FRAMES {
                at.body_jacobian_derivative(i, frame, &mut d).unwrap();
                plus.body_jacobian(i, frame, &mut jp).unwrap();
                minus.body_jacobian(i, frame, &mut jm).unwrap();
                let fd = (&jp - &jm) / (2.0 * h);
                prop_assert!(rel_err(d.as_slice(), fd.as_slice()) < 1e-6, "body {i} {frame:?}\n{d}\n{fd}");
                at.frame_jacobian_derivative(i, &point, frame, &mut d).unwrap();
                plus.frame_jacobian(i, &point, frame, &mut jp).unwrap();
                minus.frame_jacobian(i, &point, frame, &mut jm).unwrap();
                let fd = (&jp - &jm) / (2.0 * h);
                prop_assert!(rel_err(d.as_slice(), fd.as_slice()) < 1e-6, "frame on {i} {frame:?}");
            }
            at.point_jacobian_derivative(i, &point, &mut d3).unwrap();
            plus.point_jacobian(i, &point, &mut jp3).unwrap();
            minus.point_jacobian(i, &point, &mut jm3).unwrap();
            let fd = (&jp3 - &jm3) / (2.0 * h);
            prop_assert!(rel_err(d3.as_slice(), fd.as_slice()) < 1e-6, "point on {i}");
        }
    }

    /// `J a + Jdot v` equals the accelerations of the recursive kinematics (2.34): the
    /// conventional acceleration (world-aligned), the rate of body components (body frame),
    /// and the classical acceleration of a body-fixed point.
    #[test]
    fn accelerations_equal_j_a_plus_jdot_v(seed in any::<u64>(), n in 1usize..25) {
        let model = random_model(seed, n, TreeOptions { rotors: true, ..TreeOptions::default() });
        let mut r = rng(seed ^ 0xacc);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let a = random_vec(model.nv(), 1.0, &mut r);
        let point = Vector3::new(0.2, 0.1, -0.3);
        let mut fk = Data::new(&model);
        forward_kinematics(&model, &mut fk, &q, &v, &a).unwrap();
        let mut data = Data::new(&model);
        let mut jac = Jacobians::new(&model);
        jac.compute_with_derivatives(&model, &mut data, &q, &v).unwrap();
        let nv = model.nv();
        let (mut j, mut jd) = (DMatrix::zeros(6, nv), DMatrix::zeros(6, nv));
        let (mut j3, mut jd3) = (DMatrix::zeros(3, nv), DMatrix::zeros(3, nv));
        for i in 0..model.nbodies() {
            let (rot, vel, acc) = (fk.world_rot[i], fk.vel[i], fk.acc[i]);
            jac.body_jacobian(i, JacobianFrame::WorldAligned, &mut j).unwrap();
            jac.body_jacobian_derivative(i, JacobianFrame::WorldAligned, &mut jd).unwrap();
            let got = &j * &a + &jd * &v;
            let (wd, ao) = (rot * acc.ang, rot * acc.lin);
            let expected = [wd.x, wd.y, wd.z, ao.x, ao.y, ao.z];
            prop_assert!(rel_err(got.as_slice(), &expected) < 1e-10, "world-aligned body {i}");

            jac.body_jacobian(i, JacobianFrame::Body, &mut j).unwrap();
            jac.body_jacobian_derivative(i, JacobianFrame::Body, &mut jd).unwrap();
            let got = &j * &a + &jd * &v;
            let lin = acc.lin - vel.ang.cross(&vel.lin);
            let expected = [acc.ang.x, acc.ang.y, acc.ang.z, lin.x, lin.y, lin.z];
            prop_assert!(rel_err(got.as_slice(), &expected) < 1e-10, "body-frame body {i}");

            jac.point_jacobian(i, &point, &mut j3).unwrap();
            jac.point_jacobian_derivative(i, &point, &mut jd3).unwrap();
            let got = &j3 * &a + &jd3 * &v;
            let w = vel.ang;
            let acc_p = acc.lin + acc.ang.cross(&point) + w.cross(&w.cross(&point));
            let expected = rot * acc_p;
            prop_assert!(rel_err(got.as_slice(), expected.as_slice()) < 1e-10, "point on {i}");

            jac.frame_jacobian(i, &point, JacobianFrame::Body, &mut j).unwrap();
            jac.frame_jacobian_derivative(i, &point, JacobianFrame::Body, &mut jd).unwrap();
            let got = &j * &a + &jd * &v;
            let lin = acc_p - w.cross(&(vel.lin + w.cross(&point)));
            let expected = [acc.ang.x, acc.ang.y, acc.ang.z, lin.x, lin.y, lin.z];
            prop_assert!(rel_err(got.as_slice(), &expected) < 1e-10, "body-frame frame on {i}");
        }
    }

    /// `J_T^p^T f` accumulated without forming `J` equals the transpose product of the matrix,
    /// and body velocities `J v` equal those of the recursion (2.33).
    #[test]
    fn transpose_product_and_velocities(seed in any::<u64>(), n in 1usize..25) {
        let model = random_model(seed, n, TreeOptions { rotors: true, ..TreeOptions::default() });
        let mut r = rng(seed ^ 0x7);
        let q = random_q(&model, &mut r);
        let v = random_vec(model.nv(), 1.0, &mut r);
        let mut data = Data::new(&model);
        let mut jac = Jacobians::new(&model);
        jac.compute(&model, &mut data, &q).unwrap();
        let mut fk = Data::new(&model);
        forward_kinematics(&model, &mut fk, &q, &v, &DVector::zeros(model.nv())).unwrap();
        let f = Vector3::new(0.7, -1.1, 0.4);
        let point = Vector3::new(0.05, 0.3, -0.2);
        let mut j3 = DMatrix::zeros(3, model.nv());
        let mut j6 = DMatrix::zeros(6, model.nv());
        for i in 0..model.nbodies() {
            jac.point_jacobian(i, &point, &mut j3).unwrap();
            let mut acc = DVector::from_element(model.nv(), 1.0);
            jac.point_jacobian_tr_mul_add(i, &point, &f, &mut acc).unwrap();
            let expected = j3.tr_mul(&DVector::from_column_slice(f.as_slice())).add_scalar(1.0);
            prop_assert!(rel_err(acc.as_slice(), expected.as_slice()) < 1e-12);
            jac.body_jacobian(i, JacobianFrame::Body, &mut j6).unwrap();
            let got = &j6 * &v;
            let vel = fk.vel[i].to_vector();
            prop_assert!(rel_err(got.as_slice(), vel.as_slice()) < 1e-12, "body {i}");
        }
    }
}

/// Columns outside the body's path to the root are exactly zero.
#[test]
fn only_ancestor_columns_are_nonzero() {
    let model = random_model(
        11,
        30,
        TreeOptions {
            rotors: true,
            ..TreeOptions::default()
        },
    );
    let q = random_q(&model, &mut rng(3));
    let mut data = Data::new(&model);
    let mut jac = Jacobians::new(&model);
    jac.compute(&model, &mut data, &q).unwrap();
    let mut j = DMatrix::zeros(6, model.nv());
    for i in 0..model.nbodies() {
        let mut on_path = vec![false; model.nv()];
        let mut b = Some(i);
        while let Some(k) = b {
            for &c in model.bodies()[k].v_set().as_slice() {
                on_path[c] = true;
            }
            b = model.bodies()[k].parent();
        }
        jac.body_jacobian(i, JacobianFrame::World, &mut j).unwrap();
        for (c, &inside) in on_path.iter().enumerate() {
            if !inside {
                assert!(j.column(c).iter().all(|&x| x == 0.0), "body {i} col {c}");
            }
        }
    }
}

/// Bad inputs give typed errors, never panics.
#[test]
fn bad_inputs_are_errors() {
    let model = random_model(5, 6, TreeOptions::default());
    let other = random_model(6, 9, TreeOptions::default());
    let q = random_q(&model, &mut rng(1));
    let nv = model.nv();
    let mut data = Data::new(&model);
    let mut jac = Jacobians::new(&model);
    let mut j6 = DMatrix::zeros(6, nv);
    let mut j3 = DMatrix::zeros(3, nv);
    assert!(matches!(
        jac.body_jacobian(0, JacobianFrame::Body, &mut j6),
        Err(JacobianError::NotComputed(_))
    ));
    jac.compute(&model, &mut data, &q).unwrap();
    assert!(matches!(
        jac.body_jacobian_derivative(0, JacobianFrame::Body, &mut j6),
        Err(JacobianError::NotComputed(_))
    ));
    assert!(matches!(
        jac.body_jacobian(99, JacobianFrame::Body, &mut j6),
        Err(JacobianError::UnknownBody { body: 99, .. })
    ));
    assert!(matches!(
        jac.body_jacobian(0, JacobianFrame::Body, &mut j3),
        Err(JacobianError::OutputShape { .. })
    ));
    assert!(matches!(
        jac.point_jacobian(0, &Vector3::new(f64::NAN, 0.0, 0.0), &mut j3),
        Err(JacobianError::NonFinitePoint)
    ));
    let mut bad_q = q.clone();
    bad_q[0] = f64::INFINITY;
    assert!(matches!(
        jac.compute(&model, &mut data, &bad_q),
        Err(JacobianError::Dynamics(_))
    ));
    let short_v = DVector::zeros(nv + 1);
    assert!(matches!(
        jac.compute_with_derivatives(&model, &mut data, &q, &short_v),
        Err(JacobianError::Dynamics(_))
    ));
    let mut other_data = Data::new(&other);
    let q_other = random_q(&other, &mut rng(2));
    assert!(matches!(
        jac.compute(&other, &mut other_data, &q_other),
        Err(JacobianError::WorkspaceMismatch { .. })
    ));
}
