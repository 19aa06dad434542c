//! The soft joint-space tasks of a [`super::TaskStack`], whose unit rows are stacked last
//! ([`crate::ik::TaskMap::unit_rows`]).

use crate::tasks::task::{Task, TaskKind};

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
