//! Spin (motor) rows of coupled parts read back from the loop caches
//! ([`Data::coupled_spin_row`]) on a two-legged model with knee screws and ankle slider-cranks:
//! equal to the jet reference with a warm cache, a cold cache and a stale cache (another `q`),
//! equal to finite differences of the motor angles (3.3), (3.22), and O(n) forward dynamics
//! through the fast mechanism path agrees with CRBA and the sparse factorisation.

use biped_dynamics::mechanism::ankle::{AnkleDrive, AnkleDriveParams, AnklePart};
use biped_dynamics::mechanism::knee::{KneeDrive, KneeDriveParams, KneePart};
use biped_dynamics::mechanism::{Coupling, MAX_COUPLED};
use biped_dynamics::model::Mechanism;
use biped_dynamics::{
    forward_dynamics, Algorithm, Body, BodyId, BodySpec, Data, JointModel, Model, ModelBuilder,
    RigidInertia,
};
use nalgebra::{DVector, Isometry3, Matrix3, Translation3, Vector3};
use proptest::prelude::*;

fn inertia(m: f64) -> RigidInertia {
    let c = Vector3::new(0.01, -0.02, -0.05);
    RigidInertia::new(
        m,
        c,
        Matrix3::from_diagonal(&Vector3::new(0.02, 0.03, 0.01)) * m,
    )
    .unwrap()
}

fn add(b: &mut ModelBuilder, name: &str, parent: Option<BodyId>, joint: JointModel) -> BodyId {
    let (placement, m) = match joint {
        JointModel::Coupled { .. } => (Isometry3::identity(), 0.3),
        _ => (
            Isometry3::from_parts(Translation3::new(0.0, 0.0, -0.2), Default::default()),
            2.0,
        ),
    };
    b.add_body(BodySpec::named(name, parent, joint, placement, inertia(m)))
        .unwrap()
}

fn revolute(axis: Vector3<f64>) -> JointModel {
    JointModel::Revolute {
        axis: nalgebra::Unit::new_normalize(axis),
    }
}

/// Free base with two legs: thigh, knee (about z) with housing/nut/rotor, shank, ankle
/// flexion (y) and adduction (x) with two slider-cranks (nut/rotor/rod each).
fn legs() -> (Model, Vec<BodyId>) {
    let knee = KneeDrive::new(KneeDriveParams::default()).unwrap();
    let ankle = AnkleDrive::new(AnkleDriveParams::default()).unwrap();
    let mut b = ModelBuilder::new();
    let base = add(&mut b, "base", None, JointModel::FreeQuaternion);
    let mut coupled = Vec::new();
    for leg in ["l", "r"] {
        let thigh = add(
            &mut b,
            &format!("{leg}thigh"),
            Some(base),
            revolute(Vector3::y()),
        );
        let shank = add(
            &mut b,
            &format!("{leg}knee"),
            Some(thigh),
            revolute(Vector3::z()),
        );
        for part in [KneePart::Housing, KneePart::Nut, KneePart::Rotor] {
            let joint = JointModel::Coupled {
                mechanism: Mechanism::Knee(knee.part(part)),
                inputs: vec![shank],
            };
            coupled.push(add(
                &mut b,
                &format!("{leg}knee{part:?}"),
                Some(thigh),
                joint,
            ));
        }
        let flx = add(
            &mut b,
            &format!("{leg}flx"),
            Some(shank),
            revolute(Vector3::y()),
        );
        let add_ = add(
            &mut b,
            &format!("{leg}add"),
            Some(flx),
            revolute(Vector3::x()),
        );
        for act in 0..2 {
            for part in [AnklePart::Nut, AnklePart::Rotor, AnklePart::Rod] {
                let joint = JointModel::Coupled {
                    mechanism: Mechanism::Ankle(ankle.part(act, part).unwrap()),
                    inputs: vec![flx, add_],
                };
                let name = format!("{leg}ankle{act}{part:?}");
                coupled.push(add(&mut b, &name, Some(shank), joint));
            }
        }
    }
    (b.build().unwrap(), coupled)
}

/// Vector of length `len` holding `vals` at the `[thigh, knee, flexion, adduction]` joints of
/// both legs (`index` picks the q or v index), the rest zero.
fn joints(model: &Model, vals: &[f64; 8], len: usize, index: fn(&Body) -> usize) -> DVector<f64> {
    let mut x = DVector::zeros(len);
    let names = ["thigh", "knee", "flx", "add"];
    for (k, a) in vals.iter().enumerate() {
        let name = format!("{}{}", ["l", "r"][k / 4], names[k % 4]);
        x[index(model.body(model.body_id(&name).unwrap()).unwrap())] = *a;
    }
    x
}

/// `q` from the joint angles, base at rest (quaternion x, y, z, w at q[3..7]).
fn state(model: &Model, angles: &[f64; 8]) -> DVector<f64> {
    let mut q = joints(model, angles, model.nq(), Body::q_index);
    q[6] = 1.0;
    q
}

/// The jet reference: z row of the part's relative Jacobian.
fn reference_row(model: &Model, body: BodyId, q: &DVector<f64>) -> [f64; MAX_COUPLED] {
    let b = model.body(body).unwrap();
    let JointModel::Coupled { mechanism, .. } = b.joint() else {
        panic!("not coupled")
    };
    let qin: Vec<f64> = b.q_set().as_slice().iter().map(|&k| q[k]).collect();
    let m = mechanism.motion(&qin, &vec![0.0; qin.len()]).unwrap();
    std::array::from_fn(|k| m.jacobian[k][2])
}

/// Motor angle of a rotor part, for the finite-difference check (3.3), (3.22).
fn motor_angle(model: &Model, body: BodyId, q: &DVector<f64>) -> Option<f64> {
    let b = model.body(body).unwrap();
    let qin: Vec<f64> = b.q_set().as_slice().iter().map(|&k| q[k]).collect();
    match b.joint() {
        JointModel::Coupled {
            mechanism: Mechanism::Knee(k),
            ..
        } if k.part == KneePart::Rotor => Some(k.drive.motor_angle(qin[0]).unwrap()),
        JointModel::Coupled {
            mechanism: Mechanism::Ankle(_),
            ..
        } if b.name().contains("Rotor") => {
            let drive = AnkleDrive::new(AnkleDriveParams::default()).unwrap();
            let t = drive.transmission([qin[0], qin[1]], [0.0; 2]).unwrap();
            Some(t.motor_angles[usize::from(b.name().contains("ankle1"))])
        }
        _ => None,
    }
}

fn close(a: &[f64; MAX_COUPLED], b: &[f64; MAX_COUPLED], tol: f64) -> bool {
    a.iter()
        .zip(b)
        .all(|(x, y)| (x - y).abs() <= tol * (1.0 + y.abs()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn spin_rows_match_reference_and_finite_differences(
        legs_a in prop::array::uniform8(0.0..1.0f64),
        legs_b in prop::array::uniform8(0.0..1.0f64),
        vel in prop::array::uniform8(-2.0..2.0f64),
    ) {
        let (model, coupled) = legs();
        let map = |u: [f64; 8]| -> [f64; 8] {
            let lo = [-1.0, -0.05, -0.5, -0.25];
            let hi = [1.0, 2.0, 0.4, 0.25];
            std::array::from_fn(|k| lo[k % 4] + (hi[k % 4] - lo[k % 4]) * u[k])
        };
        let (qa, qb) = (state(&model, &map(legs_a)), state(&model, &map(legs_b)));
        let v = joints(&model, &vel, model.nv(), Body::v_index);
        let dq = joints(&model, &vel, model.nq(), Body::q_index);
        let tau = DVector::from_element(model.nv(), 0.5);
        let mut data = Data::new(&model);
        let cold = Data::new(&model);
        let on = forward_dynamics(&model, &mut data, &qa, &v, &tau, None, Algorithm::On)
            .unwrap().clone();
        for &body in &coupled {
            let want = reference_row(&model, body, &qa);
            let warm = data.coupled_spin_row(&model, body, qa.as_slice()).unwrap();
            let fresh = cold.coupled_spin_row(&model, body, qa.as_slice()).unwrap();
            prop_assert!(close(&warm, &want, 1e-12), "{warm:?} vs {want:?}");
            prop_assert_eq!(warm, fresh);
            let stale = data.coupled_spin_row(&model, body, qb.as_slice()).unwrap();
            prop_assert!(close(&stale, &reference_row(&model, body, &qb), 1e-12));
            if motor_angle(&model, body, &qa).is_some() {
                let h = 1e-6;
                let at = |t: f64| motor_angle(&model, body, &(&qa + &dq * t)).unwrap();
                let fd = (at(h) - at(-h)) / (2.0 * h);
                let set = model.body(body).unwrap().v_set().as_slice().to_vec();
                let rate: f64 = set.iter().zip(&warm).map(|(&k, r)| r * v[k]).sum();
                prop_assert!((rate - fd).abs() < 1e-5 * (1.0 + fd.abs()), "{rate} vs {fd}");
            }
        }
        for algo in [Algorithm::Crba, Algorithm::Sparse] {
            let other = forward_dynamics(&model, &mut data, &qa, &v, &tau, None, algo).unwrap();
            let diff = (&on - other).amax() / (1.0 + other.amax());
            prop_assert!(diff < 1e-9, "O(n) vs {algo:?}: {diff:e}");
        }
    }
}

#[test]
fn spin_row_rejects_bad_requests() {
    let (model, coupled) = legs();
    let data = Data::new(&model);
    let q = state(&model, &[0.0; 8]);
    assert!(data.coupled_spin_row(&model, 0, q.as_slice()).is_err());
    assert!(data.coupled_spin_row(&model, 999, q.as_slice()).is_err());
    assert!(data
        .coupled_spin_row(&model, coupled[0], &q.as_slice()[..3])
        .is_err());
    let mut bad = q.clone();
    bad.iter_mut().skip(7).for_each(|x| *x = f64::NAN);
    assert!(data
        .coupled_spin_row(&model, coupled[0], bad.as_slice())
        .is_err());
}
