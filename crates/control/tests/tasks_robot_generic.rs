//! The walk's task set on a described robot against the generic tasks: on the G1, the foot
//! orientation (sole frames with their offset), CoG, upper body and held-joint rows of
//! `LolaTasks` over the robot's `WalkTaskFrames` equal the rows of the generic relative
//! orientation, CoM, orientation and joint tasks, at a configuration away from the targets.

use biped_control::ik::TaskMap;
use biped_control::tasks::{LolaTasks, Task, TaskKind, TaskStack};
use biped_control::walk::WalkRobot;
use biped_robots::description::Robot;
use nalgebra::{DMatrix, DVector};

#[test]
fn g1_walk_rows_are_generic_task_rows() {
    let g1 = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
    let robot = WalkRobot::from_description(&g1).unwrap();
    let model = &robot.model;
    let frames = robot.frames;
    let mut walk = LolaTasks::with_frames(model, &frames, 0.2).unwrap();
    let q0 = robot.posture.clone();
    walk.set_targets_from(&q0).unwrap();
    let t = walk.targets.clone();

    let torso = biped_control::tasks::Frame::body(frames.torso);
    let mut generic = TaskStack::new(model);
    for (s, sole) in frames.soles.into_iter().enumerate() {
        let kind = TaskKind::RelativeOrientation {
            frame: sole,
            reference: torso,
            target: t.foot_orientation[s],
        };
        generic.push(Task::hard(kind)).unwrap();
    }
    generic
        .push(Task::hard(TaskKind::Com { target: t.cog }))
        .unwrap();
    let upper = TaskKind::Orientation {
        frame: torso,
        target: t.upper_body,
    };
    generic.push(Task::hard(upper)).unwrap();
    for (k, joint) in frames.joints.iter().enumerate() {
        let Some((q_index, v_index)) = *joint else {
            continue;
        };
        let target = t.joints[k];
        let kind = TaskKind::Joint {
            q_index,
            v_index,
            target,
        };
        generic.push(Task::hard(kind)).unwrap();
    }

    let mut q = q0.clone();
    for (k, j) in robot.joints.iter().enumerate() {
        let mid = 0.5 * (j.lower + j.upper);
        q[j.q_index] += 0.3 * (mid - q[j.q_index]) + 0.01 * (k as f64 - 14.0) / 14.0;
    }
    q[2] += 0.02;
    let (ew, jw, mw) = evaluate(&mut walk, &q);
    let (eg, jg, mg) = evaluate(&mut generic, &q);
    // feet 12, CoG 3, upper body 3, arm CoGs 6, three waist joints
    assert_eq!((mw, mg), (27, 12 + 3));
    for (rw, rg, n) in [(6, 0, 12), (24, 12, 3)] {
        let de = (ew.rows(rw, n) - eg.rows(rg, n)).amax();
        let dj = (jw.rows(rw, n) - jg.rows(rg, n)).amax();
        assert!(
            de < 1e-12 && dj < 1e-12,
            "rows {rw}..: error {de:e}, Jacobian {dj:e}"
        );
        assert!(eg.rows(rg, n).amax() > 1e-3, "rows {rw}..: no task error");
    }
}

/// Error, Jacobian and row count of `tasks` at `q`.
fn evaluate(tasks: &mut impl TaskMap, q: &DVector<f64>) -> (DVector<f64>, DMatrix<f64>, usize) {
    let m = tasks.max_rows();
    let (mut e, mut j) = (DVector::zeros(m), DMatrix::zeros(m, tasks.nv()));
    let rows = tasks.error_and_jacobian(q, &mut e, &mut j).unwrap();
    (e, j, rows)
}
