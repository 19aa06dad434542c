//! Dill(n): Featherstone's fractal kinematic tree, the branched benchmark of thesis 2.10.1
//! (Table 2.1, Figs. 2.17-2.19).
//!
//! The thesis quotes the definition; these are the choices made where it is silent:
//! - **Joint axis.** Every joint is revolute about the z axis of its joint frame; the link extends
//!   along the body x axis (the quoted cylinder is "centred on the x-axis", CoM at x = 0.05).
//! - **Inertia reference point.** The quoted moments `Ixx = 1/200000`, `Iyy = Izz = 403/1200000`
//!   are about the link's joint origin, not about the CoM: only then are they those of a cylinder
//!   of length 0.1 and radius 0.01 (about the CoM `Iyy = m(3r^2 + L^2)/12 = 103/1200000`, plus
//!   `m 0.05^2 = 300/1200000`). They are shifted to the CoM by the parallel-axis theorem.
//! - **Scaling.** Dill(0) has scale 1; the root link of Dill(n), n > 0, has scale n: lengths
//!   (the CoM) times n, mass times n^3, moments times n^5.
//! - **Skew.** Sub-tree i (i = 1..n) hangs on a joint frame that is the parent link frame
//!   translated by i * 0.1 along its x axis and rotated by i/3 rad about that x axis (the two
//!   commute). The displacement is not scaled, so sub-tree n sits at the tip of the parent link.
//! - **Body order.** Depth-first pre-order, sub-trees in increasing i, so every parent precedes
//!   its children; body k is named `link<k>` and its joint `joint<k>`.

use crate::{BodyId, BodySpec, JointModel, Model, ModelBuilder, ModelError, RigidInertia};
use nalgebra::{DVector, Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};

/// Largest supported Dill level (2^16 = 65536 bodies).
pub const MAX_DILL_LEVEL: u32 = 16;

/// Link length of Dill(0) in metres (also the sub-tree displacement step).
const LINK_LENGTH: f64 = 0.1;
/// Mass of the Dill(0) link in kg.
const LINK_MASS: f64 = 0.1;

/// Errors of the Dill(n) generator.
#[derive(Debug, thiserror::Error)]
pub enum DillError {
    /// The requested level would produce an unreasonably large tree.
    #[error("Dill level {n} is too large (at most {max} is supported)")]
    TooLarge {
        /// Requested level.
        n: u32,
        /// Largest supported level.
        max: u32,
    },
    /// The model builder rejected a body (a bug in the generator).
    #[error("Dill model construction failed: {0}")]
    Model(#[from] ModelError),
}

/// Parent of every body of Dill(n) in body-list order (`None` = attached to the world).
pub fn dill_parents(n: u32) -> Result<Vec<Option<BodyId>>, DillError> {
    check_level(n)?;
    let mut parents = Vec::with_capacity(1 << n);
    push_parents(n, None, &mut parents);
    Ok(parents)
}

/// Dill(n) with 2^n revolute bodies (thesis 2.10.1), gravity (0, 0, -9.81).
pub fn dill(n: u32) -> Result<Model, DillError> {
    check_level(n)?;
    let mut builder = ModelBuilder::new();
    add_subtree(&mut builder, n, None, Isometry3::identity(), &mut 0)?;
    Ok(builder.build()?)
}

/// The test state of thesis 2.10.1: every `q_i = pi/6`, every `qdot_i = 1`.
pub fn dill_test_state(model: &Model) -> (DVector<f64>, DVector<f64>) {
    (
        DVector::from_element(model.nq(), std::f64::consts::FRAC_PI_6),
        DVector::from_element(model.nv(), 1.0),
    )
}

/// Non-zeros of the lower triangle of Dill(n)'s mass matrix, Table 2.2: `2^(n-1) (2 + n)`.
pub fn dill_nonzeros_formula(n: u32) -> u64 {
    // 2^(n-1) (2 + n) = 2^n (2 + n) / 2, which is exact for n = 0 too (= 1).
    ((1u64 << n) * (2 + u64::from(n))) / 2
}

/// Structural non-zeros of the lower triangle of a tree's mass matrix for one-DoF joints:
/// element (i, j), j <= i, is structurally non-zero iff body j is body i or one of its ancestors.
pub fn tree_lower_nonzeros(parents: &[Option<BodyId>]) -> u64 {
    let mut depth = vec![0u64; parents.len()];
    for (i, p) in parents.iter().enumerate() {
        depth[i] = 1 + p.map_or(0, |p| depth[p]);
    }
    depth.iter().sum()
}

/// Rejects levels above [`MAX_DILL_LEVEL`].
fn check_level(n: u32) -> Result<(), DillError> {
    if n > MAX_DILL_LEVEL {
        return Err(DillError::TooLarge {
            n,
            max: MAX_DILL_LEVEL,
        });
    }
    Ok(())
}

/// Appends the parents of a Dill(n) sub-tree whose root hangs on `parent`, in pre-order.
fn push_parents(n: u32, parent: Option<BodyId>, out: &mut Vec<Option<BodyId>>) {
    let root = out.len();
    out.push(parent);
    for i in 1..=n {
        push_parents(i - 1, Some(root), out);
    }
}

/// Adds a Dill(n) sub-tree whose root joint frame sits at `placement` in body `parent`.
fn add_subtree(
    builder: &mut ModelBuilder,
    n: u32,
    parent: Option<BodyId>,
    placement: Isometry3<f64>,
    count: &mut usize,
) -> Result<BodyId, DillError> {
    let k = *count;
    *count += 1;
    let id = builder.add_body(BodySpec {
        name: format!("link{k}"),
        joint_name: format!("joint{k}"),
        parent,
        joint: JointModel::Revolute {
            axis: Vector3::z_axis(),
        },
        placement,
        inertia: link_inertia(f64::from(n.max(1)))?,
    })?;
    for i in 1..=n {
        add_subtree(builder, i - 1, Some(id), subtree_placement(i), count)?;
    }
    Ok(id)
}

/// Joint frame of sub-tree i in its parent link frame: i * 0.1 along x, skew i/3 about x.
pub fn subtree_placement(i: u32) -> Isometry3<f64> {
    let i = f64::from(i);
    Isometry3::from_parts(
        Translation3::new(i * LINK_LENGTH, 0.0, 0.0),
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), i / 3.0),
    )
}

/// Inertia of a Dill link scaled by `s` (mass s^3, lengths s, moments s^5), about its CoM.
pub fn link_inertia(s: f64) -> Result<RigidInertia, ModelError> {
    let mass = LINK_MASS * s.powi(3);
    let com = Vector3::new(0.5 * LINK_LENGTH * s, 0.0, 0.0);
    // Moments about the joint origin as quoted, scaled by s^5 ...
    let i_xx = s.powi(5) / 200_000.0;
    let i_yy = s.powi(5) * 403.0 / 1_200_000.0;
    // ... shifted to the CoM (parallel axis along x: only Iyy and Izz change).
    let shift = mass * com.x * com.x;
    let about_com = Matrix3::from_diagonal(&Vector3::new(i_xx, i_yy - shift, i_yy - shift));
    RigidInertia::new(mass, com, about_com)
}
