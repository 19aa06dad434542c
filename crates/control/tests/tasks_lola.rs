//! Lola's task description (Table 4.2): Jacobians vs finite differences of the task errors
//! (q perturbed with `integrate`), position IK on the full and redundant task sets,
//! closed-loop tracking, and smooth task switching.

use biped_control::ik::{
    ClosedLoopIk, CycleInput, IkSettings, PositionIk, StopReason, TaskBuffers, TaskMap, Weight,
};
use biped_control::tasks::{lola_joint_cost, standing_configuration, LolaTasks, TaskId};
use biped_dynamics::integrate;
use biped_robots::lola::{build, LolaModel, LolaType};
use nalgebra::{DVector, UnitQuaternion, Vector3};

fn setup() -> (LolaModel, LolaTasks, DVector<f64>) {
    let lola = build(LolaType::Type2).unwrap();
    let tasks = LolaTasks::new(&lola, 0.2).unwrap();
    let q = standing_configuration(&lola);
    (lola, tasks, q)
}

/// A generic configuration: standing pose plus deterministic joint offsets, tilted base.
fn perturbed(lola: &LolaModel, q: &DVector<f64>) -> DVector<f64> {
    let mut q = q.clone();
    for (k, l) in lola.limits.iter().enumerate() {
        let mid = 0.5 * (l.lower + l.upper);
        q[l.q_index] += 0.3 * (mid - q[l.q_index]) + 0.05 * ((k as f64) * 1.7).sin();
    }
    let rot = UnitQuaternion::from_scaled_axis(Vector3::new(0.1, -0.2, 0.7));
    q.fixed_rows_mut::<4>(3).copy_from(&rot.coords);
    q[0] = 0.3;
    q
}

#[test]
fn all_tasks_give_a_square_system_and_zero_error_at_own_targets() {
    let (lola, mut tasks, q) = setup();
    assert_eq!(tasks.nv(), TaskId::TOTAL_ROWS);
    let q = perturbed(&lola, &q);
    tasks.set_targets_from(&q).unwrap();
    let mut buf = TaskBuffers::new(&tasks);
    buf.evaluate(&mut tasks, &q).unwrap();
    assert_eq!(buf.rows, 31);
    assert!(buf.error_norm() < 1e-12, "{}", buf.error_norm());
}

#[test]
fn task_jacobians_match_finite_differences() {
    let (lola, mut tasks, q) = setup();
    let q = perturbed(&lola, &q);
    tasks.targets.planning_yaw = 0.4;
    // At targets = x(q) the orientation error is log(exp(-w h)) = -w h to first order.
    tasks.set_targets_from(&q).unwrap();
    let model = lola.model.clone();
    let mut buf = TaskBuffers::new(&tasks);
    buf.evaluate(&mut tasks, &q).unwrap();
    let (mut plus, mut minus) = (TaskBuffers::new(&tasks), TaskBuffers::new(&tasks));
    let h = 1e-6;
    let mut worst: f64 = 0.0;
    for c in 0..model.nv() {
        let mut e = DVector::zeros(model.nv());
        e[c] = 1.0;
        plus.evaluate(&mut tasks, &integrate(&model, &q, &e, h).unwrap())
            .unwrap();
        minus
            .evaluate(&mut tasks, &integrate(&model, &q, &e, -h).unwrap())
            .unwrap();
        for r in 0..31 {
            let fd = -(plus.err[r] - minus.err[r]) / (2.0 * h);
            let d = (fd - buf.jac[(r, c)]).abs();
            worst = worst.max(d);
        }
    }
    assert!(worst < 1e-6, "worst Jacobian deviation {worst}");
}

#[test]
fn newton_raphson_reaches_lola_targets_full_and_redundant() {
    let (_, mut tasks, q0) = setup();
    tasks.set_targets_from(&q0).unwrap();
    tasks.targets.cog += Vector3::new(0.02, 0.015, -0.03);
    tasks.targets.foot_position[0] += Vector3::new(0.05, -0.01, 0.03);
    tasks.targets.upper_body = *UnitQuaternion::from_scaled_axis(Vector3::new(0.0, 0.05, 0.1))
        .to_rotation_matrix()
        .matrix();
    for arms_on in [true, false] {
        tasks.set_active_now(TaskId::RightArmCoG, arms_on);
        tasks.set_active_now(TaskId::LeftArmCoG, arms_on);
        let mut q = q0.clone();
        let mut ik = PositionIk::new(&tasks, IkSettings::default());
        let r = ik.newton_raphson(&mut tasks, &mut q).unwrap();
        assert_eq!(r.stop, StopReason::Converged, "arms {arms_on}: {r:?}");
        let mut q = q0.clone();
        let r = ik.optimize(&mut tasks, &mut q).unwrap();
        assert!(r.reached(), "optimisation, arms {arms_on}: {r:?}");
    }
}

#[test]
fn unreachable_foot_target_is_reported() {
    let (_, mut tasks, q0) = setup();
    tasks.set_targets_from(&q0).unwrap();
    tasks.targets.foot_position[1] += Vector3::new(0.0, 0.0, -2.0);
    let mut q = q0.clone();
    let mut ik = PositionIk::new(
        &tasks,
        IkSettings {
            max_iterations: 50,
            ..Default::default()
        },
    );
    let r = ik.optimize(&mut tasks, &mut q).unwrap();
    assert!(!r.reached());
    assert!(r.require_reached().is_err());
    assert!(q.iter().all(|x| x.is_finite()));
}

/// Runs the closed loop with a swaying CoG; switches the arm tasks off at 0.3 s (ramped if
/// `ramp > 0`); returns (max |qd_k+1 - qd_k| after 0.25 s, final CoG error).
fn sway(ramp: f64) -> (f64, f64) {
    let (lola, mut tasks, q0) = setup();
    for a in tasks.activation.iter_mut() {
        a.ramp_time = ramp;
    }
    tasks.set_targets_from(&q0).unwrap();
    // Comfort pose with bent elbows: once the arm tasks are off, H_J moves the arms.
    let mut comfort = q0.clone();
    for l in lola.limits.iter().filter(|l| l.name.ends_with("forearm")) {
        comfort[l.q_index] = -1.0;
    }
    let cost = lola_joint_cost(&lola, &comfort, 1.0, 0.1, 0.1).unwrap();
    let (c0, dt) = (tasks.targets.cog, 1e-3);
    let mut q = q0.clone();
    let mut cl = ClosedLoopIk::new(&tasks);
    let mut grad = DVector::zeros(tasks.nv());
    let (mut prev, mut jump): (DVector<f64>, f64) = (DVector::zeros(tasks.nv()), 0.0);
    for k in 0..600 {
        let t = k as f64 * dt;
        let w = 2.0 * std::f64::consts::PI;
        tasks.targets.cog = c0 + Vector3::new(0.0, 0.03 * (w * t).sin(), 0.0);
        let off = TaskId::CoG.full_offset();
        tasks.targets.velocity[off + 1] = 0.03 * w * (w * t).cos();
        if k == 300 {
            tasks.switch(TaskId::RightArmCoG, false);
            tasks.switch(TaskId::LeftArmCoG, false);
        }
        tasks.advance(dt);
        cost.gradient_into(&q, &mut grad).unwrap();
        let input = CycleInput {
            gain: 100.0,
            weight: &Weight::Identity,
            null_space: Some((&grad, 1.0)),
            damping: 0.0,
            dt,
        };
        cl.step(&mut tasks, &mut q, &input).unwrap();
        if k > 250 {
            jump = jump.max((&cl.qdot - &prev).norm());
        }
        prev.copy_from(&cl.qdot);
    }
    let mut buf = TaskBuffers::new(&tasks);
    buf.evaluate(&mut tasks, &q).unwrap();
    let off = 12; // CoG rows follow the four foot tasks
    (jump, buf.err.fixed_rows::<3>(off).norm())
}

#[test]
fn closed_loop_tracks_cog_and_ramped_switch_keeps_qdot_continuous() {
    let (abrupt, err_a) = sway(0.0);
    let (ramped, err_r) = sway(0.2);
    assert!(err_a < 1e-3 && err_r < 1e-3, "CoG errors {err_a} {err_r}");
    assert!(abrupt > 10.0 * ramped, "abrupt {abrupt} vs ramped {ramped}");
}
