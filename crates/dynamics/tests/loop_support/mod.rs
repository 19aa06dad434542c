//! Random trees with injected kinematic loops (rotors, coupled parts) for the `loop_*` tests.
#![allow(dead_code)]

#[path = "../core_support/mod.rs"]
mod core_support;

#[allow(unused_imports)] // Each test binary uses a different part.
pub use core_support::{
    add_named, random_axis, random_inertia, random_pose, random_q, random_vec, rel_diff, rng,
};

use biped_dynamics::model::{FourBar, LinearCoupling, Mechanism};
use biped_dynamics::{
    forward_dynamics, Algorithm, BodySpec, Data, JointModel, Model, ModelBuilder, RigidInertia,
    Wrench,
};
use nalgebra::{DVector, Matrix3, Vector3};
use rand::rngs::StdRng;
use rand::Rng;

/// Asserts that O(n) and sparse LTL forward dynamics agree with CRBA to 1e-10 (relative).
pub fn assert_methods_agree(
    seed: u64,
    on: &DVector<f64>,
    crba: &DVector<f64>,
    sparse: &DVector<f64>,
) {
    assert!(
        rel_diff(on, crba) < 1e-10,
        "seed {seed}: O(n) vs CRBA {}",
        rel_diff(on, crba)
    );
    assert!(
        rel_diff(sparse, crba) < 1e-10,
        "seed {seed}: sparse vs CRBA"
    );
}

/// Forward dynamics by O(n), CRBA and sparse LTL at one state, asserted to agree
/// ([`assert_methods_agree`]); returns the O(n) result.
#[allow(clippy::too_many_arguments)]
pub fn check_methods(
    seed: u64,
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    tau: &DVector<f64>,
    fext: Option<&[Wrench]>,
) -> DVector<f64> {
    let mut run = |algo| {
        forward_dynamics(model, data, q, v, tau, fext, algo)
            .expect("forward dynamics")
            .clone()
    };
    let (on, crba, sparse) = (
        run(Algorithm::On),
        run(Algorithm::Crba),
        run(Algorithm::Sparse),
    );
    assert_methods_agree(seed, &on, &crba, &sparse);
    on
}

/// What a generated body is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Revolute or prismatic joint.
    One,
    /// Fixed, free or other joint.
    Other,
    /// Leaf sharing other bodies' coordinates.
    Coupled,
}

/// Slim, light inertia of a drive-train part.
pub fn part_inertia(rng: &mut StdRng) -> RigidInertia {
    let r = rng.random_range(0.01..0.03);
    let com = Vector3::new(
        rng.random_range(-0.02..0.02),
        0.0,
        rng.random_range(-0.02..0.02),
    );
    RigidInertia::new(
        rng.random_range(0.1..0.4),
        com,
        Matrix3::from_diagonal(&Vector3::new(r * r, r * r, 2.0 * r * r)) * 0.1,
    )
    .unwrap()
}

/// Ancestors of `b` including itself, nearest first.
pub fn ancestors(parents: &[Option<usize>], b: usize) -> Vec<usize> {
    let mut out = vec![b];
    let mut k = parents[b];
    while let Some(p) = k {
        out.push(p);
        k = parents[p];
    }
    out
}

/// Random tree of `n` bodies where about a quarter are drive-train leaves: `coupling`
/// returns the joint of a leaf given the generator, the candidate input bodies (one-DoF, in
/// a chain) and their parents, or `None` to fall back to a plain joint.
pub fn random_loop_model(
    seed: u64,
    n: usize,
    root_free: bool,
    mut coupling: impl FnMut(&mut StdRng, &[usize]) -> Option<JointModel>,
) -> Model {
    let mut rng = rng(seed);
    let mut b = ModelBuilder::new();
    let mut kinds: Vec<Kind> = Vec::new();
    let mut parents: Vec<Option<usize>> = Vec::new();
    for i in 0..n {
        let (parent, joint) = if i == 0 {
            let j = if root_free {
                JointModel::FreeQuaternion
            } else {
                JointModel::Revolute {
                    axis: random_axis(&mut rng),
                }
            };
            (None, j)
        } else {
            random_child(&mut rng, i, &kinds, &parents, &mut coupling)
        };
        kinds.push(match &joint {
            JointModel::Revolute { .. } | JointModel::Prismatic { .. } => Kind::One,
            JointModel::GearedRotor { .. } => Kind::Coupled,
            _ if joint.nv() == 0 && !matches!(joint, JointModel::Fixed) => Kind::Coupled,
            _ => Kind::Other,
        });
        parents.push(parent);
        let inertia = if kinds[i] == Kind::Coupled {
            part_inertia(&mut rng)
        } else {
            random_inertia(&mut rng)
        };
        b.add_body(BodySpec {
            name: format!("body{i}"),
            joint_name: format!("joint{i}"),
            parent,
            joint,
            placement: random_pose(&mut rng),
            inertia,
        })
        .unwrap();
    }
    b.build().unwrap()
}

/// A non-root body: a plain joint, or (one in four) a drive-train leaf whose parent is an
/// ancestor-or-self of its first input body, so that loops span several tree levels.
fn random_child(
    rng: &mut StdRng,
    i: usize,
    kinds: &[Kind],
    parents: &[Option<usize>],
    coupling: &mut impl FnMut(&mut StdRng, &[usize]) -> Option<JointModel>,
) -> (Option<usize>, JointModel) {
    let ones: Vec<usize> = (0..i).filter(|&d| kinds[d] == Kind::One).collect();
    if !ones.is_empty() && rng.random_range(0..4) == 0 {
        let d = ones[rng.random_range(0..ones.len())];
        // Inputs: `d` and possibly one-DoF ancestors of `d` (a chain, as mechanisms need).
        let chain: Vec<usize> = ancestors(parents, d)
            .into_iter()
            .filter(|&a| kinds[a] == Kind::One)
            .collect();
        let k = rng.random_range(1..=chain.len().min(3));
        let inputs = &chain[..k];
        let up = ancestors(parents, d);
        let parent = up[rng.random_range(0..up.len().min(3))];
        if let Some(j) = coupling(rng, inputs) {
            return (Some(parent), j);
        }
    }
    let cands: Vec<usize> = (0..i).filter(|&p| kinds[p] != Kind::Coupled).collect();
    let parent = cands[rng.random_range(0..cands.len())];
    let joint = match rng.random_range(0..10) {
        0..=5 => JointModel::Revolute {
            axis: random_axis(rng),
        },
        6..=8 => JointModel::Prismatic {
            axis: random_axis(rng),
        },
        _ => JointModel::Fixed,
    };
    (Some(parent), joint)
}

/// Geared rotor on the first input (the linear coupling of (3.1)).
pub fn rotor(rng: &mut StdRng, inputs: &[usize]) -> Option<JointModel> {
    Some(JointModel::GearedRotor {
        axis: random_axis(rng),
        ratio: rng.random_range(-100.0..100.0),
        driver: inputs[0],
    })
}

/// A Grashof crank-rocker: the crank turns fully, no dead centre.
pub fn four_bar(elbow: f64) -> FourBar {
    FourBar {
        crank: 0.05,
        coupler: 0.2,
        rocker: 0.15,
        ground: 0.2,
        elbow,
    }
}

/// Random coupled leaf: geared rotor, linear gear over 1-3 inputs, or four-bar coupler.
pub fn random_coupling(rng: &mut StdRng, inputs: &[usize]) -> Option<JointModel> {
    Some(match rng.random_range(0..3) {
        0 => JointModel::GearedRotor {
            axis: random_axis(rng),
            ratio: rng.random_range(-50.0..50.0),
            driver: inputs[0],
        },
        1 => JointModel::Coupled {
            mechanism: Mechanism::Linear(LinearCoupling {
                axis: random_axis(rng),
                ratios: inputs
                    .iter()
                    .map(|_| rng.random_range(-20.0..20.0))
                    .collect(),
            }),
            inputs: inputs.to_vec(),
        },
        _ => JointModel::Coupled {
            mechanism: Mechanism::FourBar(four_bar(if rng.random_bool(0.5) { 1.0 } else { -1.0 })),
            inputs: vec![inputs[0]],
        },
    })
}
