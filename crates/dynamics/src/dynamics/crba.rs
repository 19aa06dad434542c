//! Composite-rigid-body algorithm: the joint-space mass matrix `M = sum_i Jbar_i^T M_i Jbar_i`.
//!
//! Works on *joint instances*: every body with a non-empty index set contributes its columns
//! `J_i` to the coordinates of its index set, so geared rotors sharing their driver's
//! coordinate (3.1) are handled exactly (contributions are accumulated).
//!
//! Evaluated in world axes about the world origin: body inertias (13 numbers each,
//! [`CompositeInertia`]) and Jacobian columns are mapped there once, so composite inertias
//! accumulate by plain addition and every entry `M_jk = S_j . (I^c_i S_i)` of an ancestor
//! column `j` is a single 6-D dot product. The ancestor columns of every body are a few index
//! ranges built with the workspace ([`ColumnAncestors`]), so the fill walks no parent chains.

use crate::kinematics::joint_column as column;
use crate::model::joint::Joint;
use crate::model::Body;
use crate::spatial::{CompositeInertia, Motion, SpatialTransform, SubspaceKind};
use crate::{Data, Model};
use nalgebra::{Matrix3, Vector3};
use std::ops::Range;

/// Per body, the Jacobian columns of its strict ancestors as indices into `Data::col_world`,
/// in runs of consecutive indices (a chain numbered in order is one run, so the lists take
/// memory linear in the model for chains), nearest first; and each column's coordinate.
#[derive(Clone, Debug, Default)]
pub(crate) struct ColumnAncestors {
    /// `runs[start[i]..start[i + 1]]` are the ancestor columns of body `i`.
    start: Vec<usize>,
    runs: Vec<Range<usize>>,
    /// Coordinate (row and column of `M`) of every column, indexed like `col_world`.
    coord: Vec<usize>,
    /// Number of entry updates of one fill (own column pairs, twice each ancestor pair).
    writes: usize,
}

impl ColumnAncestors {
    /// The lists of `model`, with `col_offset` the first column of each body.
    pub(crate) fn new(model: &Model, col_offset: &[usize]) -> Self {
        let mut out = Self::default();
        for (i, body) in model.bodies.iter().enumerate() {
            out.start.push(out.runs.len());
            out.coord.extend_from_slice(body.v_set.as_slice());
            let mut j = i;
            while let Some(p) = model.bodies[j].parent {
                j = p;
                let cols = col_offset[j]..col_offset[j] + model.bodies[j].v_set.len();
                let own = out.runs.len() > out.start[i];
                match out.runs.last_mut() {
                    _ if cols.is_empty() => {}
                    Some(r) if own && r.start == cols.end => r.start = cols.start,
                    _ => out.runs.push(cols),
                }
            }
        }
        out.start.push(out.runs.len());
        out.writes = (model.bodies.iter().enumerate())
            .map(|(i, b)| {
                let anc: usize = out.runs[out.start[i]..out.start[i + 1]]
                    .iter()
                    .map(Range::len)
                    .sum();
                b.v_set.len() * (b.v_set.len() + 2 * anc)
            })
            .sum();
        out
    }

    /// How the sparse solve should clear `M`: by its pattern where that touches under a
    /// sixteenth of the `nv^2` entries (Dill(8) and up), else all of it (a memset streams
    /// ~16 entries per pattern entry's indexed store: TALOS and G1 measured 8-10 % slower
    /// with the pattern, Dill(8) 25 % faster).
    pub(crate) fn sparse_clear(&self, nv: usize) -> Clear {
        if self.writes.saturating_mul(16) < nv.saturating_mul(nv) {
            Clear::Pattern
        } else {
            Clear::All
        }
    }
}

/// What [`crba`] clears before it accumulates `M`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Clear {
    /// All `nv^2` entries: `M` is complete, zeros included.
    All,
    /// Only the entries the fill writes (the pattern of the tree): for the sparse solve,
    /// which reads no other entry, so that its memory traffic is linear in the pattern and
    /// not quadratic in `nv` (Dill(10): 8 MiB per call).
    Pattern,
}

/// Mass matrix into `data.mass` (symmetric storage) from the world poses in `data`; entries
/// off the tree pattern are zeroed with [`Clear::All`] and left as they were with
/// [`Clear::Pattern`].
pub(crate) fn crba(model: &Model, data: &mut Data, clear: Clear) {
    for (i, body) in model.bodies.iter().enumerate() {
        let (rot, pos) = (&data.world_rot[i], &data.world_pos[i]);
        data.ic[i] = CompositeInertia::from_body(&body.inertia, rot, pos);
        let offset = data.col_offset[i];
        for c in 0..body.v_set.len() {
            data.col_world[offset + c] = world_column(data, i, body, c);
        }
    }
    for i in (1..model.nbodies()).rev() {
        if let Some(p) = model.bodies[i].parent {
            let (head, tail) = data.ic.split_at_mut(i);
            head[p] += tail[0];
        }
    }
    if clear == Clear::All {
        data.mass.as_mut_slice().fill(0.0);
    } else {
        clear_pattern(model, data);
    }
    fill(model, data);
}

/// Zeroes the entries of `M` that [`fill`] accumulates into, and no other.
fn clear_pattern(model: &Model, data: &mut Data) {
    let n = model.nv;
    let (m, pattern) = (data.mass.as_mut_slice(), &data.column_ancestors);
    for (i, body) in model.bodies.iter().enumerate() {
        let own = data.col_offset[i]..data.col_offset[i] + body.v_set.len();
        let ancestors = &pattern.runs[pattern.start[i]..pattern.start[i + 1]];
        for k in own.clone() {
            let (row, col) = (pattern.coord[k], pattern.coord[k] * n);
            for j in own.clone() {
                m[pattern.coord[j] + col] = 0.0;
            }
            for j in ancestors.iter().flat_map(Range::clone) {
                let r = pattern.coord[j];
                (m[r + col], m[row + r * n]) = (0.0, 0.0);
            }
        }
    }
}

/// Column `c` of body `i`'s joint in world axes about the world origin: `[R s; p x R s]` for
/// a rotation axis `s` through the body origin `p`, `[0; R s]` for a translation (one column
/// of the body rotation for coordinate axes), the general transform otherwise.
#[inline]
fn world_column(data: &Data, i: usize, body: &Body, c: usize) -> Motion {
    let (rot, pos): (&Matrix3<f64>, &Vector3<f64>) = (&data.world_rot[i], &data.world_pos[i]);
    match &body.joint {
        Joint::Revolute(ax) | Joint::Prismatic(ax) | Joint::Rotor(ax) => {
            let s = ax.axis.mat_mul(rot) * ax.scale;
            match ax.kind {
                SubspaceKind::Angular => Motion::new(s, pos.cross(&s)),
                SubspaceKind::Linear => Motion::new(Vector3::zeros(), s),
            }
        }
        joint => {
            let to_world = SpatialTransform::new(rot.transpose(), *pos);
            to_world.inv_apply_motion(&column(data, i, joint, c))
        }
    }
}

/// `M_jk += S_j . (I^c_i S_k)` for every column `k` of every body `i` and every column `j` of
/// `i` itself or of an ancestor (both triangles for ancestors), onto the cleared `M`.
fn fill(model: &Model, data: &mut Data) {
    let n = model.nv;
    let Data {
        mass,
        ic,
        col_world,
        col_offset,
        column_ancestors: pattern,
        ..
    } = data;
    let m = mass.as_mut_slice();
    for (i, body) in model.bodies.iter().enumerate() {
        let own = col_offset[i]..col_offset[i] + body.v_set.len();
        let ancestors = &pattern.runs[pattern.start[i]..pattern.start[i + 1]];
        for k in own.clone() {
            let f = ic[i].apply(&col_world[k]);
            let col = pattern.coord[k] * n;
            for j in own.clone() {
                m[pattern.coord[j] + col] += col_world[j].dot(&f);
            }
            let row = pattern.coord[k];
            for j in ancestors.iter().flat_map(Range::clone) {
                let val = col_world[j].dot(&f);
                let r = pattern.coord[j];
                m[r + col] += val;
                m[row + r * n] += val;
            }
        }
    }
}
