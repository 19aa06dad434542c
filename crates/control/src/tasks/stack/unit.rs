//! The soft joint-space tasks of a [`super::TaskStack`], whose unit rows are stacked last
//! ([`crate::ik::TaskMap::unit_rows`]).

use crate::tasks::task::{Task, TaskKind};
use nalgebra::{DMatrix, DVector};

/// Whether `task`'s rows are soft unit rows (a soft posture or joint task).
pub(super) fn is_unit(task: &Task) -> bool {
    let joint_space = matches!(task.kind, TaskKind::Posture { .. } | TaskKind::Joint { .. });
    joint_space && task.weight.is_some()
}

/// Appends the columns of the unit rows of a posture or joint task to `out`.
pub(super) fn push_columns(kind: &TaskKind, out: &mut Vec<usize>) {
    match kind {
        TaskKind::Posture { joints, .. } => out.extend(joints.iter().map(|&(_, vi)| vi)),
        TaskKind::Joint { v_index, .. } => out.push(*v_index),
        _ => {}
    }
}

/// Unit rows of a posture task from row `r` (joints `(q_index, v_index)`): the row block
/// zeroed by contiguous column segments, then the unit entries; error `target - q`.
pub(super) fn write_posture(
    joints: &[(usize, usize)],
    target: &DVector<f64>,
    q: &DVector<f64>,
    r: usize,
    err: &mut DVector<f64>,
    out: &mut DMatrix<f64>,
) {
    let (nr, k) = (out.nrows(), joints.len());
    for col in out.as_mut_slice().chunks_exact_mut(nr) {
        col[r..r + k].fill(0.0);
    }
    for (i, &(qi, vi)) in joints.iter().enumerate() {
        out[(r + i, vi)] = 1.0;
        err[r + i] = target[qi] - q[qi];
    }
}

/// The unit row of a joint task `(q_index, v_index)` at row `r`; error `target - q`.
pub(super) fn write_joint(
    (qi, vi): (usize, usize),
    target: f64,
    q: &DVector<f64>,
    r: usize,
    err: &mut DVector<f64>,
    out: &mut DMatrix<f64>,
) {
    out.row_mut(r).fill(0.0);
    out[(r, vi)] = 1.0;
    err[r] = target - q[qi];
}
