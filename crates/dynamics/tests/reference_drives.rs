//! The reference O(n) algorithm (`dynamics::reference`) on the knee and ankle drives of chapter
//! 3 inside the dynamics crate: the members the fast path treats as axial screw rotors and
//! nuts, as a carrier with riders, or generally, against O(n), CRBA and sparse LTL. Legs as in
//! `loop_screw_rotor.rs`: a floating shank with the ankle's two slider-cranks, and a floating
//! thigh with the knee's roller screw (tilting or not).

mod loop_support;
mod reference_support;

use biped_dynamics::dynamics::reference::kinds::{fast_member_kinds, MemberKind};
use biped_dynamics::mechanism::ankle::{AnkleDrive, AnkleDriveParams, AnklePart};
use biped_dynamics::mechanism::knee::{KneeDrive, KneeDriveParams, KneePart};
use biped_dynamics::model::Mechanism;
use biped_dynamics::{JointModel, Model, ModelBuilder, RigidInertia, Wrench};
use loop_support::{add_named, part_inertia, random_inertia, random_q, random_vec, rng};
use nalgebra::{Isometry3, Matrix3, Vector3};
use proptest::prelude::*;
use rand::rngs::StdRng;
use rand::Rng;
use reference_support::deviation;
use std::collections::BTreeSet;

/// Rotor inertia: axisymmetric about its z (spin) axis with the CoM on it, or generic.
fn rotor_inertia(rng: &mut StdRng, axisymmetric: bool) -> RigidInertia {
    let (a, b) = (rng.random_range(2e-5..8e-5), rng.random_range(1e-5..4e-5));
    let com = Vector3::new(0.0, 0.0, rng.random_range(-0.05..0.1));
    if axisymmetric {
        let ic = Matrix3::from_diagonal(&Vector3::new(a, a, b));
        return RigidInertia::new(rng.random_range(0.05..0.3), com, ic).unwrap();
    }
    let ic = Matrix3::from_diagonal(&Vector3::new(a, 1.4 * a, 0.8 * a));
    RigidInertia::new(0.2, com + Vector3::new(2e-3, -1e-3, 0.0), ic).unwrap()
}

/// Floating shank, ankle cross (y) and foot (x) with a toe, the six ankle parts on the shank;
/// rotor and rod of actuator `i` axisymmetric if `axisymmetric[i]`.
fn ankle_leg(rng: &mut StdRng, axisymmetric: [bool; 2]) -> Model {
    let drive = AnkleDrive::new(AnkleDriveParams::default()).unwrap();
    let mut b = ModelBuilder::new();
    let rev = |axis| JointModel::Revolute { axis };
    let id = Isometry3::identity();
    let shank = add_named(
        &mut b,
        "shank",
        None,
        JointModel::FreeQuaternion,
        id,
        random_inertia(rng),
    );
    let center = Isometry3::translation(0.0, 0.0, -0.4);
    let cross = add_named(
        &mut b,
        "cross",
        Some(shank),
        rev(Vector3::y_axis()),
        center,
        random_inertia(rng),
    );
    let foot = add_named(
        &mut b,
        "foot",
        Some(cross),
        rev(Vector3::x_axis()),
        id,
        random_inertia(rng),
    );
    let toe_at = Isometry3::translation(0.15, 0.0, -0.05);
    add_named(
        &mut b,
        "toe",
        Some(foot),
        rev(Vector3::y_axis()),
        toe_at,
        random_inertia(rng),
    );
    for (act, &sym) in axisymmetric.iter().enumerate() {
        for part in [AnklePart::Nut, AnklePart::Rotor, AnklePart::Rod] {
            let inertia = match part {
                AnklePart::Rotor => rotor_inertia(rng, sym),
                AnklePart::Rod if sym => rotor_inertia(rng, true),
                _ => part_inertia(rng),
            };
            let mechanism = Mechanism::Ankle(drive.part(act, part).unwrap());
            let joint = JointModel::Coupled {
                mechanism,
                inputs: vec![cross, foot],
            };
            add_named(
                &mut b,
                &format!("{part:?}_{act}"),
                Some(shank),
                joint,
                id,
                inertia,
            );
        }
    }
    b.build().unwrap()
}

/// Floating thigh, knee (z) with a foot below, and the knee drive's housing, nut and rotor on
/// the thigh; rotor axisymmetric or generic, housing and nut generic or `round`.
fn knee_leg(rng: &mut StdRng, axisymmetric: bool, tilt: bool, round: bool) -> Model {
    let params = KneeDriveParams {
        screw_tilt: tilt,
        ..KneeDriveParams::default()
    };
    let drive = KneeDrive::new(params).unwrap();
    let mut b = ModelBuilder::new();
    let id = Isometry3::identity();
    let z = JointModel::Revolute {
        axis: Vector3::z_axis(),
    };
    let thigh = add_named(
        &mut b,
        "thigh",
        None,
        JointModel::FreeQuaternion,
        id,
        random_inertia(rng),
    );
    let knee = add_named(
        &mut b,
        "knee",
        Some(thigh),
        z.clone(),
        id,
        random_inertia(rng),
    );
    let below = Isometry3::translation(0.0, -0.4, 0.0);
    add_named(&mut b, "foot", Some(knee), z, below, random_inertia(rng));
    for part in [KneePart::Housing, KneePart::Nut, KneePart::Rotor] {
        let inertia = match part {
            KneePart::Rotor => rotor_inertia(rng, axisymmetric),
            _ if round => rotor_inertia(rng, true),
            _ => part_inertia(rng),
        };
        let joint = JointModel::Coupled {
            mechanism: Mechanism::Knee(drive.part(part)),
            inputs: vec![knee],
        };
        add_named(
            &mut b,
            &format!("{part:?}"),
            Some(thigh),
            joint,
            id,
            inertia,
        );
    }
    b.build().unwrap()
}

/// [`deviation`] at a random state with the named coordinates inside their ranges.
fn check(model: &Model, rng: &mut StdRng, ranges: &[(&str, f64, f64)], with_fext: bool) -> f64 {
    let mut q = random_q(model, rng);
    for &(name, lo, hi) in ranges {
        q[model.bodies()[model.body_id(name).unwrap()].q_index()] = rng.random_range(lo..hi);
    }
    let (v, tau) = (
        random_vec(model.nv(), 3.0, rng),
        random_vec(model.nv(), 5.0, rng),
    );
    let mut r = || Vector3::new(rng.random(), rng.random(), rng.random()) * 2.0;
    let fext: Vec<Wrench> = (0..model.nbodies())
        .map(|_| Wrench::new(r(), r()))
        .collect();
    deviation(model, &q, &v, &tau, with_fext.then_some(fext.as_slice()))
}

const ANKLE: [(&str, f64, f64); 2] = [("cross", -0.3, 0.3), ("foot", -0.3, 0.3)];
const KNEE: [(&str, f64, f64); 1] = [("knee", 0.0, 1.9)];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn ankle_legs_match_the_fast_paths(seed in any::<u64>(), a: bool, b: bool, fext: bool) {
        let mut rng = rng(seed);
        let model = ankle_leg(&mut rng, [a, b]);
        let dev = check(&model, &mut rng, &ANKLE, fext);
        prop_assert!(dev < 1e-9, "ankle {a} {b}: {dev:e}");
    }

    #[test]
    fn knee_legs_match_the_fast_paths(seed in any::<u64>(), sym: bool, tilt: bool, round: bool, fext: bool) {
        let mut rng = rng(seed);
        let model = knee_leg(&mut rng, sym, tilt, round);
        let dev = check(&model, &mut rng, &KNEE, fext);
        prop_assert!(dev < 1e-9, "knee {sym} {tilt} {round}: {dev:e}");
    }
}

/// The legs exercise the axisymmetric, axial screw and slider, carrier, rider and general
/// members of the fast path; the largest deviation is printed with `--nocapture`.
#[test]
fn drive_member_kinds_covered() {
    let mut rng = rng(5);
    let (mut kinds, mut worst) = (BTreeSet::new(), 0.0_f64);
    for flags in 0..8u8 {
        let bit = |k: u8| flags & (1 << k) != 0;
        let ankle = ankle_leg(&mut rng, [bit(0), bit(1)]);
        let knee = knee_leg(&mut rng, bit(0), bit(1), bit(2));
        for (model, ranges) in [(&ankle, &ANKLE[..]), (&knee, &KNEE[..])] {
            kinds.extend(fast_member_kinds(model).into_iter().map(|(_, k)| k));
            for _ in 0..4 {
                worst = worst.max(check(model, &mut rng, ranges, bit(2)));
            }
        }
    }
    println!("drive member kinds: {kinds:?}, largest deviation {worst:e}");
    assert!(worst < 1e-9, "{worst:e}");
    use MemberKind::*;
    for k in [
        Axisymmetric,
        AxialScrew,
        AxialSlider,
        Carrier,
        Rider,
        General,
    ] {
        assert!(kinds.contains(&k), "{k:?} not exercised: {kinds:?}");
    }
}
