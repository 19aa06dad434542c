//! Immutable multibody model: bodies in strict parent-before-child order with parent, child and
//! brother links (section 2.4.1), joints and their coordinate index sets (2.26).

mod ancestors;
mod builder;
mod coordinates;
pub mod coupling;
pub mod gear;
pub(crate) mod joint;
mod rotors;

pub(crate) use ancestors::DofAncestors;
pub use builder::{BodySpec, ModelBuilder};
pub use coupling::{FourBar, LinearCoupling, Mechanism};
pub use gear::ElasticGear;
pub use joint::JointModel;
pub use rotors::RotorSpec;

use crate::spatial::{RigidInertia, SpatialTransform};
use crate::subsystem::{Node, Subsystem};
use joint::Joint;
use nalgebra::{DVector, Isometry3, Vector3};

/// Index into the model's body list (parent-before-child order).
pub type BodyId = usize;

/// A joint with coordinates: its name and its slices of `q` and `v`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct JointInfo {
    /// Joint name.
    pub name: String,
    /// Number of position coordinates.
    pub nq: usize,
    /// Number of velocity coordinates.
    pub nv: usize,
    /// First index in `q`.
    pub q_index: usize,
    /// First index in `v`.
    pub v_index: usize,
}

/// Largest index set a body can have (a quaternion free joint has 7 position coordinates).
pub const MAX_INDEX_SET: usize = 8;

/// Index set of a body into `q` or `v` (2.26): the coordinates its relative motion depends
/// on, in the order of the columns of `J_i`; not necessarily contiguous, possibly shared with
/// other bodies (geared rotors; later, mechanisms whose motion couples several joints).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IndexSet {
    idx: [usize; MAX_INDEX_SET],
    len: usize,
}

impl IndexSet {
    /// The set `start, start + 1, ..., start + len - 1` (`len <= MAX_INDEX_SET`).
    pub(crate) fn contiguous(start: usize, len: usize) -> Self {
        let mut idx = [0; MAX_INDEX_SET];
        for (k, slot) in idx.iter_mut().take(len).enumerate() {
            *slot = start + k;
        }
        Self {
            idx,
            len: len.min(MAX_INDEX_SET),
        }
    }

    /// The given indices in column order (`len <= MAX_INDEX_SET`).
    pub(crate) fn from_slice(indices: &[usize]) -> Self {
        let mut idx = [0; MAX_INDEX_SET];
        let len = indices.len().min(MAX_INDEX_SET);
        idx[..len].copy_from_slice(&indices[..len]);
        Self { idx, len }
    }

    /// The indices in column order.
    #[inline]
    pub fn as_slice(&self) -> &[usize] {
        &self.idx[..self.len]
    }

    /// Number of indices.
    #[inline]
    pub fn len(&self) -> usize {
        self.len
    }

    /// True for bodies without coordinates (fixed joints).
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

/// One body of the model with its joint to the parent (a node of Fig. 2.7).
#[derive(Clone, Debug)]
pub struct Body {
    pub(crate) name: String,
    pub(crate) joint_name: String,
    pub(crate) parent: Option<BodyId>,
    pub(crate) first_child: Option<BodyId>,
    pub(crate) brother: Option<BodyId>,
    pub(crate) joint_model: JointModel,
    pub(crate) joint: Joint,
    pub(crate) placement: Isometry3<f64>,
    /// Placement as a transform: `rot = A_k'p`, `trans` = joint origin in the parent frame.
    pub(crate) placement_x: SpatialTransform,
    pub(crate) inertia: RigidInertia,
    pub(crate) q_index: usize,
    pub(crate) v_index: usize,
    /// Index set into `q` (2.26).
    pub(crate) q_set: IndexSet,
    /// Index set into `v` (2.26), one entry per column of `J_i`.
    pub(crate) v_set: IndexSet,
    /// Whether the body owns its index set (false for geared rotors).
    pub(crate) owns_coordinates: bool,
}

impl Body {
    /// Body name.
    pub fn name(&self) -> &str {
        &self.name
    }
    /// Name of the joint to the parent.
    pub fn joint_name(&self) -> &str {
        &self.joint_name
    }
    /// Parent body `p(i)` (`None` = the fixed world frame).
    pub fn parent(&self) -> Option<BodyId> {
        self.parent
    }
    /// First child `c` (Fig. 2.7).
    pub fn first_child(&self) -> Option<BodyId> {
        self.first_child
    }
    /// Next child of the same parent, the brother `b` (Fig. 2.7).
    pub fn brother(&self) -> Option<BodyId> {
        self.brother
    }
    /// Joint model to the parent.
    pub fn joint(&self) -> &JointModel {
        &self.joint_model
    }
    /// Pose of the joint frame in the parent body frame.
    pub fn placement(&self) -> &Isometry3<f64> {
        &self.placement
    }
    /// Inertia in the body frame.
    pub fn inertia(&self) -> &RigidInertia {
        &self.inertia
    }
    /// First index of the body's index set in `q` (where its coordinates would start if empty).
    pub fn q_index(&self) -> usize {
        self.q_index
    }
    /// First index of the body's index set in `v` (where its coordinates would start if empty).
    pub fn v_index(&self) -> usize {
        self.v_index
    }
    /// Index set into `q` (2.26).
    pub fn q_set(&self) -> &IndexSet {
        &self.q_set
    }
    /// Index set into `v` (2.26): the coordinates of the columns of `J_i` (2.35).
    pub fn v_set(&self) -> &IndexSet {
        &self.v_set
    }
    /// False if the index set is borrowed from another body (geared rotors).
    pub fn owns_coordinates(&self) -> bool {
        self.owns_coordinates
    }
}

/// Immutable multibody model (topology, joints, inertias, gravity).
///
/// Built once, by [`ModelBuilder`] (bodies parent-first), by [`crate::urdf::load_file`] or by
/// [`crate::dill::dill`]; every algorithm takes it by reference together with a [`crate::Data`]
/// workspace made for it.
///
/// # Examples
///
/// A floating box carrying an arm with one revolute joint: the free quaternion joint has
/// `nq = 7`, `nv = 6`, the revolute joint one of each.
///
/// ```
/// use biped_dynamics::{BodySpec, JointModel, ModelBuilder, RigidInertia};
/// use nalgebra::{Isometry3, Matrix3, Vector3};
///
/// let inertia = RigidInertia::new(1.0, Vector3::zeros(), Matrix3::identity() * 0.01)?;
/// let mut b = ModelBuilder::new();
/// let base = b.add_body(BodySpec::named(
///     "base", None, JointModel::FreeQuaternion, Isometry3::identity(), inertia,
/// ))?;
/// b.add_body(BodySpec::named(
///     "arm",
///     Some(base),
///     JointModel::Revolute { axis: Vector3::z_axis() },
///     Isometry3::translation(0.0, 0.0, 0.2),
///     inertia,
/// ))?;
/// let model = b.build()?;
/// assert_eq!((model.nq(), model.nv(), model.nbodies()), (8, 7, 2));
/// assert_eq!(model.body_names(), ["base", "arm"]);
/// assert_eq!(model.body_id("arm"), Some(1));
/// // neutral: base at the origin with the identity quaternion [0, 0, 0, 1], arm at 0
/// assert_eq!(model.neutral().as_slice(), &[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// From the bundled Unitree G1 URDF with a floating base: 29 revolute joints plus the free
/// root, and the total mass equals the sum of the file's `<mass>` tags (fixed joints merge
/// links, they do not drop them).
///
/// ```
/// use biped_dynamics::urdf::{load_file, UrdfOptions};
/// use biped_dynamics::{center_of_mass, Data};
///
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/g1_29dof_rev_1_0.urdf");
/// let options = UrdfOptions { floating: true, ..UrdfOptions::default() };
/// let model = load_file(path, &options)?.model;
/// assert_eq!((model.nq(), model.nv()), (7 + 29, 6 + 29));
/// assert_eq!(model.joints().len(), 30); // "root" and the 29 revolute joints
///
/// let text = std::fs::read_to_string(path)?;
/// let mut file_mass = 0.0;
/// for tail in text.split("<mass value=\"").skip(1) {
///     file_mass += tail[..tail.find('"').unwrap()].parse::<f64>()?;
/// }
/// let mut data = Data::new(&model);
/// let com = center_of_mass(&model, &mut data, &model.neutral(), None)?;
/// assert!((com.mass - file_mass).abs() < 1e-9 && (file_mass - 33.34).abs() < 0.01);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct Model {
    pub(crate) bodies: Vec<Body>,
    pub(crate) joints: Vec<JointInfo>,
    pub(crate) nq: usize,
    pub(crate) nv: usize,
    pub(crate) gravity: Vector3<f64>,
    /// Parent array over velocity coordinates (`lambda` of the sparse LTL factorisation).
    pub(crate) dof_parent: Vec<Option<usize>>,
    /// The ancestors of each velocity coordinate in `dof_parent`, nearest first.
    pub(crate) dof_ancestors: ancestors::DofAncestors,
    pub(crate) has_rotors: bool,
    /// Sub-systems generated from overlapping index sets (2.9).
    pub(crate) subsystems: Vec<Subsystem>,
    /// Rewired body list with sub-system nodes (Fig. 2.14).
    pub(crate) nodes: Vec<Node>,
}

impl Model {
    /// Number of position coordinates.
    pub fn nq(&self) -> usize {
        self.nq
    }
    /// Number of velocity coordinates (DoFs).
    pub fn nv(&self) -> usize {
        self.nv
    }
    /// Number of bodies.
    pub fn nbodies(&self) -> usize {
        self.bodies.len()
    }
    /// Total mass: the sum of the bodies' masses \[kg].
    pub fn mass(&self) -> f64 {
        self.bodies.iter().map(|b| b.inertia().mass()).sum()
    }
    /// Joints with coordinates, in coordinate order.
    pub fn joints(&self) -> &[JointInfo] {
        &self.joints
    }
    /// Body names in body-list order.
    pub fn body_names(&self) -> Vec<&str> {
        self.bodies.iter().map(|b| b.name.as_str()).collect()
    }
    /// Bodies in body-list order.
    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }
    /// One body.
    pub fn body(&self, id: BodyId) -> Option<&Body> {
        self.bodies.get(id)
    }
    /// Neutral configuration: zeros, identity quaternion `[0, 0, 0, 1]` for free joints.
    pub fn neutral(&self) -> DVector<f64> {
        let mut q = DVector::zeros(self.nq);
        for b in &self.bodies {
            if matches!(b.joint, Joint::Quaternion) {
                q[b.q_index + 6] = 1.0;
            }
        }
        q
    }
    /// Gravity in the world frame.
    pub fn gravity(&self) -> Vector3<f64> {
        self.gravity
    }
    /// Body index by name.
    pub fn body_id(&self, name: &str) -> Option<BodyId> {
        self.bodies.iter().position(|b| b.name == name)
    }
    /// Parent of each velocity coordinate in the tree of DoFs (`lambda`, thesis 2.10.1).
    pub fn dof_parents(&self) -> &[Option<usize>] {
        &self.dof_parent
    }
    /// Whether some body shares its driver's coordinates instead of owning its own: a geared
    /// or Harmonic Drive rotor, or a coupled part of a closed-form mechanism.
    pub fn has_rotors(&self) -> bool {
        self.has_rotors
    }
    /// Sub-systems built automatically from bodies sharing coordinates (section 2.9).
    pub fn subsystems(&self) -> &[Subsystem] {
        &self.subsystems
    }
    /// Member body names of every sub-system, in sub-system order.
    pub fn subsystem_names(&self) -> Vec<Vec<&str>> {
        self.subsystems
            .iter()
            .map(|s| {
                s.members
                    .iter()
                    .map(|&m| self.bodies[m].name.as_str())
                    .collect()
            })
            .collect()
    }
    /// Rewired body list: bodies outside sub-systems and sub-system nodes (Fig. 2.14).
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }
}
