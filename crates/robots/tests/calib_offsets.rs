//! Encoder-offset calibration on synthetic G1 jig data (thesis 3.5): exact recovery, noise
//! scaling, observability, geometric-error detection, Jacobian vs finite differences.

mod calib_support;

use biped_robots::calibration::{calibrate, CalibrationError, Components, SolveOptions};
use calib_support::*;
use nalgebra::{DMatrix, DVector};

fn synthetic(poses: usize, noise: f64, seed: u64) -> Synthetic {
    Synthetic {
        joints: leg_names(),
        offsets: random_offsets(12, seed + 1000),
        noise,
        poses,
        seed,
    }
}

#[test]
fn recovers_offsets_exactly_without_noise() {
    let g1 = load(&g1_xml());
    for poses in [1, 3] {
        let s = synthetic(poses, 0.0, 7);
        let p = problem(&g1, &g1, &s, Components::Pose);
        let c = calibrate(&p, &SolveOptions::default()).unwrap();
        let err = (&c.offsets - &s.offsets).amax();
        assert!(err < 1e-9, "{poses} poses: offset error {err:e}");
        assert!(c.rms_after < 1e-10, "rms after {:e}", c.rms_after);
        for r in &c.poses {
            assert!(r.rms_before > 1e-3 && r.max_after < 1e-10, "{r:?}");
        }
    }
}

/// Linearised standard deviation of each offset estimate for encoder noise `sigma` on the
/// calibrated joints: `Cov = sigma^2 H^-1 (sum_p H_p^2) H^-1`, `H_p = J_p^T J_p`, `H = sum H_p`
/// (noise enters pose `p` through the same columns as the offsets).
fn predicted_std(j: &DMatrix<f64>, rows_per_pose: usize, sigma: f64) -> DVector<f64> {
    let k = j.ncols();
    let h = j.tr_mul(j);
    let mut s = DMatrix::zeros(k, k);
    for p in 0..j.nrows() / rows_per_pose {
        let jp = j.rows(p * rows_per_pose, rows_per_pose);
        let hp = jp.tr_mul(&jp);
        s += &hp * &hp;
    }
    let hi = h.try_inverse().unwrap();
    let cov = &hi * s * &hi * (sigma * sigma);
    DVector::from_fn(k, |i, _| cov[(i, i)].sqrt())
}

#[test]
fn noisy_offsets_within_noise_derived_tolerance() {
    let g1 = load(&g1_xml());
    let sigma = 1e-3;
    for poses in [1, 2, 6] {
        let s = synthetic(poses, sigma, 11);
        let p = problem(&g1, &g1, &s, Components::Pose);
        let c = calibrate(&p, &SolveOptions::default()).unwrap();
        let err = &c.offsets - &s.offsets;
        let (_, j) = p.residual_jacobian(&c.offsets).unwrap();
        let std = predicted_std(&j, 12, sigma);
        for i in 0..12 {
            assert!(
                err[i].abs() < 5.0 * std[i],
                "{poses} poses, joint {i}: {:e} vs std {:e}",
                err[i],
                std[i]
            );
        }
        if poses == 1 {
            // One pose, 12 equations: the offsets absorb the noise exactly (std = sigma).
            assert!((std.amax() - sigma).abs() < 1e-9 && (std.min() - sigma).abs() < 1e-9);
        }
    }
}

/// Mean squared offset error over seeds, and the mean predicted variance.
fn mean_error(g1: &biped_dynamics::urdf::UrdfModel, poses: usize, sigma: f64) -> (f64, f64) {
    let (mut e2, mut v) = (0.0, 0.0);
    for seed in 0..6 {
        let s = synthetic(poses, sigma, 100 + seed);
        let p = problem(g1, g1, &s, Components::Pose);
        let c = calibrate(&p, &SolveOptions::default()).unwrap();
        e2 += (&c.offsets - &s.offsets).norm_squared() / 72.0;
        let (_, j) = p.residual_jacobian(&c.offsets).unwrap();
        v += predicted_std(&j, 12, sigma).norm_squared() / 72.0;
    }
    (e2.sqrt(), v.sqrt())
}

/// The unweighted Cartesian least squares averages poses by their `J_p^T J_p`, not uniformly,
/// so 12 poses gain less than `1/sqrt(12)` (the prediction says how much; measured ~0.57).
#[test]
fn more_poses_reduce_the_error() {
    let g1 = load(&g1_xml());
    let sigma = 2e-3;
    let (few, few_pred) = mean_error(&g1, 1, sigma);
    let (many, many_pred) = mean_error(&g1, 12, sigma);
    eprintln!("rms offset error: 1 pose {few:e} (pred {few_pred:e}), 12 poses {many:e} (pred {many_pred:e})");
    assert!(many < 0.75 * few, "1 pose {few:e}, 12 poses {many:e}");
    assert!(many_pred < 0.75 * few_pred);
    assert!(many < 2.0 * many_pred && few < 2.0 * few_pred);
}

#[test]
fn unobservable_joints_are_reported() {
    let g1 = load(&g1_xml());
    let mut s = synthetic(2, 0.0, 3);
    s.joints.push("waist_yaw_joint".into());
    s.joints.push("left_elbow_joint".into());
    s.offsets = random_offsets(14, 5);
    let p = problem(&g1, &g1, &s, Components::Pose);
    match calibrate(&p, &SolveOptions::default()) {
        Err(CalibrationError::Unobservable { joints, .. }) => {
            assert!(
                joints.contains(&"left_elbow_joint".to_string()),
                "{joints:?}"
            );
        }
        other => panic!("expected Unobservable, got {other:?}"),
    }
    // Waist joints move the pelvis-fixed frames of nothing here (pelvis is the root): their
    // columns vanish too once the elbow is removed.
    s.joints.pop();
    s.offsets = random_offsets(13, 5);
    let p = problem(&g1, &g1, &s, Components::Pose);
    match calibrate(&p, &SolveOptions::default()) {
        Err(CalibrationError::Unobservable { joints, .. }) => {
            assert_eq!(joints, vec!["waist_yaw_joint".to_string()]);
        }
        other => panic!("expected Unobservable, got {other:?}"),
    }
    // Position-only jig, one pose: 6 rows for 12 unknowns.
    let s = synthetic(1, 0.0, 3);
    let p = problem(&g1, &g1, &s, Components::Position);
    assert!(matches!(
        calibrate(&p, &SolveOptions::default()),
        Err(CalibrationError::Unobservable { unknowns: 12, .. })
    ));
}

#[test]
fn wrong_link_length_leaves_a_structured_residual() {
    let xml = g1_xml();
    let nominal = load(&xml);
    let long = xml.replace(
        "xyz=\"-0.078273 0.0021489 -0.17734\"",
        "xyz=\"-0.078273 0.0021489 -0.18234\"",
    );
    assert_ne!(long, xml, "left knee origin found");
    let truth = load(&long);
    let sigma = 1e-5;
    let s = synthetic(4, sigma, 21);
    let good = calibrate(
        &problem(&nominal, &nominal, &s, Components::Pose),
        &SolveOptions::default(),
    )
    .unwrap();
    let bad = calibrate(
        &problem(&truth, &nominal, &s, Components::Pose),
        &SolveOptions::default(),
    )
    .unwrap();
    // The noise-only fit leaves a residual of order sigma times the weights; a 5 mm thigh
    // error cannot be absorbed by the offsets and stays far above it.
    assert!(
        bad.rms_after > 20.0 * good.rms_after,
        "bad {:e} good {:e}",
        bad.rms_after,
        good.rms_after
    );
    let left_mm: f64 = bad
        .poses
        .iter()
        .map(|r| r.constraints[0].position_after)
        .fold(0.0, f64::max);
    assert!(
        left_mm > 2e-4,
        "left foot closure after calibration {left_mm:e} m"
    );
    // Structured: the error sits in the left leg; the right leg's closure stays at noise level.
    let right_mm: f64 = bad
        .poses
        .iter()
        .map(|r| r.constraints[1].position_after)
        .fold(0.0, f64::max);
    eprintln!(
        "wrong thigh: rms {:e} vs {:e}; left {left_mm:e} m, right {right_mm:e} m",
        bad.rms_after, good.rms_after
    );
    assert!(right_mm < 0.05 * left_mm, "right foot {right_mm:e} m");
}

#[test]
fn residual_jacobian_matches_central_differences() {
    let g1 = load(&g1_xml());
    for comp in [Components::Pose, Components::Position] {
        let s = synthetic(2, 1e-3, 9);
        let p = problem(&g1, &g1, &s, comp);
        let x = random_offsets(12, 77);
        let (_, j) = p.residual_jacobian(&x).unwrap();
        let h = 1e-6;
        for c in 0..12 {
            let mut xp = x.clone();
            let mut xm = x.clone();
            xp[c] += h;
            xm[c] -= h;
            let fd: DVector<f64> =
                (p.residual(&xp).unwrap() - p.residual(&xm).unwrap()) / (2.0 * h);
            let e = (&fd - j.column(c)).amax();
            assert!(e < 1e-6 * (1.0 + fd.amax()), "column {c}: {e:e}");
        }
    }
}
