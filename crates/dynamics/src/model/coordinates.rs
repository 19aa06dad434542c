//! Names of the coordinates of `q` and `v`, for tables and recorded signals that people read.

use super::{JointInfo, Model};

/// Position and velocity coordinate names of a free joint with a quaternion (Pinocchio's
/// order: position, then `x y z w` of the quaternion; linear, then angular velocity).
const FREE_QUATERNION: ([&str; 7], [&str; 6]) = (
    ["x", "y", "z", "qx", "qy", "qz", "qw"],
    ["vx", "vy", "vz", "wx", "wy", "wz"],
);

impl JointInfo {
    /// Name of its `k`-th position (`velocity = false`) or velocity coordinate: the joint's
    /// name for a one-coordinate joint, `NAME.x` .. `NAME.qw` / `NAME.vx` .. `NAME.wz` for a
    /// quaternion free joint, `NAME.k` otherwise.
    pub fn coordinate_name(&self, k: usize, velocity: bool) -> String {
        let n = if velocity { self.nv } else { self.nq };
        if n == 1 {
            return self.name.clone();
        }
        let (q, v) = FREE_QUATERNION;
        let label = match (self.nq, self.nv, velocity) {
            (7, 6, false) => q.get(k).map(|s| s.to_string()),
            (7, 6, true) => v.get(k).map(|s| s.to_string()),
            _ => None,
        };
        format!("{}.{}", self.name, label.unwrap_or_else(|| k.to_string()))
    }
}

impl Model {
    /// Names of every position coordinate, in `q` order ([`JointInfo::coordinate_name`]).
    pub fn q_names(&self) -> Vec<String> {
        let joints = self.joints().iter();
        joints
            .flat_map(|j| (0..j.nq).map(move |k| j.coordinate_name(k, false)))
            .collect()
    }

    /// Names of every velocity coordinate, in `v` order ([`JointInfo::coordinate_name`]).
    pub fn v_names(&self) -> Vec<String> {
        let joints = self.joints().iter();
        joints
            .flat_map(|j| (0..j.nv).map(move |k| j.coordinate_name(k, true)))
            .collect()
    }
}
