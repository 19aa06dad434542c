//! The full planned motion of a walk at the control rate, for replay by a viewer or a script:
//! every position coordinate, the CoM, the ZMP, both sole frames and the ground wrench.

use super::controller::WalkController;
use super::evaluate::CycleMetrics;
use crate::tasks::Frame;
use nalgebra::{Isometry3, Rotation3, Vector3};

/// One walk's motion, one row per control cycle (SI units, world frame, ground `z = 0`).
#[derive(Debug, Clone, Default)]
pub struct Trajectory {
    /// Names of the position coordinates (`Model::q_names`: `joint`, `root.x` ..
    /// `root.qw` for the floating base).
    pub q_names: Vec<String>,
    /// Time \[s].
    pub t: Vec<f64>,
    /// Positions, `q_names.len()` per row.
    pub q: Vec<f64>,
    /// Centre of mass \[m].
    pub com: Vec<[f64; 3]>,
    /// ZMP (centre of pressure of the ground wrench) \[m].
    pub zmp: Vec<[f64; 2]>,
    /// Sole frames `[left, right]` as `x, y, z, qx, qy, qz, qw`.
    pub soles: Vec<[[f64; 7]; 2]>,
    /// Ground force `f_x, f_y, f_z` \[N] and free moment about the vertical through the ZMP
    /// \[N m]: the total over both feet (its split in double support is not determined by a
    /// kinematic plan).
    pub ground: Vec<[f64; 4]>,
}

impl Trajectory {
    /// Empty trajectory of `cycles` rows with coordinate names `q_names`.
    pub fn with_capacity(q_names: Vec<String>, cycles: usize) -> Self {
        let nq = q_names.len();
        Self {
            q_names,
            t: Vec::with_capacity(cycles),
            q: Vec::with_capacity(cycles * nq),
            com: Vec::with_capacity(cycles),
            zmp: Vec::with_capacity(cycles),
            soles: Vec::with_capacity(cycles),
            ground: Vec::with_capacity(cycles),
        }
    }

    /// Appends the cycle `ctrl` has just run at time `t`, evaluated as `m`, with the sole
    /// frames `soles` (`[left, right]`).
    pub fn push(&mut self, t: f64, ctrl: &WalkController, m: &CycleMetrics, soles: [Frame; 2]) {
        let (data, _) = ctrl.kinematics();
        self.t.push(t);
        self.q.extend(ctrl.q_eval().iter());
        self.com.push(vec3(&ctrl.tasks().centroidal().com()));
        self.zmp.push([m.friction.cop.x, m.friction.cop.y]);
        self.soles.push(soles.map(|f| {
            let rot = Rotation3::from_matrix_unchecked(data.world_rot[f.body]);
            let body = Isometry3::from_parts(data.world_pos[f.body].into(), rot.into());
            pose7(&(body * f.offset))
        }));
        let f = &m.force;
        self.ground.push([f.x, f.y, f.z, m.friction.free_moment]);
    }

    /// Number of rows.
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// True without rows.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// Positions of row `k`.
    pub fn q_row(&self, k: usize) -> &[f64] {
        let n = self.q_names.len();
        &self.q[k * n..(k + 1) * n]
    }

    /// Column names and values of row `k` in the order of the trajectory file: `q[NAME]` per
    /// coordinate, `com.x/y/z`, `zmp.x/y`, `l_sole.x/y/z/qx/qy/qz/qw`, `r_sole.*`,
    /// `ground.fx/fy/fz/tau_n`.
    pub fn columns(&self) -> Vec<String> {
        let mut c: Vec<String> = self.q_names.iter().map(|n| format!("q[{n}]")).collect();
        c.extend(["com.x", "com.y", "com.z", "zmp.x", "zmp.y"].map(String::from));
        for side in ["l_sole", "r_sole"] {
            c.extend(["x", "y", "z", "qx", "qy", "qz", "qw"].map(|k| format!("{side}.{k}")));
        }
        c.extend(["ground.fx", "ground.fy", "ground.fz", "ground.tau_n"].map(String::from));
        c
    }

    /// Values of row `k` in the order of [`Self::columns`].
    pub fn row(&self, k: usize) -> impl Iterator<Item = f64> + '_ {
        let [l, r] = &self.soles[k];
        self.q_row(k)
            .iter()
            .chain(&self.com[k])
            .chain(&self.zmp[k])
            .chain(l)
            .chain(r)
            .chain(&self.ground[k])
            .copied()
    }
}

fn vec3(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// `x, y, z, qx, qy, qz, qw` of a pose.
fn pose7(p: &Isometry3<f64>) -> [f64; 7] {
    let (t, q) = (&p.translation.vector, &p.rotation);
    [t.x, t.y, t.z, q.i, q.j, q.k, q.w]
}
