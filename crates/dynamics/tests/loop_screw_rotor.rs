//! Roller-screw rotors and nuts on the axial path of the O(n) algorithm (spin rate
//! `N_screw dl/dq` and nut travel read from the mechanism's loop, no part kinematics): O(n)
//! against CRBA and sparse LTL (which evaluate the spun and moved part poses), RNEA as the
//! inverse, external wrenches also on the rotors and nuts, and the centroidal momentum against
//! `A_G v`. Ankle: rotors axisymmetric (axial path) or generic (general path), on a floating
//! shank whose foot carries a toe (a child outside the ankle sub-system). Knee: the rotor and
//! nut ride on the tilting screw housing (lumped into it; with round parts the lumped inertia
//! takes the axisymmetric path), or take the general path when the rotor is not axisymmetric.

mod loop_support;

use biped_dynamics::mechanism::ankle::{AnkleDrive, AnkleDriveParams, AnklePart};
use biped_dynamics::mechanism::knee::{KneeDrive, KneeDriveParams, KneePart};
use biped_dynamics::model::Mechanism;
use biped_dynamics::{
    centroidal_momentum, inverse_dynamics, Centroidal, Data, JointModel, Model, ModelBuilder,
    RigidInertia, Wrench,
};
use loop_support::*;
use nalgebra::{DVector, Isometry3, Matrix3, Vector3};
use proptest::prelude::*;
use rand::rngs::StdRng;
use rand::Rng;

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

/// Floating shank, ankle cross (flexion, y) and foot (adduction, x) with a toe, and the six
/// slider-crank parts of the default ankle drive on the shank; `axisymmetric[i]` for rotor `i`.
fn ankle_leg(seed: u64, axisymmetric: [bool; 2]) -> Model {
    let mut rng = rng(seed);
    let drive = AnkleDrive::new(AnkleDriveParams::default()).unwrap();
    let mut b = ModelBuilder::new();
    let mut add = |name: &str, parent, joint, placement, inertia| {
        add_named(&mut b, name, parent, joint, placement, inertia)
    };
    let rev = |axis| JointModel::Revolute { axis };
    let (i0, i1, i2) = (
        random_inertia(&mut rng),
        random_inertia(&mut rng),
        random_inertia(&mut rng),
    );
    let shank = add(
        "shank",
        None,
        JointModel::FreeQuaternion,
        Isometry3::identity(),
        i0,
    );
    let center = Isometry3::translation(0.0, 0.0, -0.4);
    let cross = add("cross", Some(shank), rev(Vector3::y_axis()), center, i1);
    let foot = add(
        "foot",
        Some(cross),
        rev(Vector3::x_axis()),
        Isometry3::identity(),
        i2,
    );
    let toe_at = Isometry3::translation(0.15, 0.0, -0.05);
    let toe_inertia = random_inertia(&mut rng);
    add(
        "toe",
        Some(foot),
        rev(Vector3::y_axis()),
        toe_at,
        toe_inertia,
    );
    for (act, &sym) in axisymmetric.iter().enumerate() {
        for part in [AnklePart::Nut, AnklePart::Rotor, AnklePart::Rod] {
            let inertia = match part {
                AnklePart::Rotor => rotor_inertia(&mut rng, sym),
                _ => part_inertia(&mut rng),
            };
            let joint = JointModel::Coupled {
                mechanism: Mechanism::Ankle(drive.part(act, part).unwrap()),
                inputs: vec![cross, foot],
            };
            add(
                &format!("{part:?}_{act}"),
                Some(shank),
                joint,
                Isometry3::identity(),
                inertia,
            );
        }
    }
    b.build().unwrap()
}

/// Floating thigh, shank on the knee (thigh z axis) with a foot below it (a child outside
/// the knee sub-system), and the housing, nut and rotor of a knee drive (tilt on or off) on
/// the thigh; the rotor axisymmetric or generic, housing and nut generic or `round` (on-axis
/// CoM, `I_xx = I_yy`).
fn knee_leg(seed: u64, axisymmetric: bool, tilt: bool, round: bool) -> Model {
    let mut rng = rng(seed);
    let drive = KneeDrive::new(KneeDriveParams {
        screw_tilt: tilt,
        ..KneeDriveParams::default()
    })
    .unwrap();
    let mut b = ModelBuilder::new();
    let mut add = |name: &str, parent, joint, placement, inertia| {
        add_named(&mut b, name, parent, joint, placement, inertia)
    };
    let (i0, i1, i2) = (
        random_inertia(&mut rng),
        random_inertia(&mut rng),
        random_inertia(&mut rng),
    );
    let id = Isometry3::identity();
    let thigh = add("thigh", None, JointModel::FreeQuaternion, id, i0);
    let z = JointModel::Revolute {
        axis: Vector3::z_axis(),
    };
    let shank = add("knee", Some(thigh), z.clone(), id, i1);
    let below = Isometry3::translation(0.0, -0.4, 0.0);
    add("foot", Some(shank), z.clone(), below, i2);
    for part in [KneePart::Housing, KneePart::Nut, KneePart::Rotor] {
        let inertia = match part {
            KneePart::Rotor => rotor_inertia(&mut rng, axisymmetric),
            _ if round => rotor_inertia(&mut rng, true),
            _ => part_inertia(&mut rng),
        };
        let joint = JointModel::Coupled {
            mechanism: Mechanism::Knee(drive.part(part)),
            inputs: vec![shank],
        };
        add(&format!("{part:?}"), Some(thigh), joint, id, inertia);
    }
    b.build().unwrap()
}

/// A random state with the named coordinates inside their ranges.
fn state(
    model: &Model,
    rng: &mut StdRng,
    ranges: &[(&str, f64, f64)],
) -> (DVector<f64>, DVector<f64>) {
    let mut q = random_q(model, rng);
    for &(name, lo, hi) in ranges {
        let i = model.body_id(name).unwrap();
        q[model.bodies()[i].q_index()] = rng.random_range(lo..hi);
    }
    (q, random_vec(model.nv(), 3.0, rng))
}

/// O(n), CRBA and sparse agree, RNEA inverts them, and the centroidal momentum of the
/// forward-dynamics pass equals `A_G v`, at a random state (`ranges`) of `model`.
fn check(model: &Model, seed: u64, ranges: &[(&str, f64, f64)], with_fext: bool) {
    let mut rng = rng(seed ^ 0xa4c1e);
    let (q, v) = state(model, &mut rng, ranges);
    let tau = random_vec(model.nv(), 5.0, &mut rng);
    let mut r = || Vector3::new(rng.random(), rng.random(), rng.random()) * 2.0;
    let fext: Vec<Wrench> = (0..model.nbodies())
        .map(|_| Wrench::new(r(), r()))
        .collect();
    let fext = with_fext.then_some(fext.as_slice());
    let mut data = Data::new(model);
    let on = check_methods(seed, model, &mut data, &q, &v, &tau, fext);
    let back = inverse_dynamics(model, &mut data, &q, &v, &on, fext)
        .unwrap()
        .clone();
    assert!(rel_diff(&back, &tau) < 1e-9, "seed {seed}: RNEA(O(n))");
    let fast = centroidal_momentum(model, &mut data, &q, &v).unwrap();
    let mut c = Centroidal::new(model);
    c.compute(model, &mut Data::new(model), &q, &v).unwrap();
    let h = c.momentum().unwrap();
    let scale = 1.0 + h.ang.norm() + h.lin.norm();
    assert!(
        (fast.momentum.ang - h.ang).norm() < 1e-11 * scale,
        "seed {seed}"
    );
    assert!(
        (fast.momentum.lin - h.lin).norm() < 1e-11 * scale,
        "seed {seed}"
    );
    assert!((fast.com - c.com()).norm() < 1e-12, "seed {seed}");
}

const ANKLE: [(&str, f64, f64); 2] = [("cross", -0.3, 0.3), ("foot", -0.3, 0.3)];
const KNEE: [(&str, f64, f64); 1] = [("knee", 0.0, 1.9)];

/// One ankle leg.
fn check_ankle(seed: u64, axisymmetric: [bool; 2], with_fext: bool) {
    check(&ankle_leg(seed, axisymmetric), seed, &ANKLE, with_fext);
}

/// One knee leg.
fn check_knee(seed: u64, axisymmetric: bool, tilt: bool, round: bool, fext: bool) {
    let model = knee_leg(seed, axisymmetric, tilt, round);
    check(&model, seed, &KNEE, fext);
}

#[test]
fn screw_rotor_legs_all_methods_agree() {
    for seed in 0..24 {
        let sym = [seed % 4 != 3, seed % 5 != 4];
        check_ankle(seed, sym, seed % 2 == 0);
    }
}

#[test]
fn knee_riders_all_methods_agree() {
    for seed in 0..24 {
        let (sym, tilt, round) = (seed % 4 != 3, seed % 3 != 2, seed % 5 == 4);
        check_knee(seed, sym, tilt, round, seed % 2 == 0);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    /// Random legs and states, fast and general rotors, with and without external wrenches.
    #[test]
    fn screw_rotors_match_crba(seed in 0u64..100_000, a in any::<bool>(), b in any::<bool>(),
                               fext in any::<bool>()) {
        check_ankle(seed, [a, b], fext);
    }

    /// Random knee legs and states: riders on a tilting or fixed housing, or general parts.
    #[test]
    fn knee_riders_match_crba(seed in 0u64..100_000, sym in any::<bool>(), tilt in any::<bool>(),
                              round in any::<bool>(), fext in any::<bool>()) {
        check_knee(seed, sym, tilt, round, fext);
    }
}
