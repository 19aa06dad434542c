//! Free-joint quaternion norms: a quaternion farther than `QUATERNION_NORM_TOLERANCE` from the
//! unit sphere (or non-finite, or ~zero) is a typed error naming the joint and the norm, in
//! every entry point; within the tolerance it is normalised. Norms are computed without
//! overflow, so components of 1e155 (squares beyond `f64::MAX`) are reported, not turned into
//! a zero rotation.

use biped_dynamics::configuration::QUATERNION_NORM_TOLERANCE;
use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{
    forward_dynamics, integrate, inverse_dynamics, mass_matrix, Algorithm, Data, DynamicsError,
    Model,
};
use nalgebra::{DVector, UnitQuaternion, Vector3};
use proptest::prelude::*;
use std::path::PathBuf;
use std::sync::OnceLock;

/// The G1 humanoid with a free-flyer root joint (`q[3..7]` is its quaternion), loaded once.
fn g1_floating() -> &'static Model {
    static MODEL: OnceLock<Model> = OnceLock::new();
    MODEL.get_or_init(|| {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/g1_29dof_rev_1_0.urdf");
        let opts = UrdfOptions {
            floating: true,
            ..UrdfOptions::default()
        };
        load_file(&path, &opts).unwrap().model
    })
}

/// The neutral configuration at 0.8 m height with quaternion `[qx, qy, qz, qw]`.
fn with_quaternion(model: &Model, quat: [f64; 4]) -> DVector<f64> {
    let mut q = model.neutral();
    q[2] = 0.8;
    q.rows_mut(3, 4).copy_from_slice(&quat);
    q
}

/// True if every entry is finite.
fn finite(xs: &[f64]) -> bool {
    xs.iter().all(|x| x.is_finite())
}

/// Every entry point taking `q`: forward dynamics (three algorithms), mass matrix, inverse
/// dynamics, integration. All must agree: the same error, or all `Ok` and finite; returns the
/// O(n) forward dynamics.
fn all_entry_points(model: &Model, q: &DVector<f64>) -> Result<DVector<f64>, DynamicsError> {
    let mut data = Data::new(model);
    let z = DVector::zeros(model.nv());
    let on = forward_dynamics(model, &mut data, q, &z, &z, None, Algorithm::On).cloned();
    let d = &mut data;
    let others = [
        forward_dynamics(model, d, q, &z, &z, None, Algorithm::Crba).map(|x| finite(x.as_slice())),
        forward_dynamics(model, d, q, &z, &z, None, Algorithm::Sparse)
            .map(|x| finite(x.as_slice())),
        mass_matrix(model, d, q).map(|m| finite(m.as_slice())),
        inverse_dynamics(model, d, q, &z, &z, None).map(|t| finite(t.as_slice())),
        integrate(model, q, &z, 0.0).map(|q| finite(q.as_slice())),
    ];
    for (k, other) in others.into_iter().enumerate() {
        match (&on, other) {
            (Ok(ddq), Ok(ok)) => assert!(ok && finite(ddq.as_slice()), "entry point {k}"),
            (Err(e), Err(o)) => assert_eq!(e, &o, "entry point {k}"),
            (a, b) => panic!("entry point {k} disagrees: {a:?} vs {b:?}"),
        }
    }
    on
}

/// The reported norm of a rejected quaternion (panics on any other outcome).
fn rejected_norm(model: &Model, quat: [f64; 4]) -> f64 {
    match all_entry_points(model, &with_quaternion(model, quat)) {
        Err(DynamicsError::QuaternionNorm {
            joint,
            q_index,
            norm,
            tolerance,
        }) => {
            assert_eq!((joint.as_str(), q_index), ("root", 3));
            assert_eq!(tolerance, QUATERNION_NORM_TOLERANCE);
            norm
        }
        other => panic!("{quat:?}: {other:?}"),
    }
}

#[test]
fn overflowing_quaternion_is_an_error_with_its_norm() {
    let model = g1_floating();
    // 1e155^2 = 1e310 overflows: the norm was infinite and the rotation all zeros.
    let norm = rejected_norm(model, [0.0, 0.0, 0.0, 1e155]);
    assert!((norm / 1e155 - 1.0).abs() < 1e-15, "{norm}");
    let norm = rejected_norm(model, [1e300, -1e300, 1e300, 1e300]);
    assert!((norm / 2e300 - 1.0).abs() < 1e-15, "{norm}");
    let e = all_entry_points(model, &with_quaternion(model, [0.0, 0.0, 0.0, 1e155]));
    let msg = e.unwrap_err().to_string();
    assert!(msg.contains("`root`") && msg.contains("1e155"), "{msg}");
}

#[test]
fn unnormalised_quaternion_is_an_error() {
    let model = g1_floating();
    assert_eq!(rejected_norm(model, [0.0, 0.0, 0.0, 2.0]), 2.0);
    assert_eq!(rejected_norm(model, [0.0, 0.0, 0.0, 0.5]), 0.5);
    assert_eq!(rejected_norm(model, [0.5, 0.5, 0.5, 0.5 * 1.1]), {
        let w: f64 = 0.5 * 1.1;
        (0.75 + w * w).sqrt()
    });
}

#[test]
fn near_zero_and_nan_quaternions_are_errors() {
    let model = g1_floating();
    for quat in [
        [0.0; 4],
        [0.0, 0.0, 0.0, 1e-13],
        [1e-300, 0.0, -1e-300, 1e-300],
    ] {
        let r = all_entry_points(model, &with_quaternion(model, quat));
        assert_eq!(
            r,
            Err(DynamicsError::ZeroQuaternion { q_index: 3 }),
            "{quat:?}"
        );
    }
    // Small but not zero: a norm error that reports the norm.
    let norm = rejected_norm(model, [0.0, 1e-6, 0.0, 0.0]);
    assert!((norm / 1e-6 - 1.0).abs() < 1e-15, "{norm}");
    for (i, bad) in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY]
        .into_iter()
        .enumerate()
    {
        let mut quat = [0.0, 0.0, 0.0, 1.0];
        quat[i] = bad;
        let r = all_entry_points(model, &with_quaternion(model, quat));
        let expected = DynamicsError::NonFinite {
            argument: "q",
            index: 3 + i,
        };
        assert_eq!(r, Err(expected), "{quat:?}");
    }
}

#[test]
fn quaternion_within_tolerance_is_normalised() {
    let model = g1_floating();
    let unit = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 0.4);
    let c = unit.quaternion().coords; // [x, y, z, w]
    let exact = all_entry_points(model, &with_quaternion(model, [c.x, c.y, c.z, c.w])).unwrap();
    for s in [
        1.0 - 0.9 * QUATERNION_NORM_TOLERANCE,
        1.0 + 0.9 * QUATERNION_NORM_TOLERANCE,
    ] {
        let quat = [c.x * s, c.y * s, c.z * s, c.w * s];
        let ddq = all_entry_points(model, &with_quaternion(model, quat)).unwrap();
        assert!((&ddq - &exact).amax() < 1e-12 * exact.amax(), "scale {s}");
    }
    for s in [
        1.0 - 1.1 * QUATERNION_NORM_TOLERANCE,
        1.0 + 1.1 * QUATERNION_NORM_TOLERANCE,
    ] {
        let norm = rejected_norm(model, [c.x * s, c.y * s, c.z * s, c.w * s]);
        assert!((norm - s).abs() < 1e-15, "{norm} vs {s}");
    }
}

/// Number of generated quaternions of the property test.
const CASES: u32 = 256;

/// A component `sign * 10^e` with `e` uniform in [-300, 300], or zero.
fn component() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        6 => (any::<bool>(), -300.0f64..300.0)
            .prop_map(|(neg, e)| if neg { -(10f64.powf(e)) } else { 10f64.powf(e) }),
    ]
}

/// Quaternions of any magnitude in [1e-300, 1e300] per component, and unit quaternions
/// scaled by up to twice the tolerance (both sides of the boundary).
fn quaternion() -> impl Strategy<Value = [f64; 4]> {
    let any_size = [component(), component(), component(), component()];
    let near_unit = (
        prop::array::uniform4(-1.0f64..1.0),
        -2.0 * QUATERNION_NORM_TOLERANCE..2.0 * QUATERNION_NORM_TOLERANCE,
    )
        .prop_filter("direction", |(d, _)| d.iter().any(|x| x.abs() > 1e-3))
        .prop_map(|(d, e)| {
            let n = d.iter().map(|x| x * x).sum::<f64>().sqrt();
            d.map(|x| x / n * (1.0 + e))
        });
    prop_oneof![any_size, near_unit]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    /// Any quaternion gives a clear error or finite dynamics: `Ok` exactly when its norm
    /// (computed independently with `hypot`) is within the tolerance, the reported norm matches.
    #[test]
    fn any_quaternion_gives_an_error_or_finite_dynamics(quat in quaternion()) {
        let model = g1_floating();
        let norm = quat[0].hypot(quat[1]).hypot(quat[2]).hypot(quat[3]);
        let inside = (norm - 1.0).abs() <= QUATERNION_NORM_TOLERANCE;
        // Within 1e-12 of the boundary the two norm computations may round differently.
        let boundary = ((norm - 1.0).abs() - QUATERNION_NORM_TOLERANCE).abs() < 1e-12;
        match all_entry_points(model, &with_quaternion(model, quat)) {
            Ok(ddq) => {
                prop_assert!(inside || boundary, "{quat:?}: norm {norm} accepted");
                prop_assert!(ddq.iter().all(|x| x.is_finite()));
            }
            Err(DynamicsError::QuaternionNorm { norm: reported, .. }) => {
                prop_assert!(!inside || boundary, "{quat:?}: norm {norm} rejected");
                prop_assert!((reported / norm - 1.0).abs() < 1e-14, "{reported} vs {norm}");
            }
            Err(DynamicsError::ZeroQuaternion { .. }) => prop_assert!(norm <= 1e-12, "{norm}"),
            Err(e) => prop_assert!(false, "{quat:?}: unexpected {e}"),
        }
    }
}
