//! The passive joint layer (end stops, joint friction), effort and speed limits on a single
//! joint (axis z, no gravity torque) whose inertia is the cube formula, against closed-form
//! results: static stop penetration `tau / k`, exponential viscous decay, Coulomb deceleration
//! `f / I`, the exponential approach to the speed limit on the torque-speed line;
//! the laws' signs and slopes; the stability-interval check of the simulation.

mod common;

use biped_sim::controller::{Commands, Controller};
use biped_sim::drive::{Actuator, DriveMode, FrictionParams, MotorParams, Transmission};
use biped_sim::ode::Method;
use biped_sim::passive::{EndStop, JointFriction, JointSpec, PassiveJoints, PassiveParams};
use biped_sim::plant::{Plant, PlantConfig};
use biped_sim::sensors::Sensors;
use biped_sim::simulation::{Frame, Simulation};
use biped_sim::SimError;
use nalgebra::DVector;
use proptest::prelude::*;

use common::{spinner, SPINNER_I_ZZ as I_ZZ};

fn spec(range: Option<[f64; 2]>, damping: f64, friction: f64) -> JointSpec {
    JointSpec {
        name: "spin".into(),
        q: 0,
        v: 0,
        range,
        damping,
        friction,
    }
}

/// The spinner as a torque-mode plant with effort limit `effort` and the passive `spec`.
fn plant(spec: JointSpec, effort: f64) -> Plant {
    limited(spec, effort, f64::INFINITY)
}

/// [`plant`] with the joint speed limit `velocity` as well.
fn limited(spec: JointSpec, effort: f64, velocity: f64) -> Plant {
    let a = spin_actuator(effort, velocity);
    Plant::new(spinner(), vec![a], &[], vec![], PlantConfig::default())
        .unwrap()
        .with_passive(&[spec])
        .unwrap()
}

/// A direct torque drive of the spinner with the given limits.
fn spin_actuator(effort: f64, velocity: f64) -> Actuator {
    Actuator {
        name: "spin".into(),
        joint_q: 0,
        joint_v: 0,
        transmission: Transmission::Direct,
        motor: MotorParams::default(),
        friction: FrictionParams::none(),
        nominal_ratio: 1.0,
        effort,
        velocity,
    }
}

/// State after `t` s of held torque `tau` from `(q0, v0)`, RK4 at 0.1 ms.
fn run(p: &mut Plant, tau: f64, (q0, v0): (f64, f64), t: f64) -> Vec<f64> {
    p.set_commands(&Commands {
        mode: DriveMode::Torque,
        values: vec![tau],
    })
    .unwrap();
    let mut z = p
        .initial_state(&DVector::from_element(1, q0), &DVector::from_element(1, v0))
        .unwrap();
    let h = 1e-4;
    common::integrate(
        p,
        Method::Rk4,
        h,
        &mut z,
        (t / h).round() as usize,
        |_, _, _| {},
    );
    z
}

#[test]
fn a_held_torque_rests_at_tau_over_k_inside_the_stop() {
    let p0 = PassiveParams::default();
    let upper = 0.5;
    let mut p = plant(spec(Some([-0.5, upper]), 0.0, 0.0), f64::INFINITY);
    // k = I omega^2 with the free inertia of the single joint, I_zz.
    let k = I_ZZ * p0.stop_frequency().powi(2);
    assert!((p.passive().stops()[0].stiffness - k).abs() < 1e-12 * k);
    let tau = 0.3;
    let z = run(&mut p, tau, (0.4, 0.0), 2.0);
    let expected = upper + tau / k;
    assert!(
        (z[0] - expected).abs() < 1e-6 * tau / k,
        "{} vs {expected}",
        z[0]
    );
    assert!(z[1].abs() < 1e-6, "at rest: {}", z[1]);
    // Same at the lower stop with the opposite torque.
    let z = run(&mut p, -tau, (-0.4, 0.0), 2.0);
    assert!((z[0] - (-0.5 - tau / k)).abs() < 1e-6 * tau / k, "{}", z[0]);
}

#[test]
fn the_effort_limit_caps_the_pressing_torque() {
    let p0 = PassiveParams::default();
    let effort = 0.1;
    let mut p = plant(spec(Some([-0.5, 0.5]), 0.0, 0.0), effort);
    let k = I_ZZ * p0.stop_frequency().powi(2);
    let z = run(&mut p, 5.0, (0.4, 0.0), 2.0);
    assert!(
        (z[0] - (0.5 + effort / k)).abs() < 1e-6 * effort / k,
        "{}",
        z[0]
    );
}

/// The torque-speed line `tau = e (1 - w / w_max)`, sampled per control cycle of length `h`
/// ([`Plant::hold_commands`]): a saturated command holds `e (1 - w_k / w_max)` over cycle `k`,
/// which RK4 integrates exactly (constant torque, no other force), so
/// `w_k - w_max = (w_0 - w_max) (1 - h e / (I w_max))^k`: from rest up to the limit (to
/// `-w_max` for the opposite command), and from above the limit down to it for a zero command
/// (braking only).
#[test]
fn the_speed_limit_follows_the_sampled_torque_speed_line() {
    let (effort, w_max, h, n) = (0.05, 2.0, 1e-3, 300);
    let mut p = limited(spec(None, 0.0, 0.0), effort, w_max);
    let factor = 1.0 - h * effort / (I_ZZ * w_max);
    assert!(factor > 0.0 && factor < 1.0);
    for (tau, w0, limit) in [(10.0, 0.0, w_max), (-10.0, 0.0, -w_max), (0.0, 3.0, w_max)] {
        let cmds = Commands {
            mode: DriveMode::Torque,
            values: vec![tau],
        };
        let mut z = p
            .initial_state(&DVector::zeros(1), &DVector::from_element(1, w0))
            .unwrap();
        p.hold_commands(&cmds, &z).unwrap();
        common::integrate(&mut p, Method::Rk4, h, &mut z, n, |_, z, p| {
            p.hold_commands(&cmds, z).unwrap()
        });
        let w = limit + (w0 - limit) * factor.powi(n as i32);
        assert!(
            (z[1] - w).abs() < 1e-12,
            "tau {tau}, w0 {w0}: {} vs {w}",
            z[1]
        );
        assert!(
            (w - w0).abs() > 0.2,
            "the run must move the speed: {w0} -> {w}"
        );
    }
    // Without sampling (set_commands), only the effort clamp acts: w = w0 + e t / I.
    let mut z = p
        .initial_state(&DVector::zeros(1), &DVector::zeros(1))
        .unwrap();
    let cmds = Commands {
        mode: DriveMode::Torque,
        values: vec![10.0],
    };
    p.set_commands(&cmds).unwrap();
    common::integrate(&mut p, Method::Rk4, h, &mut z, n, |_, _, _| {});
    let w = effort * h * n as f64 / I_ZZ;
    assert!((z[1] - w).abs() < 1e-9 * w, "{} vs {w}", z[1]);
    assert!(matches!(
        p.hold_commands(&cmds, &z[..1]),
        Err(SimError::Length { what: "z", .. })
    ));
}

#[test]
fn viscous_damping_decays_exponentially() {
    let d = 0.02;
    let mut p = plant(spec(None, d, 0.0), f64::INFINITY);
    let (v0, t) = (3.0, 0.5);
    let z = run(&mut p, 0.0, (0.0, v0), t);
    let exact_v = v0 * (-d * t / I_ZZ).exp();
    let exact_q = v0 * I_ZZ / d * (1.0 - (-d * t / I_ZZ).exp());
    assert!((z[1] - exact_v).abs() < 1e-9, "{} vs {exact_v}", z[1]);
    assert!((z[0] - exact_q).abs() < 1e-9, "{} vs {exact_q}", z[0]);
}

#[test]
fn coulomb_friction_decelerates_at_f_over_i_and_stops() {
    let f = 0.01;
    let mut p = plant(spec(None, 0.0, f), f64::INFINITY);
    let eps = p.passive().friction()[0].smoothing;
    let v0 = 2.0;
    // While |v| >> eps, tanh = 1 to within 2 exp(-2 v / eps): v(t) = v0 - f t / I.
    let t = 0.5; // a whole number of steps; v0 - f t / I = 1.25

    let z = run(&mut p, 0.0, (0.0, v0), t);
    let exact = v0 - f * t / I_ZZ;
    assert!(
        exact / eps > 20.0,
        "still sliding fast: {exact} vs eps {eps}"
    );
    assert!((z[1] - exact).abs() < 1e-6 * v0, "{} vs {exact}", z[1]);
    // Well after the sliding time the joint is (nearly) at rest: the smoothed law leaves a
    // creep at most eps-sized.
    let z = run(&mut p, 0.0, (0.0, v0), 4.0);
    assert!(z[1].abs() < eps, "{} vs eps {eps}", z[1]);
}

/// A controller that holds a constant torque on every actuator (1 ms period).
struct Hold(f64);

/// Zero torque on every actuator.
const ZERO: Hold = Hold(0.0);

impl Controller for Hold {
    fn period(&self) -> f64 {
        1e-3
    }
    fn mode(&self) -> DriveMode {
        DriveMode::Torque
    }
    fn update(&mut self, _: f64, _: &Sensors, c: &mut Commands) -> Result<(), SimError> {
        c.values.fill(self.0);
        Ok(())
    }
}

/// The simulation holds commands through the drive limits and counts the cycles that cut
/// them: a saturated command every cycle (the speed then follows the sampled torque-speed
/// line of `the_speed_limit_follows_the_sampled_torque_speed_line`), none for zero torque
/// from rest, and for a command below the effort only the cycles beyond the speed
/// `w_max (1 - tau / e)` where the line falls below it.
#[test]
fn the_simulation_counts_commands_cut_by_the_drive_limits() {
    let (effort, w_max, n) = (0.05, 2.0, 300u64);
    let factor = 1.0 - 1e-3 * effort / (I_ZZ * w_max);
    let run = |tau: f64| {
        let p = limited(spec(None, 0.0, 0.0), effort, w_max);
        let z0 = p
            .initial_state(&DVector::zeros(1), &DVector::zeros(1))
            .unwrap();
        let mut sim = Simulation::new(p, Hold(tau), Method::Rk4, z0).unwrap();
        // The frames show the held commands: within the effort, below tau once cut.
        let mut held_max = 0.0f64;
        let mut seen = |f: &Frame| {
            held_max = held_max.max(f.commands.values[0].abs());
            Ok(())
        };
        let s = sim.run(n as f64 * 1e-3, &mut seen).unwrap();
        let bound = effort.min(tau.abs());
        assert!(held_max <= bound && held_max >= 0.5 * bound, "{held_max}");
        (s.drive_limits, sim.state()[1])
    };
    let (cut, w) = run(10.0);
    assert_eq!(cut.cycles, n);
    let most = cut.most.unwrap();
    assert_eq!((most.joint.as_str(), most.cycles), ("spin", n));
    let exact = w_max * (1.0 - factor.powi(n as i32));
    assert!((w - exact).abs() < 1e-12, "{w} vs {exact}");
    let (cut, _) = run(0.0);
    assert_eq!((cut.cycles, cut.most), (0, None));
    // Cut from the first cycle whose sampled speed exceeds w_max (1 - tau / e) = 0.4 on.
    let tau = 0.04;
    let (cut, w) = run(tau);
    let free = (0..n).map(|k| tau * 1e-3 * k as f64 / I_ZZ);
    let uncut = free
        .take_while(|w| *w <= w_max * (1.0 - tau / effort))
        .count() as u64;
    assert!(uncut > 0 && uncut < n && w < w_max, "{uncut}, {w}");
    assert_eq!(cut.cycles, n - uncut);
}

#[test]
fn a_step_beyond_the_stability_interval_is_an_error_naming_the_joint() {
    for method in [Method::Euler, Method::Symplectic, Method::Rk4] {
        let bound = method.decay_stability_bound().unwrap();
        // Viscous rate d / I just inside and just outside `bound / h` at h = 1 ms.
        for (factor, ok) in [(0.99, true), (1.01, false)] {
            let d = factor * bound / 1e-3 * I_ZZ;
            let p = plant(spec(None, d, 0.0), f64::INFINITY);
            let z0 = p
                .initial_state(&DVector::zeros(1), &DVector::zeros(1))
                .unwrap();
            match Simulation::new(p, ZERO, method, z0) {
                Ok(_) => assert!(ok, "{method} at {factor} x the bound must be rejected"),
                Err(e) => {
                    assert!(!ok, "{method} at {factor}: {e}");
                    assert!(
                        e.to_string().contains("joint `spin` damping and friction"),
                        "{e}"
                    );
                }
            }
        }
    }
    // Adaptive Dopri5 takes whatever steps it needs.
    let p = plant(spec(None, 1e3, 0.0), f64::INFINITY);
    let z0 = p
        .initial_state(&DVector::zeros(1), &DVector::zeros(1))
        .unwrap();
    assert!(Simulation::new(p, ZERO, Method::Dopri5, z0).is_ok());
}

/// `y' = -y` with step `x`: growth factor of one step of `method`'s stability polynomial,
/// evaluated by running the integrator on a one-joint viscous plant (`lambda = d / I`).
fn decay_growth(method: Method, x: f64) -> f64 {
    let d = 1.0;
    let h = x * I_ZZ / d;
    let mut p = plant(spec(None, d, 0.0), f64::INFINITY);
    let mut z = p
        .initial_state(&DVector::zeros(1), &DVector::from_element(1, 1.0))
        .unwrap();
    common::integrate(&mut p, method, h, &mut z, 200, |_, _, _| {});
    z[1].abs().powf(1.0 / 200.0)
}

#[test]
fn the_decay_stability_bounds_separate_decay_from_growth() {
    for method in [Method::Euler, Method::Symplectic, Method::Rk4] {
        let b = method.decay_stability_bound().unwrap();
        assert!(decay_growth(method, 0.999 * b) < 1.0, "{method} inside");
        assert!(decay_growth(method, 1.001 * b) > 1.0, "{method} outside");
    }
}

#[test]
fn bad_passive_inputs_are_errors() {
    let m = PassiveParams::default();
    let free = |_| I_ZZ;
    let reversed = PassiveJoints::new(&[spec(Some([1.0, -1.0]), 0.0, 0.0)], free, &m);
    assert!(reversed
        .unwrap_err()
        .to_string()
        .contains("joint `spin` range"));
    let negative = PassiveJoints::new(&[spec(None, -1.0, 0.0)], free, &m);
    assert!(negative
        .unwrap_err()
        .to_string()
        .contains("joint `spin` damping"));
    let massless = PassiveJoints::new(&[spec(None, 0.0, 1.0)], |_| 0.0, &m);
    assert!(massless.unwrap_err().to_string().contains("free inertia"));
    let params = PassiveParams {
        stop_time_constant: -1.0,
        ..m
    };
    assert!(PassiveJoints::new(&[], free, &params).is_err());
    // Layers switched off build nothing, and then need no inertia.
    let off = PassiveParams {
        end_stops: false,
        joint_friction: false,
        ..m
    };
    let none = PassiveJoints::new(&[spec(Some([-1.0, 1.0]), 1.0, 1.0)], |_| 0.0, &off).unwrap();
    assert!(none.is_empty() && none.fastest().is_none());
    // Drive limits must be > 0 (infinite = none).
    for (effort, velocity) in [
        (0.0, 1.0),
        (f64::NAN, 1.0),
        (1.0, 0.0),
        (1.0, -2.0),
        (1.0, f64::NAN),
    ] {
        let a = spin_actuator(effort, velocity);
        let r = Plant::new(spinner(), vec![a], &[], vec![], PlantConfig::default());
        assert!(r.unwrap_err().to_string().contains("actuator `spin`"));
    }
}

proptest! {
    /// The torque envelope lies in `[-e, e]`, holds 0 up to the speed limit and excludes
    /// driving torque beyond it, is `[-e, e]` at rest and odd in the speed.
    #[test]
    fn the_torque_envelope_is_bounded_and_odd(
        e in 1e-3f64..1e3, w_max in 1e-2f64..1e2, x in -3.0f64..3.0,
    ) {
        let a = limited(spec(None, 0.0, 0.0), e, w_max).actuators()[0].clone();
        let w = x * w_max;
        let (lo, hi) = a.torque_envelope(w);
        prop_assert!(-e <= lo && lo <= hi && hi <= e);
        prop_assert_eq!(x.abs() <= 1.0, lo <= 0.0 && 0.0 <= hi);
        prop_assert_eq!(a.torque_envelope(0.0), (-e, e));
        let (mlo, mhi) = a.torque_envelope(-w);
        prop_assert!((mlo + hi).abs() <= 1e-12 * e && (mhi + lo).abs() <= 1e-12 * e);
    }

    /// The stop pushes back only: zero inside the range, towards the range outside, never
    /// pulling the joint into the stop, and continuous in `q` at the range ends at rest.
    #[test]
    fn the_stop_pushes_back_only(q in -3.0..3.0f64, qdot in -10.0..10.0f64,
                                 k in 1.0..1e4f64, d in 0.0..1e2f64) {
        let s = EndStop { name: "j".into(), q: 0, v: 0, lower: -1.0, upper: 1.0, stiffness: k, damping: d };
        let tau = s.torque(q, qdot);
        if (-1.0..=1.0).contains(&q) {
            prop_assert_eq!(tau, 0.0);
        } else if q > 1.0 {
            prop_assert!(tau <= 0.0);
        } else {
            prop_assert!(tau >= 0.0);
        }
        prop_assert!(s.torque(1.0 + 1e-12, 0.0).abs() < 1e-8 * k);
    }

    /// Joint friction opposes the motion, is odd, and has the slope `d + f / eps` at rest.
    #[test]
    fn joint_friction_opposes_motion(qdot in -10.0..10.0f64, d in 0.0..1.0f64,
                                     f in 0.0..5.0f64, eps in 1e-3..1.0f64) {
        let j = JointFriction { name: "j".into(), v: 0, viscous: d, coulomb: f, smoothing: eps };
        prop_assert!(j.torque(qdot) * qdot <= 0.0);
        prop_assert!((j.torque(qdot) + j.torque(-qdot)).abs() <= 1e-12 * (1.0 + j.torque(qdot).abs()));
        let h = 1e-6 * eps;
        let fd = -(j.torque(h) - j.torque(-h)) / (2.0 * h);
        prop_assert!((fd - j.slope()).abs() <= 1e-6 * j.slope().max(1e-12));
    }

    /// Built laws stay inside their rate bounds: the Coulomb slope over the free inertia is at
    /// most `1 / T_f`, the stop's rate is `omega`, and `fastest` is the largest of them.
    #[test]
    fn built_rates_are_bounded(inertia in 1e-5..10.0f64, f in 0.0..10.0f64) {
        let p = PassiveParams::default();
        let layer = PassiveJoints::new(&[spec(Some([-1.0, 1.0]), 0.0, f)], |_| inertia, &p).unwrap();
        let stop = &layer.stops()[0];
        prop_assert!((stop.stiffness - inertia * p.stop_frequency().powi(2)).abs() <= 1e-12 * stop.stiffness);
        let mut fastest = p.stop_frequency();
        if let Some(fr) = layer.friction().first() {
            let rate = fr.slope() / inertia;
            prop_assert!(rate <= (1.0 + 1e-12) / p.friction_time_constant, "{}", rate);
            fastest = fastest.max(rate);
        }
        prop_assert!((layer.fastest().unwrap().rate - fastest).abs() <= 1e-12 * fastest);
    }
}
