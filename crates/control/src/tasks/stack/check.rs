//! Validation of a task pushed on a [`TaskStack`].

use super::TaskStack;
use crate::error::IkError;
use crate::tasks::task::{Frame, Point, Task, TaskKind};

impl TaskStack {
    /// Errors on body, q or v indices outside the model, a posture target of the wrong length
    /// or a weight that is not finite and positive.
    pub(super) fn check(&self, task: &Task) -> Result<(), IkError> {
        let bad = |name, reason| Err(IkError::InvalidParameter { name, reason });
        if task.weight.is_some_and(|w| !(w > 0.0 && w.is_finite())) {
            return bad("task weight", "must be finite and > 0");
        }
        let (nb, nq, nv) = (self.model.nbodies(), self.model.nq(), self.model.nv());
        let frame_ok = |f: &Frame| f.body < nb;
        let point_ok = |p: &Point| match p {
            Point::Frame(f) => frame_ok(f),
            Point::Com => true,
            Point::SubtreeCom(b) => *b < nb,
        };
        let ok = match &task.kind {
            TaskKind::Position { frame, .. }
            | TaskKind::Orientation { frame, .. }
            | TaskKind::Pose { frame, .. } => frame_ok(frame),
            TaskKind::RelativePosition {
                frame, reference, ..
            }
            | TaskKind::RelativeOrientation {
                frame, reference, ..
            } => frame_ok(frame) && frame_ok(reference),
            TaskKind::Offset {
                point, from, axes, ..
            } => point_ok(point) && point_ok(from) && axes.iter().all(|a| a.is_finite()),
            TaskKind::Posture { joints, target } => {
                target.len() == nq && joints.iter().all(|&(qi, vi)| qi < nq && vi < nv)
            }
            TaskKind::Joint {
                q_index, v_index, ..
            } => *q_index < nq && *v_index < nv,
            TaskKind::Com { .. } | TaskKind::AngularMomentum { .. } => true,
        };
        if ok {
            Ok(())
        } else {
            bad(
                "task",
                "body, joint index or target length does not fit the model",
            )
        }
    }
}
