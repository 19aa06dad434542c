//! Typed errors of model construction and of the dynamics algorithms.

use crate::mechanism::MechanismError;
use thiserror::Error;

/// Invalid model input, reported by [`crate::RigidInertia::new`] and [`crate::ModelBuilder`].
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ModelError {
    /// A body's parent index does not exist yet (parents must be added before children).
    #[error("body `{body}`: parent index {parent} does not exist yet ({nbodies} bodies added; parents must precede children)")]
    UnknownParent {
        /// Name of the offending body.
        body: String,
        /// Requested parent index.
        parent: usize,
        /// Number of bodies added so far.
        nbodies: usize,
    },
    /// A body names itself as its parent (a cycle).
    #[error("body `{body}` would be its own parent (cycle)")]
    CyclicParent {
        /// Name of the offending body.
        body: String,
    },
    /// Two bodies share a name.
    #[error("duplicate body name `{0}`")]
    DuplicateBodyName(String),
    /// Two joints share a name.
    #[error("duplicate joint name `{0}`")]
    DuplicateJointName(String),
    /// A joint placement contains NaN or infinity.
    #[error("body `{body}`: non-finite joint placement")]
    NonFinitePlacement {
        /// Name of the offending body.
        body: String,
    },
    /// Mass, CoM or inertia contains NaN or infinity.
    #[error("non-finite mass, centre of mass or inertia")]
    NonFiniteInertia,
    /// Negative mass.
    #[error("negative mass {mass}")]
    NegativeMass {
        /// The mass given.
        mass: f64,
    },
    /// The rotational inertia matrix is not symmetric.
    #[error("inertia matrix not symmetric (max asymmetry {asymmetry})")]
    InertiaNotSymmetric {
        /// Largest absolute difference `|I - I^T|`.
        asymmetry: f64,
    },
    /// The rotational inertia has a negative principal moment (not positive semi-definite).
    #[error("inertia matrix not positive (semi-)definite: principal moment {min_moment}")]
    InertiaNotPositive {
        /// Smallest principal moment.
        min_moment: f64,
    },
    /// The principal moments violate `I1 + I2 >= I3`.
    #[error("principal moments {moments:?} violate the triangle inequality")]
    TriangleInequality {
        /// Principal moments, ascending.
        moments: [f64; 3],
    },
    /// A joint axis is zero or not finite.
    #[error("body `{body}`: zero or non-finite joint axis")]
    ZeroAxis {
        /// Name of the offending body.
        body: String,
    },
    /// A geared rotor's gear ratio is zero or not finite.
    #[error("body `{body}`: invalid gear ratio {ratio}")]
    InvalidGearRatio {
        /// Name of the offending body.
        body: String,
        /// The ratio given.
        ratio: f64,
    },
    /// A geared rotor's driver is not an existing one-DoF body compatible with the tree.
    #[error("rotor `{body}`: bad driver body {driver}: {reason}")]
    BadDriver {
        /// Name of the rotor body.
        body: String,
        /// Driver index given.
        driver: usize,
        /// Why it was rejected.
        reason: &'static str,
    },
    /// Bodies cannot be attached to a geared rotor (rotors are leaves).
    #[error("body `{body}`: parent `{rotor}` is a geared rotor; rotors must be leaves")]
    ChildOfRotor {
        /// Name of the offending body.
        body: String,
        /// Name of the rotor.
        rotor: String,
    },
    /// Gravity contains NaN or infinity.
    #[error("non-finite gravity vector")]
    NonFiniteGravity,
    /// Coordinate-sharing bodies form a sub-system with too many coordinates (2.6).
    #[error(
        "body `{body}`: its sub-system spans {dof} coordinates, more than the supported {max}"
    )]
    SubsystemTooLarge {
        /// Name of the sub-system's first member body.
        body: String,
        /// Coordinates the sub-system would span.
        dof: usize,
        /// Largest supported sub-system size.
        max: usize,
    },
}

/// Invalid input to, or failure of, a kinematics/dynamics computation.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DynamicsError {
    /// An argument has the wrong length.
    #[error("argument `{argument}` has length {got}, expected {expected}")]
    DimensionMismatch {
        /// Which argument.
        argument: &'static str,
        /// Expected length.
        expected: usize,
        /// Actual length.
        got: usize,
    },
    /// An argument contains NaN or infinity.
    #[error("argument `{argument}` has a non-finite entry at index {index}")]
    NonFinite {
        /// Which argument.
        argument: &'static str,
        /// Index of the first offending entry.
        index: usize,
    },
    /// A free-joint quaternion in `q` is (numerically) zero.
    #[error("quaternion at q[{q_index}..] has zero norm")]
    ZeroQuaternion {
        /// Index of the quaternion's first component in `q`.
        q_index: usize,
    },
    /// A free-joint quaternion in `q` has a norm farther from 1 than
    /// [`crate::configuration::QUATERNION_NORM_TOLERANCE`] (it is normalised only within it).
    #[error("joint `{joint}`: quaternion at q[{q_index}..] has norm {norm:e}, more than {tolerance} from 1 (pass a unit quaternion)")]
    QuaternionNorm {
        /// Name of the free joint.
        joint: String,
        /// Index of the quaternion's first component in `q`.
        q_index: usize,
        /// Its Euclidean norm (computed without overflow).
        norm: f64,
        /// The accepted deviation of the norm from 1.
        tolerance: f64,
    },
    /// The workspace for a dense result could not be allocated (the model is too large).
    #[error(
        "cannot allocate the {rows} x {rows} {what} ({:.3e} bytes): model too large for a dense matrix",
        (*.rows as f64).powi(2) * 8.0
    )]
    Allocation {
        /// Which workspace.
        what: &'static str,
        /// Its number of rows (and columns), of 8 bytes each.
        rows: usize,
    },
    /// A (projected) mass matrix is not positive definite, e.g. at a singular Euler angle.
    #[error("mass matrix not positive definite (pivot {pivot} at coordinate {index})")]
    NotPositiveDefinite {
        /// Velocity coordinate (or body, for 6-DoF joints) where factorisation failed.
        index: usize,
        /// Offending pivot.
        pivot: f64,
    },
    /// A coupled part's mechanism cannot be evaluated at the given coordinates.
    #[error("coupled body {body}: {source}")]
    Mechanism {
        /// Index of the coupled body.
        body: usize,
        /// What the mechanism reported.
        source: MechanismError,
    },
    /// [`crate::forward_dynamics_solve`] without current kinematics from
    /// [`crate::forward_dynamics_kinematics`] (none yet, or another kinematics call since).
    #[error("forward_dynamics_solve needs a preceding forward_dynamics_kinematics on this data")]
    KinematicsNotCurrent,
    /// The algorithm does not support a feature of the model.
    #[error("algorithm not supported for this model: {0}")]
    Unsupported(&'static str),
    /// A result overflowed to infinity or NaN although every input was finite (inputs too
    /// large for `f64`, e.g. a body of 1e308 kg).
    #[error(
        "result `{quantity}` is non-finite at index {index} (finite inputs too large for f64)"
    )]
    NonFiniteResult {
        /// Which result.
        quantity: &'static str,
        /// Index of the first offending entry.
        index: usize,
    },
}
