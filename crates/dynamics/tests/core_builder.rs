//! Builder and input validation: every invalid input is a typed error, never a panic.

mod core_support;

use biped_dynamics::{
    forward_dynamics, inverse_dynamics, mass_matrix, Algorithm, BodySpec, Data, DynamicsError,
    Force, JointModel, ModelBuilder, ModelError, RigidInertia,
};
use core_support::*;
use nalgebra::{DVector, Isometry3, Matrix3, Translation3, Unit, UnitQuaternion, Vector3};

fn unit_inertia() -> RigidInertia {
    RigidInertia::new(1.0, Vector3::new(0.1, 0.0, 0.0), Matrix3::identity() * 0.01).unwrap()
}

fn spec(name: &str, parent: Option<usize>, joint: JointModel) -> BodySpec {
    BodySpec {
        name: name.into(),
        joint_name: format!("j_{name}"),
        parent,
        joint,
        placement: Isometry3::translation(0.0, 0.0, 0.3),
        inertia: unit_inertia(),
    }
}

fn revolute() -> JointModel {
    JointModel::Revolute {
        axis: Vector3::z_axis(),
    }
}

#[test]
fn inertia_validation() {
    let i = Matrix3::identity();
    assert_eq!(
        RigidInertia::new(-1.0, Vector3::zeros(), i),
        Err(ModelError::NegativeMass { mass: -1.0 })
    );
    assert_eq!(
        RigidInertia::new(f64::NAN, Vector3::zeros(), i),
        Err(ModelError::NonFiniteInertia)
    );
    assert_eq!(
        RigidInertia::new(1.0, Vector3::new(f64::INFINITY, 0.0, 0.0), i),
        Err(ModelError::NonFiniteInertia)
    );
    let mut asym = i;
    asym[(0, 1)] = 0.5;
    assert!(matches!(
        RigidInertia::new(1.0, Vector3::zeros(), asym),
        Err(ModelError::InertiaNotSymmetric { .. })
    ));
    let neg = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -0.1));
    assert!(matches!(
        RigidInertia::new(1.0, Vector3::zeros(), neg),
        Err(ModelError::InertiaNotPositive { .. })
    ));
    let tri = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 2.5));
    assert!(matches!(
        RigidInertia::new(1.0, Vector3::zeros(), tri),
        Err(ModelError::TriangleInequality { .. })
    ));
    // Thin rod: I1 + I2 = I3 exactly at the boundary is accepted; so are point masses.
    assert!(RigidInertia::new(
        1.0,
        Vector3::zeros(),
        Matrix3::from_diagonal(&Vector3::new(0.0, 1.0, 1.0))
    )
    .is_ok());
    assert!(RigidInertia::new(1.0, Vector3::zeros(), Matrix3::zeros()).is_ok());
}

#[test]
fn topology_and_name_errors() {
    let mut b = ModelBuilder::new();
    assert!(matches!(
        b.add_body(spec("a", Some(0), revolute())),
        Err(ModelError::CyclicParent { .. })
    ));
    assert!(matches!(
        b.add_body(spec("a", Some(3), revolute())),
        Err(ModelError::UnknownParent { parent: 3, .. })
    ));
    b.add_body(spec("a", None, revolute())).unwrap();
    assert_eq!(
        b.add_body(spec("a", Some(0), revolute())),
        Err(ModelError::DuplicateBodyName("a".into()))
    );
    let mut s = spec("b", Some(0), revolute());
    s.joint_name = "j_a".into();
    assert_eq!(
        b.add_body(s),
        Err(ModelError::DuplicateJointName("j_a".into()))
    );
    let mut s = spec("b", Some(0), revolute());
    s.placement = Isometry3::translation(f64::NAN, 0.0, 0.0);
    assert!(matches!(
        b.add_body(s),
        Err(ModelError::NonFinitePlacement { .. })
    ));
    let zero = JointModel::Prismatic {
        axis: Unit::new_unchecked(Vector3::zeros()),
    };
    assert!(matches!(
        b.add_body(spec("b", Some(0), zero)),
        Err(ModelError::ZeroAxis { .. })
    ));
    // The failed attempts left the builder usable.
    assert_eq!(b.add_body(spec("b", Some(0), revolute())), Ok(1));
    let model = b.build().unwrap();
    assert_eq!(model.nv(), 2);
    assert_eq!(model.bodies()[0].first_child(), Some(1));
}

#[test]
fn rotor_errors() {
    let mut b = ModelBuilder::new();
    let base = b.add_body(spec("base", None, revolute())).unwrap();
    let fixed = b
        .add_body(spec("plate", Some(base), JointModel::Fixed))
        .unwrap();
    let left = b.add_body(spec("left", Some(base), revolute())).unwrap();
    let right = b.add_body(spec("right", Some(base), revolute())).unwrap();
    let rotor = |driver, ratio| JointModel::GearedRotor {
        axis: Vector3::z_axis(),
        ratio,
        driver,
    };
    let err = b
        .add_body(spec("r0", Some(base), rotor(9, 100.0)))
        .unwrap_err();
    assert!(matches!(err, ModelError::BadDriver { driver: 9, .. }));
    let err = b
        .add_body(spec("r1", Some(base), rotor(fixed, 100.0)))
        .unwrap_err();
    assert!(matches!(err, ModelError::BadDriver { .. }));
    let err = b
        .add_body(spec("r2", Some(base), rotor(left, 0.0)))
        .unwrap_err();
    assert!(matches!(err, ModelError::InvalidGearRatio { .. }));
    // Rotor on `left` driven by its sibling `right`: the coordinates are not on one path.
    let err = b
        .add_body(spec("r3", Some(left), rotor(right, 50.0)))
        .unwrap_err();
    assert!(matches!(err, ModelError::BadDriver { .. }));
    // Valid: on the parent, driving a child joint; and on the driven body itself.
    let r = b
        .add_body(spec("r4", Some(base), rotor(left, 50.0)))
        .unwrap();
    b.add_body(spec("r5", Some(right), rotor(right, -30.0)))
        .unwrap();
    let err = b.add_body(spec("c", Some(r), revolute())).unwrap_err();
    assert!(matches!(err, ModelError::ChildOfRotor { .. }));
    let mut b2 = b.clone();
    b2.set_gravity(Vector3::new(0.0, f64::NAN, 0.0));
    assert_eq!(b2.build().unwrap_err(), ModelError::NonFiniteGravity);
    let model = b.build().unwrap();
    assert_eq!(model.nv(), 3);
    assert!(model.has_rotors());
    // A rotor's index set (2.26) is its driver's: shared, not owned.
    let bodies = model.bodies();
    assert_eq!(
        bodies[r].v_set().as_slice(),
        bodies[left].v_set().as_slice()
    );
    assert!(!bodies[r].owns_coordinates() && bodies[left].owns_coordinates());
    assert!(bodies[fixed].v_set().is_empty());
    assert_eq!(bodies[0].first_child(), Some(fixed));
    assert_eq!(bodies[fixed].brother(), Some(left));
    // O(n) handles the rotor through an automatically generated sub-system (2.9).
    let mut data = Data::new(&model);
    let z = DVector::zeros(3);
    assert!(forward_dynamics(&model, &mut data, &z, &z, &z, None, Algorithm::On).is_ok());
    assert!(forward_dynamics(&model, &mut data, &z, &z, &z, None, Algorithm::Sparse).is_ok());
}

#[test]
fn dynamics_input_errors() {
    let model = random_model(
        11,
        6,
        TreeOptions {
            root: 0,
            ..TreeOptions::default()
        },
    );
    let mut data = Data::new(&model);
    let q = model.neutral();
    let v = DVector::zeros(model.nv());
    let short = DVector::zeros(model.nv() - 1);
    for algo in [Algorithm::On, Algorithm::Crba, Algorithm::Sparse] {
        let e = forward_dynamics(&model, &mut data, &q, &short, &v, None, algo).unwrap_err();
        assert_eq!(
            e,
            DynamicsError::DimensionMismatch {
                argument: "v",
                expected: model.nv(),
                got: model.nv() - 1
            }
        );
        let e = forward_dynamics(&model, &mut data, &q, &v, &short, None, algo).unwrap_err();
        assert!(matches!(
            e,
            DynamicsError::DimensionMismatch {
                argument: "tau",
                ..
            }
        ));
        let mut bad = v.clone();
        bad[2] = f64::NAN;
        let e = forward_dynamics(&model, &mut data, &q, &bad, &v, None, algo).unwrap_err();
        assert_eq!(
            e,
            DynamicsError::NonFinite {
                argument: "v",
                index: 2
            }
        );
        let mut zq = q.clone();
        zq.rows_mut(3, 4).fill(0.0);
        let e = forward_dynamics(&model, &mut data, &zq, &v, &v, None, algo).unwrap_err();
        assert_eq!(e, DynamicsError::ZeroQuaternion { q_index: 3 });
        let few = vec![Force::zero(); 2];
        let e = forward_dynamics(&model, &mut data, &q, &v, &v, Some(&few), algo).unwrap_err();
        assert!(matches!(
            e,
            DynamicsError::DimensionMismatch {
                argument: "fext",
                ..
            }
        ));
        let mut nan = vec![Force::zero(); model.nbodies()];
        nan[4].lin.x = f64::INFINITY;
        let e = forward_dynamics(&model, &mut data, &q, &v, &v, Some(&nan), algo).unwrap_err();
        assert_eq!(
            e,
            DynamicsError::NonFinite {
                argument: "fext",
                index: 4
            }
        );
    }
    assert!(matches!(
        mass_matrix(&model, &mut data, &short),
        Err(DynamicsError::DimensionMismatch { argument: "q", .. })
    ));
    assert!(matches!(
        inverse_dynamics(&model, &mut data, &q, &v, &short, None),
        Err(DynamicsError::DimensionMismatch { argument: "a", .. })
    ));
    let other = random_model(12, 3, TreeOptions::default());
    let mut wrong = Data::new(&other);
    assert!(matches!(
        mass_matrix(&model, &mut wrong, &q),
        Err(DynamicsError::DimensionMismatch { .. })
    ));
}

/// Euler ZXZ at theta = 0 is singular: reported as not positive definite, never NaN.
#[test]
fn euler_singularity_is_an_error() {
    let mut b = ModelBuilder::new();
    b.add_body(spec("free", None, JointModel::FreeEulerZxz))
        .unwrap();
    let model = b.build().unwrap();
    let mut data = Data::new(&model);
    let z = DVector::zeros(6);
    for algo in [Algorithm::On, Algorithm::Crba, Algorithm::Sparse] {
        let e = forward_dynamics(&model, &mut data, &z, &z, &z, None, algo).unwrap_err();
        assert!(
            matches!(e, DynamicsError::NotPositiveDefinite { .. }),
            "{algo:?}: {e:?}"
        );
    }
}

/// `merged` equals the sum of the two dense spatial inertias expressed in the first frame.
#[test]
fn merged_inertia_is_the_sum() {
    let mut r = rng(4);
    for _ in 0..20 {
        let a = random_inertia(&mut r);
        let b = random_inertia(&mut r);
        let pose = Isometry3::from_parts(
            Translation3::new(0.3, -0.2, 0.1),
            UnitQuaternion::from_euler_angles(0.3, -1.0, 2.0),
        );
        let m = a.merged(&b, &pose);
        // Spatial transform from the frame of b to the frame of a: C = C_{b a}.
        let x = biped_dynamics::SpatialTransform::from_pose(&pose).to_matrix();
        let dense = a.to_matrix() + x.transpose() * b.to_matrix() * x;
        assert!((m.to_matrix() - dense).amax() < 1e-12);
        assert!((m.mass() - a.mass() - b.mass()).abs() < 1e-12);
    }
}

/// Coordinate names: one per coordinate, distinct, joint names for one-DoF joints and the
/// quaternion free joint's components by letter (checked on the G1 against its URDF).
#[test]
fn coordinate_names_follow_the_joints() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/g1_29dof_rev_1_0.urdf");
    let opts = biped_dynamics::urdf::UrdfOptions {
        floating: true,
        ..Default::default()
    };
    let model = biped_dynamics::urdf::load_file(path, &opts).unwrap().model;
    let (q, v) = (model.q_names(), model.v_names());
    assert_eq!((q.len(), v.len()), (model.nq(), model.nv()));
    assert_eq!(
        &q[..8],
        [
            "root.x",
            "root.y",
            "root.z",
            "root.qx",
            "root.qy",
            "root.qz",
            "root.qw",
            "left_hip_pitch_joint"
        ]
    );
    assert_eq!(
        &v[..7],
        [
            "root.vx",
            "root.vy",
            "root.vz",
            "root.wx",
            "root.wy",
            "root.wz",
            "left_hip_pitch_joint"
        ]
    );
    let text = std::fs::read_to_string(path).unwrap();
    for name in &q[7..] {
        assert!(
            text.contains(&format!("<joint name=\"{name}\"")),
            "{name} is a URDF joint"
        );
    }
    let distinct: std::collections::HashSet<&String> = q.iter().collect();
    assert_eq!(distinct.len(), q.len());
}
