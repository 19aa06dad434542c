//! Generic tasks on any model: what a [`super::TaskStack`] row block measures and where it
//! should be.
//!
//! Every task is an error `x_d - x(q)` with a geometric Jacobian (Appendix C), in the
//! conventions of [`crate::ik::TaskMap`]:
//! - frame position: the world position of a point fixed in a body, `J = J_p`;
//! - frame orientation: `log(A_d A^T)` (C.1) in world axes, `J = J_w`;
//! - frame pose: position rows then orientation rows;
//! - relative position: `x = A_r^T (p - p_r)` in the axes of a reference frame,
//!   `J = A_r^T (J_p - J_p,r(p))` with `J_p,r(p)` the Jacobian of the point of the reference
//!   body that coincides with `p` (since `xdot = A_r^T (pdot - pdot_r - w_r x (p - p_r))`);
//! - relative orientation: `R = A_r^T A`, error `log(R_d R^T)` in reference axes,
//!   `J = A_r^T (J_w - J_w,r)` (since `dR/dt = [A_r^T (w - w_r)]x R`);
//! - offset of one point from another in fixed axes `A` (a frame origin, the CoM or the CoM
//!   of a subtree, e.g. a foot from the CoM in a yawed planning frame): `x = A^T (p - p_from)`,
//!   `J = A^T (J_p - J_from)`; a subtree CoM has `J = sum m_b J_p(b, c_b) / sum m_b`;
//! - centre of mass: `J = J_C`;
//! - posture: every joint with a range towards a configuration, `J = E` on those columns;
//! - joint: one coordinate, `J = e_i^T`;
//! - angular momentum about the CoM (7.2): a velocity-level task `J_L v = L_d` (or its
//!   vertical row `J_Lz`, 7.3), error 0 and the target as feed-forward velocity.

use nalgebra::{DVector, Isometry3, Matrix3, Vector3};

/// A frame fixed in a body of the model: the body and the frame's pose in the body frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Body index in the model.
    pub body: usize,
    /// Pose of the frame in the body frame (identity: the body frame itself).
    pub offset: Isometry3<f64>,
}

impl Frame {
    /// The frame of body `body` itself.
    pub fn body(body: usize) -> Self {
        Self {
            body,
            offset: Isometry3::identity(),
        }
    }
}

/// A point that a task can follow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Point {
    /// The origin of a frame.
    Frame(Frame),
    /// The centre of mass of the whole model.
    Com,
    /// The centre of mass of the subtree rooted at this body (the body included).
    SubtreeCom(usize),
}

impl Point {
    /// Whether following the point needs the centroidal quantities.
    fn is_com(&self) -> bool {
        matches!(self, Point::Com)
    }
}

/// Which rows of the angular momentum `L` a momentum task controls.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MomentumAxes {
    /// Only the vertical component `L_z` (one row, `J_Lz`).
    Vertical,
    /// All three components (three rows, `J_L`).
    All,
}

/// What a task measures, with its target.
#[derive(Debug, Clone, PartialEq)]
pub enum TaskKind {
    /// World position of a frame's origin.
    Position {
        /// The frame.
        frame: Frame,
        /// Target position (world) \[m].
        target: Vector3<f64>,
    },
    /// World orientation of a frame.
    Orientation {
        /// The frame.
        frame: Frame,
        /// Target orientation (columns = frame axes in world).
        target: Matrix3<f64>,
    },
    /// World pose of a frame (position rows, then orientation rows).
    Pose {
        /// The frame.
        frame: Frame,
        /// Target pose (world).
        target: Isometry3<f64>,
    },
    /// Position of a frame's origin in the axes of a reference frame, relative to its origin.
    RelativePosition {
        /// The moving frame.
        frame: Frame,
        /// The reference frame.
        reference: Frame,
        /// Target position in the reference frame \[m].
        target: Vector3<f64>,
    },
    /// Orientation of a frame relative to a reference frame (`A_r^T A`).
    RelativeOrientation {
        /// The moving frame.
        frame: Frame,
        /// The reference frame.
        reference: Frame,
        /// Target relative orientation.
        target: Matrix3<f64>,
    },
    /// Offset of `point` from `from` in the fixed axes `axes` (columns: the axes in world
    /// coordinates): `x = axes^T (p - p_from)`.
    Offset {
        /// The point that moves.
        point: Point,
        /// The point it is measured from.
        from: Point,
        /// The axes of the offset (e.g. a planning frame yawed about the vertical).
        axes: Matrix3<f64>,
        /// Target offset in `axes` \[m].
        target: Vector3<f64>,
    },
    /// Centre of mass of the whole model (world).
    Com {
        /// Target CoM \[m].
        target: Vector3<f64>,
    },
    /// The listed joints `(q_index, v_index)` towards the entries of a configuration.
    Posture {
        /// Joints of the task.
        joints: Vec<(usize, usize)>,
        /// Target configuration (length nq; only the listed joints' entries are used).
        target: DVector<f64>,
    },
    /// One joint coordinate.
    Joint {
        /// Index into q.
        q_index: usize,
        /// Index into v.
        v_index: usize,
        /// Target value \[rad or m].
        target: f64,
    },
    /// Angular momentum about the CoM, world axes (7.2): `J_L v = L_d`.
    AngularMomentum {
        /// Which components.
        axes: MomentumAxes,
        /// Target `L_d` \[N m s] (for [`MomentumAxes::Vertical`] only `z` is used).
        target: Vector3<f64>,
    },
}

impl TaskKind {
    /// Number of rows.
    pub fn dim(&self) -> usize {
        match self {
            TaskKind::Pose { .. } => 6,
            TaskKind::Posture { joints, .. } => joints.len(),
            TaskKind::Joint { .. } => 1,
            TaskKind::AngularMomentum { axes, .. } => match axes {
                MomentumAxes::Vertical => 1,
                MomentumAxes::All => 3,
            },
            _ => 3,
        }
    }

    /// Whether evaluating the task needs the centroidal quantities (CoM, `A_G`).
    pub fn needs_centroidal(&self) -> bool {
        match self {
            TaskKind::Com { .. } | TaskKind::AngularMomentum { .. } => true,
            TaskKind::Offset { point, from, .. } => point.is_com() || from.is_com(),
            _ => false,
        }
    }
}

/// One task of a [`super::TaskStack`]: what it measures, how it is weighted and its target
/// velocity.
#[derive(Debug, Clone, PartialEq)]
pub struct Task {
    /// What the task measures, with its target.
    pub kind: TaskKind,
    /// `None`: a hard task (kept exactly while feasible); `Some(w)`: a soft one, the penalty
    /// `w |xd - J qd|^2 / 2` against the joint velocity norm (row softness `1 / w`).
    pub weight: Option<f64>,
    /// Feed-forward task velocity `xd_d` of the first rows (up to 6; posture rows get 0).
    pub velocity: [f64; 6],
    /// Whether the task is stacked (an inactive task keeps its place but has no rows).
    pub active: bool,
}

impl Task {
    /// A hard task with zero target velocity.
    pub fn hard(kind: TaskKind) -> Self {
        Self {
            kind,
            weight: None,
            velocity: [0.0; 6],
            active: true,
        }
    }

    /// A soft task of weight `w` with zero target velocity.
    pub fn soft(kind: TaskKind, w: f64) -> Self {
        Self {
            weight: Some(w),
            ..Self::hard(kind)
        }
    }
}
