//! Random trees and helpers shared by the `core_*` integration tests.
#![allow(dead_code)]

use biped_dynamics::{BodySpec, JointModel, Model, ModelBuilder, RigidInertia};
use nalgebra::{
    DVector, Isometry3, Matrix3, Rotation3, Translation3, Unit, UnitQuaternion, Vector3,
};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// Options of the random tree generator.
#[derive(Clone, Copy, Debug)]
pub struct TreeOptions {
    /// Root joint: 0 quaternion free, 1 Euler free, 2 revolute, 3 prismatic, 4 fixed, 5 random.
    pub root: u8,
    /// Allow geared rotors.
    pub rotors: bool,
    /// Allow free joints below the root.
    pub inner_free: bool,
    /// Gravity.
    pub gravity: Vector3<f64>,
}

impl Default for TreeOptions {
    fn default() -> Self {
        Self {
            root: 5,
            rotors: false,
            inner_free: true,
            gravity: Vector3::new(0.0, 0.0, -9.81),
        }
    }
}

/// Random unit vector, sometimes a (signed) coordinate axis.
pub fn random_axis(rng: &mut StdRng) -> Unit<Vector3<f64>> {
    match rng.random_range(0..5) {
        0 => Vector3::x_axis(),
        1 => Vector3::y_axis(),
        2 => Vector3::z_axis(),
        _ => loop {
            let v = Vector3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            );
            if v.norm() > 0.1 {
                return Unit::new_normalize(v);
            }
        },
    }
}

/// Random rotation.
pub fn random_rotation(rng: &mut StdRng) -> UnitQuaternion<f64> {
    let q = nalgebra::Quaternion::new(
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
    );
    UnitQuaternion::new_normalize(q + nalgebra::Quaternion::new(1e-3, 0.0, 0.0, 0.0))
}

/// Random pose with translation in [-0.4, 0.4]^3.
pub fn random_pose(rng: &mut StdRng) -> Isometry3<f64> {
    let t = Vector3::new(
        rng.random_range(-0.4..0.4),
        rng.random_range(-0.4..0.4),
        rng.random_range(-0.4..0.4),
    );
    Isometry3::from_parts(Translation3::from(t), random_rotation(rng))
}

/// Random physically valid inertia (a box of random size and orientation, random CoM).
pub fn random_inertia(rng: &mut StdRng) -> RigidInertia {
    let m = rng.random_range(0.3..3.0);
    let (a, b, c): (f64, f64, f64) = (
        rng.random_range(0.05..0.5),
        rng.random_range(0.05..0.5),
        rng.random_range(0.05..0.5),
    );
    let d = Matrix3::from_diagonal(&Vector3::new(b * b + c * c, a * a + c * c, a * a + b * b))
        * (m / 12.0);
    let r = random_rotation(rng).to_rotation_matrix().into_inner();
    let com = Vector3::new(
        rng.random_range(-0.2..0.2),
        rng.random_range(-0.2..0.2),
        rng.random_range(-0.2..0.2),
    );
    RigidInertia::new(m, com, r * d * r.transpose()).unwrap()
}

/// Joint of a non-root body.
fn random_joint(rng: &mut StdRng, opts: &TreeOptions) -> JointModel {
    let k = rng.random_range(0..20);
    match k {
        0..=9 => JointModel::Revolute {
            axis: random_axis(rng),
        },
        10..=14 => JointModel::Prismatic {
            axis: random_axis(rng),
        },
        15..=16 => JointModel::Fixed,
        17 if opts.inner_free => JointModel::FreeEulerZxz,
        18 if opts.inner_free => JointModel::FreeQuaternion,
        _ => JointModel::Revolute {
            axis: random_axis(rng),
        },
    }
}

/// Random tree with `n` bodies.
pub fn random_model(seed: u64, n: usize, opts: TreeOptions) -> Model {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut b = ModelBuilder::new();
    b.set_gravity(opts.gravity);
    let mut kinds: Vec<&'static str> = Vec::new();
    let mut parents: Vec<Option<usize>> = Vec::new();
    for i in 0..n {
        let (parent, joint) = if i == 0 {
            let root = if opts.root == 5 {
                rng.random_range(0..5)
            } else {
                opts.root
            };
            let j = match root {
                0 => JointModel::FreeQuaternion,
                1 => JointModel::FreeEulerZxz,
                2 => JointModel::Revolute {
                    axis: random_axis(&mut rng),
                },
                3 => JointModel::Prismatic {
                    axis: random_axis(&mut rng),
                },
                _ => JointModel::Fixed,
            };
            (None, j)
        } else {
            let candidates: Vec<usize> = (0..i).filter(|&p| kinds[p] != "rotor").collect();
            let parent = candidates[rng.random_range(0..candidates.len())];
            let mut joint = random_joint(&mut rng, &opts);
            if opts.rotors && rng.random_range(0..4) == 0 {
                // Driver: a one-DoF child of the parent (sibling rotor) or the parent itself.
                let mut drivers: Vec<usize> = (0..i)
                    .filter(|&d| parents[d] == Some(parent) && kinds[d] == "one")
                    .collect();
                if kinds[parent] == "one" {
                    drivers.push(parent);
                }
                if !drivers.is_empty() {
                    joint = JointModel::GearedRotor {
                        axis: random_axis(&mut rng),
                        ratio: rng.random_range(-100.0..100.0),
                        driver: drivers[rng.random_range(0..drivers.len())],
                    };
                }
            }
            (Some(parent), joint)
        };
        kinds.push(match &joint {
            JointModel::Revolute { .. } | JointModel::Prismatic { .. } => "one",
            JointModel::GearedRotor { .. } => "rotor",
            _ => "other",
        });
        parents.push(parent);
        let mut inertia = random_inertia(&mut rng);
        if kinds[i] == "rotor" {
            // Rotors are slim and light compared with links.
            let r = rng.random_range(0.01..0.03);
            inertia = RigidInertia::new(
                0.2,
                Vector3::zeros(),
                Matrix3::from_diagonal(&Vector3::new(r * r, r * r, 2.0 * r * r)) * 0.1,
            )
            .unwrap();
        }
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

/// Random configuration (Euler angles kept away from the ZXZ singularity).
pub fn random_q(model: &Model, rng: &mut StdRng) -> DVector<f64> {
    let mut q = DVector::zeros(model.nq());
    for body in model.bodies() {
        if !body.owns_coordinates() {
            continue;
        }
        let qi = body.q_index();
        match body.joint() {
            JointModel::Revolute { .. } => q[qi] = rng.random_range(-3.0..3.0),
            JointModel::Prismatic { .. } => q[qi] = rng.random_range(-0.5..0.5),
            JointModel::FreeEulerZxz => {
                for c in 0..3 {
                    q[qi + c] = rng.random_range(-1.0..1.0);
                }
                q[qi + 3] = rng.random_range(-3.0..3.0);
                q[qi + 4] = rng.random_range(0.4..2.7);
                q[qi + 5] = rng.random_range(-3.0..3.0);
            }
            JointModel::FreeQuaternion => {
                for c in 0..3 {
                    q[qi + c] = rng.random_range(-1.0..1.0);
                }
                let r = random_rotation(rng);
                q.rows_mut(qi + 3, 4).copy_from(&r.quaternion().coords);
            }
            _ => {}
        }
    }
    q
}

/// Random vector with entries in [-s, s].
pub fn random_vec(n: usize, s: f64, rng: &mut StdRng) -> DVector<f64> {
    DVector::from_fn(n, |_, _| rng.random_range(-s..s))
}

/// Adds body `name` (its joint named alike) to `b`; its id.
pub fn add_named(
    b: &mut ModelBuilder,
    name: &str,
    parent: Option<usize>,
    joint: JointModel,
    placement: Isometry3<f64>,
    inertia: RigidInertia,
) -> usize {
    b.add_body(BodySpec::named(name, parent, joint, placement, inertia))
        .unwrap()
}

/// Seeded generator.
pub fn rng(seed: u64) -> StdRng {
    StdRng::seed_from_u64(seed)
}

/// Relative difference `|a - b| / max(1, |a|, |b|)` in the max norm.
pub fn rel_diff(a: &DVector<f64>, b: &DVector<f64>) -> f64 {
    let scale = a.amax().max(b.amax()).max(1.0);
    (a - b).amax() / scale
}

/// World rotation as a matrix from a world pose.
pub fn rot(iso: &Isometry3<f64>) -> Matrix3<f64> {
    iso.rotation.to_rotation_matrix().into_inner()
}

/// Angular velocity vector from `R^T Rdot` (finite-difference helper).
pub fn vee(m: &Matrix3<f64>) -> Vector3<f64> {
    Vector3::new(
        m[(2, 1)] - m[(1, 2)],
        m[(0, 2)] - m[(2, 0)],
        m[(1, 0)] - m[(0, 1)],
    ) * 0.5
}

/// Keeps `Rotation3` in scope for callers building rotations.
pub fn rotation_about(axis: &Unit<Vector3<f64>>, angle: f64) -> Matrix3<f64> {
    Rotation3::from_axis_angle(axis, angle).into_inner()
}
