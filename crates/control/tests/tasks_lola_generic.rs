//! Lola's task set (Table 4.2) against the generic tasks: on the Lola model, with its coupled
//! drive mechanisms, the generic relative orientation, CoM, orientation and joint tasks give
//! exactly the rows (error and Jacobian) of `LolaTasks`' foot orientation, CoG, upper body and
//! joint tasks, at configurations away from the targets.

use biped_control::ik::TaskMap;
use biped_control::tasks::{standing_configuration, Frame, LolaTasks, Task, TaskKind, TaskStack};
use biped_robots::lola::{build, LolaType};
use nalgebra::{DMatrix, DVector};

#[test]
fn lola_rows_are_generic_task_rows() {
    let lola = build(LolaType::Type2).unwrap();
    let model = &lola.model;
    let mut lola_tasks = LolaTasks::new(&lola, 0.2).unwrap();
    let q0 = standing_configuration(&lola);
    lola_tasks.set_targets_from(&q0).unwrap();
    let t = lola_tasks.targets.clone();

    let body = |n: &str| Frame::body(model.body_id(n).unwrap());
    let joint = |n: &str| {
        let l = lola.limits.iter().find(|l| l.name == n).unwrap();
        (l.q_index, l.v_index)
    };
    let mut generic = TaskStack::new(model);
    // rows 6..18 of Table 4.2: foot orientations (torso frame), CoG, upper body
    for (s, sole) in ["r_sole", "l_sole"].into_iter().enumerate() {
        let kind = TaskKind::RelativeOrientation {
            frame: body(sole),
            reference: body("torso"),
            target: t.foot_orientation[s],
        };
        generic.push(Task::hard(kind)).unwrap();
    }
    generic
        .push(Task::hard(TaskKind::Com { target: t.cog }))
        .unwrap();
    let upper = TaskKind::Orientation {
        frame: body("torso"),
        target: t.upper_body,
    };
    generic.push(Task::hard(upper)).unwrap();
    // rows 24..31: the joint tasks
    let names = [
        "pelvis_rotation",
        "torso",
        "r_toe",
        "l_toe",
        "head_pan",
        "head",
        "camera",
    ];
    for (k, n) in names.iter().enumerate() {
        let (q_index, v_index) = joint(n);
        let target = t.joints[k];
        generic
            .push(Task::hard(TaskKind::Joint {
                q_index,
                v_index,
                target,
            }))
            .unwrap();
    }

    // a configuration away from the targets: every actuated joint moved
    let mut q = q0.clone();
    for (k, l) in lola.limits.iter().enumerate() {
        let mid = 0.5 * (l.lower + l.upper);
        q[l.q_index] += 0.3 * (mid - q[l.q_index]) + 0.01 * (k as f64 - 12.0) / 12.0;
    }
    q[2] += 0.02; // base height
    let (el, jl, ml) = evaluate(&mut lola_tasks, &q);
    let (eg, jg, mg) = evaluate(&mut generic, &q);
    assert_eq!((ml, mg), (31, 12 + 7));
    let pairs = [(6, 0, 12), (24, 12, 7)]; // (Lola row, generic row, rows)
    for (rl, rg, n) in pairs {
        let de = (el.rows(rl, n) - eg.rows(rg, n)).amax();
        let dj = (jl.rows(rl, n) - jg.rows(rg, n)).amax();
        assert!(
            de < 1e-12 && dj < 1e-12,
            "rows {rl}..: error {de:e}, Jacobian {dj:e}"
        );
        assert!(
            eg.rows(rg, n).amax() > 1e-3,
            "rows {rl}..: no task error to compare"
        );
    }
}

/// Error, Jacobian and row count of `tasks` at `q`.
fn evaluate(tasks: &mut impl TaskMap, q: &DVector<f64>) -> (DVector<f64>, DMatrix<f64>, usize) {
    let m = tasks.max_rows();
    let (mut e, mut j) = (DVector::zeros(m), DMatrix::zeros(m, tasks.nv()));
    let rows = tasks.error_and_jacobian(q, &mut e, &mut j).unwrap();
    (e, j, rows)
}
