//! Sub-system members axisymmetric about their z axis (CoM on the axis, `I_c = diag(a, a, b)`):
//! the O(n) backward step applies their inertia and congruence in short forms
//! (`subsystem::rigid`). On random trees whose sub-systems mix such members with general rigid
//! and articulated ones (one and two coordinates), O(n) forward dynamics must agree with CRBA
//! and the sparse LTL method, which do not use those forms.

mod loop_support;

use biped_dynamics::model::{LinearCoupling, Mechanism};
use biped_dynamics::{BodySpec, Data, JointModel, Model, ModelBuilder, RigidInertia};
use loop_support::*;
use nalgebra::{Matrix3, Vector3};
use rand::rngs::StdRng;
use rand::Rng;

/// A random body axisymmetric about its z axis (exactly: the short path applies).
fn axisymmetric(rng: &mut StdRng) -> RigidInertia {
    let a = rng.random_range(0.01..0.2);
    let b = a * rng.random_range(0.1..2.0); // Triangle inequality: b <= 2 a.
    let com = Vector3::new(0.0, 0.0, rng.random_range(-0.2..0.2));
    let ic = Matrix3::from_diagonal(&Vector3::new(a, a, b));
    RigidInertia::new(rng.random_range(0.1..2.0), com, ic).expect("valid")
}

/// Free root; links 1 (revolute, child 4 outside) and 2 (revolute, axisymmetric leaf) joined
/// with part 3 (axisymmetric, driven by both) into a two-coordinate sub-system; link 4 and its
/// axisymmetric geared rotor 5 (on link 1) a one-coordinate one.
fn model(seed: u64) -> Model {
    let mut rng = rng(seed);
    let mut b = ModelBuilder::new();
    let mut count = 0;
    let mut add = |rng: &mut StdRng, parent: Option<usize>, joint, inertia| {
        let i = count;
        count += 1;
        b.add_body(BodySpec {
            name: format!("body{i}"),
            joint_name: format!("joint{i}"),
            parent,
            joint,
            placement: random_pose(rng),
            inertia,
        })
        .expect("body")
    };
    let inertia = random_inertia(&mut rng);
    add(&mut rng, None, JointModel::FreeQuaternion, inertia);
    let revolute = |rng: &mut StdRng| JointModel::Revolute {
        axis: random_axis(rng),
    };
    let (j, i) = (revolute(&mut rng), random_inertia(&mut rng));
    add(&mut rng, Some(0), j, i);
    let (j, i) = (revolute(&mut rng), axisymmetric(&mut rng));
    add(&mut rng, Some(1), j, i);
    let gear = JointModel::Coupled {
        mechanism: Mechanism::Linear(LinearCoupling {
            axis: random_axis(&mut rng),
            ratios: vec![rng.random_range(-20.0..20.0), rng.random_range(-20.0..20.0)],
        }),
        inputs: vec![1, 2],
    };
    let i = axisymmetric(&mut rng);
    add(&mut rng, Some(0), gear, i);
    let (j, i) = (revolute(&mut rng), random_inertia(&mut rng));
    add(&mut rng, Some(1), j, i);
    let rotor = JointModel::GearedRotor {
        axis: random_axis(&mut rng),
        ratio: rng.random_range(-50.0..50.0),
        driver: 4,
    };
    let i = axisymmetric(&mut rng);
    add(&mut rng, Some(1), rotor, i);
    b.build().expect("model")
}

#[test]
fn on_with_axisymmetric_members_matches_crba_and_sparse() {
    for seed in 0..30 {
        let model = model(seed);
        assert_eq!(model.subsystems().len(), 2, "seed {seed}");
        let mut rng = rng(1000 + seed);
        let q = random_q(&model, &mut rng);
        let v = random_vec(model.nv(), 1.0, &mut rng);
        let tau = random_vec(model.nv(), 1.0, &mut rng);
        let mut data = Data::new(&model);
        check_methods(seed, &model, &mut data, &q, &v, &tau, None);
    }
}
