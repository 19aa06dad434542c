//! The dynamic walk (`biped walk --dynamic`): the kinematic walk tracked in the contact
//! simulation. Checks the verdict on the default walk, that the criteria can fail, and the
//! RNEA feedforward against the simulation's own plant (independent of the walk).

use biped_control::pattern::{Phase, WalkingPattern};
use biped_control::walk::dynamic::{
    build_reference, start_on_ground, Feedforward, JointReference, ReferenceOptions,
    TrackingController,
};
use biped_control::walk::{
    run_dynamic_walk, walk_pattern_params, DynamicWalkParams, Method, WalkController, WalkParams,
};
use biped_robots::lola::{self, LolaType};
use biped_robots::plant::lola_plant;
use biped_sim::drive::FrictionParams;
use biped_sim::plant::PlantConfig;
use biped_sim::simulation::Simulation;
use biped_sim::Method as Integrator;
use nalgebra::{DVector, Vector3};

/// The default walk (10 steps of 0.4 m in 0.8 s, minimisation) walks in the simulation.
#[test]
fn default_walk_does_not_fall_and_advances() {
    let p = DynamicWalkParams::default();
    assert_eq!((p.steps, p.step_length, p.step_time), (10, 0.4, 0.8));
    let run = run_dynamic_walk(&p).expect("dynamic walk");
    let s = run.summary;
    println!("{s:#?}");
    assert!(s.walked, "{s:?}");
    assert_eq!(s.fell_at, None);
    // the planned base travel is the 10 steps minus the half first/last steps' share
    assert!(s.planned_distance > 3.0, "{}", s.planned_distance);
    assert!(s.distance >= 0.8 * s.planned_distance, "{s:?}");
    assert!(s.max_tilt < 0.1, "{}", s.max_tilt);
    assert!(s.min_base_height > 0.9, "{}", s.min_base_height);
    assert!(s.max_tracking_error < 0.05, "{}", s.max_tracking_error);
    // With toe-off and the IK's hard joint limits the reference stays inside every range
    // (the flat-footed reference took the rear ankle ~0.34 rad beyond it).
    assert_eq!(s.limit_excess, 0.0, "{}", s.limit_excess);
    // no divergence, and the soles keep their grip (walk_dynamic_contact.rs: what slipping is)
    assert!(!s.diverged);
    assert!(s.friction_kept && s.slip_at.is_none(), "{s:?}");
    // the series cover the walk plus the hold time, every cycle, both feet used
    let n = run.series.t.len();
    assert!((s.sim_time - (n - 1) as f64 * 1e-3).abs() < 1e-9);
    for foot in 0..2 {
        let peak = run
            .series
            .foot_fz
            .iter()
            .map(|f| f[foot])
            .fold(0.0, f64::max);
        assert!(peak > 500.0, "foot {foot} never carried the robot: {peak}");
    }
    assert_eq!(
        s.rhs_evaluations,
        4 * (n as u64 - 1),
        "RK4: 4 rhs per 1 ms cycle"
    );
}

/// The criteria can fail: without the multibody ZMP correction and the stabiliser the same
/// walk falls (forward, after a few steps) and is reported as such.
#[test]
fn open_loop_lipm_walk_falls_and_is_reported() {
    let p = DynamicWalkParams {
        zmp_iterations: 0,
        stabiliser: None,
        ..DynamicWalkParams::default()
    };
    let run = run_dynamic_walk(&p).expect("simulation itself succeeds");
    let s = run.summary;
    assert!(!s.walked);
    let t = s.fell_at.expect("falls");
    assert!(t > 1.0 && t < 9.0, "{t}");
    let z0 = run.series.base[0][2];
    assert!(s.max_tilt > p.max_tilt || s.min_base_height < z0 - p.fall_drop);
    // the run stops at the fall
    assert!((s.sim_time - t).abs() < 0.06, "{} vs {t}", s.sim_time);
    assert!(s.progress < 0.8, "{}", s.progress);
}

/// The correction brings the planned motion's multibody ZMP to the LIPM ZMP.
#[test]
fn zmp_correction_reduces_the_multibody_zmp_error() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let pat = WalkingPattern::generate(&walk_pattern_params(&lola, 3, 0.4, 0.8).unwrap()).unwrap();
    let o = ReferenceOptions {
        method: Method::Minimization,
        walk: WalkParams::default(),
        zmp_iterations: 2,
        clamp_margin: None,
    };
    let r = build_reference(&lola, &pat, &o).unwrap();
    let e = &r.zmp_error;
    assert_eq!(e.len(), 3);
    assert!(e[0] > 0.12, "uncorrected error {e:?}");
    assert!(e[2] < 0.5 * e[0], "{e:?}");
    // recomputed here: the reference's multibody ZMP against the LIPM ZMP
    let worst = r
        .zmp
        .iter()
        .zip(&r.pattern_zmp)
        .map(|(a, b)| (a - b).amax())
        .fold(0.0, f64::max);
    assert!((worst - e[2]).abs() < 1e-12);
}

/// `offset_com` moves CoM and LIPM ZMP consistently: `dp = dc - h/g dc_ddot`.
#[test]
fn offset_com_updates_the_lipm_zmp() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let params = walk_pattern_params(&lola, 2, 0.3, 0.8).unwrap();
    let pat = WalkingPattern::generate(&params).unwrap();
    let mut moved = pat.clone();
    let n = pat.len();
    let off: Vec<[Vector3<f64>; 2]> = (0..n)
        .map(|k| {
            let t = k as f64 * 1e-3;
            [
                Vector3::new(0.01 * t, 0.01, 0.3 * t),
                Vector3::new(-0.02, 0.0, -0.5),
            ]
        })
        .collect();
    moved.offset_com(&off).unwrap();
    let hg = params.com_height / params.gravity;
    for (k, (a, b)) in pat.samples().iter().zip(moved.samples()).enumerate() {
        for (axis, d) in off[k].iter().enumerate() {
            assert!((b.com[axis] - a.com[axis] - d[0]).abs() < 1e-12);
            assert!((b.com_acc[axis] - a.com_acc[axis] - d[2]).abs() < 1e-12);
            let dp = b.zmp[axis] - a.zmp[axis];
            assert!((dp - (d[0] - hg * d[2])).abs() < 1e-9, "{dp}");
        }
        assert_eq!(a.zmp_ref, b.zmp_ref);
    }
    assert!(moved.offset_com(&off[1..]).is_err());
}

/// Along a walk, the distributed wrenches make RNEA's free-joint entries vanish; in single
/// support the swing foot carries nothing, in double support both feet carry a share.
#[test]
fn feedforward_balances_the_base_in_every_phase() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let pat = WalkingPattern::generate(&walk_pattern_params(&lola, 2, 0.4, 0.8).unwrap()).unwrap();
    let mut ctrl = WalkController::new(&lola, Method::None, WalkParams::default(), &pat).unwrap();
    let mut ff = Feedforward::new(&lola).unwrap();
    let dt = pat.params().dt;
    let mut prev = DVector::zeros(lola.model.nv());
    let mut seen = [false; 3];
    for (k, s) in pat.iter().enumerate() {
        ctrl.cycle(s, dt).unwrap();
        let a = (ctrl.qdot() - &prev) / dt;
        prev.copy_from(ctrl.qdot());
        if k == 0 || k % 97 != 0 {
            continue;
        }
        let (q, v) = (ctrl.q_eval().clone(), ctrl.qdot().clone());
        let feet = ff.foot_wrenches(&q, &v, &a, s).unwrap();
        let tau = ff.compute(&q, &v, &a, s).unwrap();
        let scale = tau.amax().max(1.0);
        assert!(
            tau.rows(0, 6).amax() < 1e-9 * scale,
            "t = {}: {}",
            s.t,
            tau.rows(0, 6)
        );
        let fz = feet.map(|(_, w)| w.lin.norm());
        match s.phase {
            Phase::LeftStance => assert!(fz[1] == 0.0 && fz[0] > 0.7 * weight(&lola), "{fz:?}"),
            Phase::RightStance => assert!(fz[0] == 0.0 && fz[1] > 0.7 * weight(&lola), "{fz:?}"),
            Phase::Double => assert!((fz[0] + fz[1] - weight(&lola)).abs() < 100.0, "{fz:?}"),
        }
        seen[s.phase as usize] = true;
    }
    assert_eq!(seen, [true; 3]);
}

/// Weight `m |g|` of the Lola model \[N].
fn weight(lola: &lola::LolaModel) -> f64 {
    let m: f64 = lola.model.bodies().iter().map(|b| b.inertia().mass()).sum();
    m * lola.model.gravity().norm()
}

/// A constant standing reference at `q0` with its RNEA feedforward (double support).
fn standing_reference(n: usize) -> (JointReference, DVector<f64>) {
    let lola = lola::build(LolaType::Type2).unwrap();
    let pat = WalkingPattern::generate(&walk_pattern_params(&lola, 1, 0.3, 0.8).unwrap()).unwrap();
    let o = ReferenceOptions {
        method: Method::None,
        walk: WalkParams::default(),
        zmp_iterations: 0,
        clamp_margin: None,
    };
    let mut r = build_reference(&lola, &pat, &o).unwrap();
    let nj = r.joints;
    assert_eq!(r.phase[0], Phase::Double);
    let zeros = DVector::zeros(lola.model.nv());
    let s0 = pat.samples()[0];
    let mut ff = Feedforward::new(&lola).unwrap();
    let tau = ff.compute(&r.q0, &zeros, &zeros, &s0).unwrap().clone();
    assert!(
        tau.rows(0, 6).amax() < 1e-8 * tau.amax(),
        "free-joint rows vanish"
    );
    let q: Vec<f64> = lola.limits.iter().map(|l| r.q0[l.q_index]).collect();
    let t: Vec<f64> = lola.limits.iter().map(|l| tau[l.v_index]).collect();
    r.q = q.repeat(n);
    r.qd = vec![0.0; n * nj];
    r.tau = t.repeat(n);
    r.tilt = vec![r.tilt[0]; n];
    r.phase = vec![Phase::Double; n];
    r.base = vec![r.base[0]; n];
    let q0 = r.q0.clone();
    (r, q0)
}

/// Feedforward alone (PD gains zero) holds the robot standing in the simulation for 0.3 s;
/// without it the robot collapses. The plant is the simulation's own (O(n) forward dynamics,
/// compliant contacts, drive friction), independent of the RNEA route.
#[test]
fn feedforward_alone_holds_the_standing_robot() {
    let drift = |feedforward: bool| {
        let (r, q0) = standing_reference(400);
        let mut plant = lola_plant(LolaType::Type2, PlantConfig::default())
            .unwrap()
            .plant;
        let q0 = start_on_ground(&plant, &q0).unwrap();
        let z0 = plant
            .initial_state(&q0, &DVector::zeros(plant.layout().nv))
            .unwrap();
        let mut c =
            TrackingController::new(&mut plant, r, &q0, (40.0, 1.0), feedforward, None).unwrap();
        c.scale_gains(0.0);
        let mut sim = Simulation::new(plant, c, Integrator::Rk4, z0).unwrap();
        sim.run(0.3, &mut |_| Ok(())).unwrap();
        let nq = q0.len();
        (sim.state()[..nq].iter().zip(q0.iter()).skip(7))
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
    };
    let (held, free) = (drift(true), drift(false));
    assert!(held < 0.01, "feedforward alone drifts {held} rad");
    assert!(
        free > 10.0 * held,
        "without feedforward {free} rad vs {held}"
    );
}

/// Under PD + feedforward on the simulation's plant (drive friction off), RNEA with the
/// contact wrenches the simulation computes and the simulated acceleration (central
/// difference) reproduces the commanded joint torques and balances the floating base:
/// `tau = M(q) qdd + h(q, qd) - J^T f_contact`, an independent route to the plant's O(n)
/// forward dynamics with its contact layer.
#[test]
fn rnea_with_simulated_contact_wrenches_reproduces_the_commands() {
    let (r, q0) = standing_reference(1100);
    let lola = lola::build(LolaType::Type2).unwrap();
    let config = PlantConfig {
        friction: FrictionParams::none(),
        ..PlantConfig::default()
    };
    let mut plant = lola_plant(LolaType::Type2, config).unwrap().plant;
    let q0 = start_on_ground(&plant, &q0).unwrap();
    let z0 = plant
        .initial_state(&q0, &DVector::zeros(plant.layout().nv))
        .unwrap();
    let c = TrackingController::new(&mut plant, r, &q0, (40.0, 1.0), true, None).unwrap();
    let mut sim = Simulation::new(plant, c, Integrator::Rk4, z0).unwrap();
    let h = 1e-3;
    let l = sim.plant().layout();
    let v_of =
        |sim: &Simulation<TrackingController>| DVector::from_column_slice(&sim.state()[l.v()]);
    sim.run(1.0, &mut |_| Ok(())).unwrap();
    let v_prev = v_of(&sim);
    let cmd_prev = sim.plant().commands().to_vec();
    sim.run(h, &mut |_| Ok(())).unwrap();
    let q = DVector::from_column_slice(&sim.state()[l.q()]);
    let v = v_of(&sim);
    // Every contact entry's wrench: the feet and the toe segments, each on its own body.
    let fext = sim.plant().external_wrenches();
    let measured: Vec<_> = sim
        .plant()
        .contact()
        .bodies()
        .map(|b| (b, fext[b]))
        .collect();
    assert_eq!(measured.len(), 4);
    let cmd_now = sim.plant().commands().to_vec();
    sim.run(h, &mut |_| Ok(())).unwrap();
    let a = (v_of(&sim) - &v_prev) / (2.0 * h);
    let carried: f64 = measured.iter().map(|(_, w)| w.lin.norm()).sum();
    let weight = weight(&lola);
    assert!(
        (carried - weight).abs() < 0.02 * weight,
        "contact carries the weight: {carried} of {weight}"
    );
    let mut ff = Feedforward::new(&lola).unwrap();
    let tau = ff.with_wrenches(&q, &v, &a, &measured).unwrap();
    assert!(
        tau.rows(0, 6).amax() < 0.5,
        "base balanced: {}",
        tau.rows(0, 6)
    );
    for (k, lim) in lola.limits.iter().enumerate() {
        let cmd = 0.5 * (cmd_prev[k] + cmd_now[k]);
        let diff = (tau[lim.v_index] - cmd).abs();
        assert!(
            diff < 0.05 + 0.01 * cmd.abs(),
            "{}: rnea {} vs command {cmd}",
            lim.name,
            tau[lim.v_index]
        );
    }
}

/// Bad parameters are typed errors, not panics.
#[test]
fn bad_parameters_are_rejected() {
    let base = DynamicWalkParams::default();
    for p in [
        DynamicWalkParams { steps: 0, ..base },
        DynamicWalkParams {
            bandwidth: f64::NAN,
            ..base
        },
        DynamicWalkParams {
            max_tilt: -1.0,
            ..base
        },
        DynamicWalkParams {
            clamp_margin: Some(f64::INFINITY),
            ..base
        },
        DynamicWalkParams {
            step_length: f64::NAN,
            ..base
        },
    ] {
        assert!(run_dynamic_walk(&p).is_err(), "{p:?}");
    }
}
