//! One-DoF joint motion subspaces with zero pruning (end of section 2.4.4).

use super::{ArticulatedInertia, Force, Motion};
use nalgebra::{Matrix3, Unit, Vector3};

/// A joint axis: a coordinate axis of the joint frame (pruned products) or a general unit vector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Axis {
    /// `e_x`.
    X,
    /// `e_y`.
    Y,
    /// `e_z` (the thesis' standard revolute/prismatic axis, (2.45), (2.47)).
    Z,
    /// Any other unit vector.
    General(Vector3<f64>),
}

impl Axis {
    /// Classifies a unit vector, snapping to a coordinate axis when it is one (to 1e-12).
    pub fn from_unit(u: &Unit<Vector3<f64>>) -> Self {
        let v = u.into_inner();
        let tol = 1e-12;
        if (v - Vector3::x()).amax() < tol {
            Axis::X
        } else if (v - Vector3::y()).amax() < tol {
            Axis::Y
        } else if (v - Vector3::z()).amax() < tol {
            Axis::Z
        } else {
            Axis::General(v)
        }
    }

    /// The axis as a 3-vector.
    #[inline]
    pub fn vector(&self) -> Vector3<f64> {
        match self {
            Axis::X => Vector3::x(),
            Axis::Y => Vector3::y(),
            Axis::Z => Vector3::z(),
            Axis::General(v) => *v,
        }
    }

    /// `axis . w` (picks one component for coordinate axes).
    #[inline]
    pub fn dot(&self, w: &Vector3<f64>) -> f64 {
        match self {
            Axis::X => w.x,
            Axis::Y => w.y,
            Axis::Z => w.z,
            Axis::General(v) => v.dot(w),
        }
    }

    /// `m axis` (picks one column for coordinate axes).
    #[inline]
    pub fn mat_mul(&self, m: &Matrix3<f64>) -> Vector3<f64> {
        match self {
            Axis::X => m.column(0).into(),
            Axis::Y => m.column(1).into(),
            Axis::Z => m.column(2).into(),
            Axis::General(v) => m * v,
        }
    }

    /// `m^T axis` (picks one row for coordinate axes).
    #[inline]
    pub fn tr_mat_mul(&self, m: &Matrix3<f64>) -> Vector3<f64> {
        match self {
            Axis::X => m.row(0).transpose(),
            Axis::Y => m.row(1).transpose(),
            Axis::Z => m.row(2).transpose(),
            Axis::General(v) => m.tr_mul(v),
        }
    }

    /// Rotation matrix about this axis by the angle with the given sine and cosine.
    pub fn rotation(&self, s: f64, c: f64) -> Matrix3<f64> {
        match self {
            Axis::X => Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c),
            Axis::Y => Matrix3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c),
            Axis::Z => Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0),
            Axis::General(u) => {
                let k = super::skew(u);
                Matrix3::identity() + k * s + k * k * (1.0 - c)
            }
        }
    }

    /// `Rot(axis, angle)^T m` with the rotation's sine and cosine, exploiting coordinate axes
    /// (the revolute-joint product `A_z(q) A_k'p` of (2.46) costs 12 multiplications).
    #[inline]
    pub fn rot_tr_mul(&self, s: f64, c: f64, m: &Matrix3<f64>) -> Matrix3<f64> {
        let (r0, r1, r2) = (m.row(0), m.row(1), m.row(2));
        match self {
            Axis::X => Matrix3::from_rows(&[r0.into(), (r1 * c + r2 * s), (r2 * c - r1 * s)]),
            Axis::Y => Matrix3::from_rows(&[(r0 * c - r2 * s), r1.into(), (r2 * c + r0 * s)]),
            Axis::Z => Matrix3::from_rows(&[(r0 * c + r1 * s), (r1 * c - r0 * s), r2.into()]),
            Axis::General(_) => self.rotation(s, c).tr_mul(m),
        }
    }
}

/// Whether a one-DoF subspace is a rotation or a translation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SubspaceKind {
    /// `S = [scale axis; 0]` (revolute joint (2.45), geared rotor (3.1)).
    Angular,
    /// `S = [0; scale axis]` (prismatic joint (2.47)).
    Linear,
}

/// One-column relative Jacobian `J_i = S` of a one-DoF joint in child coordinates, pruned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointAxis {
    /// Direction in the child (and joint) frame.
    pub axis: Axis,
    /// Rotation or translation.
    pub kind: SubspaceKind,
    /// Scale (1 for plain joints, the gear ratio `N` of (3.1) for rotors).
    pub scale: f64,
}

impl JointAxis {
    /// Relative motion `S qdot`.
    #[inline]
    pub fn motion(&self, qd: f64) -> Motion {
        let w = self.axis.vector() * (self.scale * qd);
        match self.kind {
            SubspaceKind::Angular => Motion::new(w, Vector3::zeros()),
            SubspaceKind::Linear => Motion::new(Vector3::zeros(), w),
        }
    }

    /// `S^T f` (one component of the force for coordinate axes).
    #[inline]
    pub fn dot_force(&self, f: &Force) -> f64 {
        self.scale
            * match self.kind {
                SubspaceKind::Angular => self.axis.dot(&f.ang),
                SubspaceKind::Linear => self.axis.dot(&f.lin),
            }
    }

    /// `S^T m` for a motion, used when a subspace column is paired with an acceleration.
    #[inline]
    pub fn dot_motion(&self, m: &Motion) -> f64 {
        self.scale
            * match self.kind {
                SubspaceKind::Angular => self.axis.dot(&m.ang),
                SubspaceKind::Linear => self.axis.dot(&m.lin),
            }
    }

    /// `U = I S` for an inertia `I = [A B; B^T D]` (column picks for coordinate axes).
    #[inline]
    pub fn apply_inertia(&self, inertia: &ArticulatedInertia) -> Force {
        let f = match self.kind {
            SubspaceKind::Angular => Force::new(
                self.axis.mat_mul(&inertia.ang),
                self.axis.tr_mat_mul(&inertia.cross),
            ),
            SubspaceKind::Linear => Force::new(
                self.axis.mat_mul(&inertia.cross),
                self.axis.mat_mul(&inertia.lin),
            ),
        };
        f * self.scale
    }
}
