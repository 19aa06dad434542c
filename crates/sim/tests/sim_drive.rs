//! Drive models on a single geared joint (axis z, no gravity torque): no-load speed `u / k_e`,
//! stall torque `k_t u / R`, the current limit, the steady state with friction (solved
//! independently by bisection), and a cascaded position loop over a current loop.

mod common;

use biped_dynamics::JointModel;
use biped_sim::controller::{Cascade, CurrentPi, JointPd};
use biped_sim::drive::{Actuator, DriveMode, FrictionParams, MotorParams, Transmission};
use biped_sim::ode::{Method, OdeSystem, Settings};
use biped_sim::plant::{Plant, PlantConfig};
use biped_sim::simulation::Simulation;
use nalgebra::DVector;

const N: f64 = 10.0;
use common::{spinner, SPINNER_I_ZZ as I_ZZ};

fn plant(mode: DriveMode, friction: FrictionParams) -> Plant {
    let a = Actuator {
        name: "spin".into(),
        joint_q: 0,
        joint_v: 0,
        transmission: Transmission::Gear { ratio: N },
        motor: MotorParams::default(),
        friction,
        nominal_ratio: N,
        effort: f64::INFINITY,
        velocity: f64::INFINITY,
    };
    let config = PlantConfig {
        mode,
        ..PlantConfig::default()
    };
    Plant::new(spinner(), vec![a], &[], vec![], config).unwrap()
}

fn hold(p: &mut Plant, mode: DriveMode, value: f64) {
    p.set_commands(&biped_sim::controller::Commands {
        mode,
        values: vec![value],
    })
    .unwrap();
}

/// Joint speed after `t` seconds at constant voltage `u` from rest.
fn spin_up(friction: FrictionParams, u: f64, t: f64) -> (f64, f64) {
    let mut p = plant(DriveMode::Voltage, friction);
    hold(&mut p, DriveMode::Voltage, u);
    let mut z = p
        .initial_state(&DVector::zeros(1), &DVector::zeros(1))
        .unwrap();
    let h = 2e-5;
    common::integrate(
        &mut p,
        Method::Rk4,
        h,
        &mut z,
        (t / h) as usize,
        |_, _, _| {},
    );
    (z[1], z[2]) // joint speed, current
}

#[test]
fn model_inertia_is_the_cube_formula() {
    let m = spinner();
    let mut d = biped_dynamics::Data::new(&m);
    let mm = biped_dynamics::mass_matrix(&m, &mut d, &DVector::zeros(1)).unwrap();
    assert!((mm[(0, 0)] - I_ZZ).abs() < 1e-15);
}

#[test]
fn no_load_speed_is_u_over_ke_and_current_vanishes() {
    let m = MotorParams::default();
    let u = 12.0;
    let (w, i) = spin_up(FrictionParams::none(), u, 3.0);
    let expected = m.no_load_speed(u) / N;
    assert!((expected - u / m.back_emf / N).abs() < 1e-12);
    assert!(
        (w - expected).abs() < 1e-6 * expected,
        "speed {w}, expected {expected}"
    );
    assert!(i.abs() < 1e-6, "current {i}");
}

#[test]
fn stall_torque_is_kt_u_over_r_times_the_ratio() {
    let m = MotorParams::default();
    let mut p = plant(DriveMode::Voltage, FrictionParams::none());
    let u = 6.0;
    hold(&mut p, DriveMode::Voltage, u);
    let mut z = p
        .initial_state(&DVector::zeros(1), &DVector::zeros(1))
        .unwrap();
    z[2] = u / m.resistance; // steady stall current
    let mut zdot = vec![0.0; 3];
    p.rhs(0.0, &z, &mut zdot).unwrap();
    let inertia = I_ZZ;
    let torque = zdot[1] * inertia;
    let expected = N * m.torque_constant * u / m.resistance;
    assert!((m.stall_torque(u) * N - expected).abs() < 1e-12);
    assert!(
        (torque - expected).abs() < 1e-9 * expected,
        "{torque} vs {expected}"
    );
    assert!(zdot[2].abs() < 1e-9, "stall current is steady");
}

#[test]
fn current_mode_delivers_kt_i_and_clamps_at_the_limit() {
    let m = MotorParams::default();
    let inertia = I_ZZ;
    for (cmd, expected_i) in [(5.0, 5.0), (30.0, m.max_current), (-30.0, -m.max_current)] {
        let mut p = plant(DriveMode::Current, FrictionParams::none());
        hold(&mut p, DriveMode::Current, cmd);
        let z = p
            .initial_state(&DVector::zeros(1), &DVector::zeros(1))
            .unwrap();
        let mut zdot = vec![0.0; z.len()];
        p.rhs(0.0, &z, &mut zdot).unwrap();
        let expected = N * m.torque_constant * expected_i;
        assert!((zdot[1] * inertia - expected).abs() < 1e-9 * expected.abs());
    }
}

#[test]
fn steady_speed_with_friction_matches_the_bisection_solution() {
    let m = MotorParams::default();
    let f = FrictionParams {
        viscous: 5e-4,
        coulomb: 0.05,
        smoothing: 1.0,
        efficiency: 0.8,
    };
    let u = 12.0;
    // Independent steady state: k_t (u - k_e w) / R = d w + (tau_c + (1 - eta) |tau_m|) tanh(w / eps).
    let residual = |w: f64| {
        let tau_m = m.torque_constant * (u - m.back_emf * w) / m.resistance;
        tau_m
            - f.viscous * w
            - (f.coulomb + (1.0 - f.efficiency) * tau_m.abs()) * (w / f.smoothing).tanh()
    };
    let (mut lo, mut hi) = (0.0, u / m.back_emf);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if residual(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let (w, _) = spin_up(f, u, 3.0);
    let expected = 0.5 * (lo + hi) / N;
    assert!(
        expected < 0.9 * u / m.back_emf / N,
        "friction must slow the motor noticeably"
    );
    assert!(
        (w - expected).abs() < 1e-6 * expected,
        "speed {w}, expected {expected}"
    );
}

#[test]
fn cascaded_position_over_current_loop_reaches_the_target() {
    // Lossless drive: a PD has no integral action, so friction would leave a position error.
    let mut p = plant(DriveMode::Voltage, FrictionParams::none());
    let inertia = I_ZZ;
    let w = 20.0;
    let outer = JointPd::new(
        1e-3,
        vec![0.5],
        vec![w * w * inertia],
        vec![2.0 * w * inertia],
    )
    .unwrap();
    let inner = CurrentPi::new(&p, 1e-4, 2.0, 2000.0).unwrap();
    let cascade = Cascade::new(outer, inner, 1).unwrap();
    let z0 = p
        .initial_state(&DVector::zeros(1), &DVector::zeros(1))
        .unwrap();
    hold(&mut p, DriveMode::Voltage, 0.0);
    let mut sim =
        Simulation::with_settings(p, cascade, Method::Rk4, Settings::fixed(2e-5), z0).unwrap();
    let s = sim.run(1.0, &mut |_| Ok(())).unwrap();
    assert_eq!(s.control_cycles, 10_000);
    let q = sim.state()[0];
    assert!((q - 0.5).abs() < 1e-4, "position {q}");
    assert!(sim.state()[1].abs() < 1e-2, "speed {}", sim.state()[1]);
}

/// The motor-rate rows of Lola's roller-screw rotors (knee, ankles) equal the finite-difference
/// spin rate of the rotor part's pose about its own z axis, and the rigid gears' rows equal N.
#[test]
fn lola_motor_rows_match_finite_differences_of_the_rotor_pose() {
    use biped_dynamics::mechanism::Coupling;
    use biped_robots::lola::LolaType;
    use biped_robots::plant::lola_plant;
    let lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let plant = &lp.plant;
    let m = plant.model();
    let mut q = m.neutral();
    for l in &lp.lola.limits {
        q[l.q_index] = 0.3 * l.lower + 0.7 * l.upper;
    }
    let mut rotors = 0;
    for a in plant.actuators() {
        let row = a.motor_row(m, q.as_slice()).unwrap();
        match a.transmission {
            Transmission::Gear { ratio } => {
                let entries: Vec<_> = row.unwrap().entries().collect();
                assert_eq!(entries, vec![(a.joint_v, ratio)]);
            }
            Transmission::Rotor { body, q_in, n, .. } => {
                rotors += 1;
                let JointModel::Coupled { mechanism, .. } = m.bodies()[body].joint() else {
                    panic!()
                };
                let row: Vec<_> = row.unwrap().entries().collect();
                let eps = 1e-6;
                for k in 0..n {
                    let mut qp: Vec<f64> = (0..n).map(|i| q[q_in[i]]).collect();
                    let mut qm = qp.clone();
                    qp[k] += eps;
                    qm[k] -= eps;
                    let zeros = vec![0.0; n];
                    let rp = mechanism.motion(&qp, &zeros).unwrap().pose.rotation;
                    let rm = mechanism.motion(&qm, &zeros).unwrap().pose.rotation;
                    let spin = (rm.inverse() * rp).scaled_axis().z / (2.0 * eps);
                    assert!(
                        (spin - row[k].1).abs() < 1e-5 * spin.abs().max(1.0),
                        "{}: {spin} vs {}",
                        a.name,
                        row[k].1
                    );
                }
            }
            _ => {}
        }
    }
    assert_eq!(rotors, 6, "2 knee and 4 ankle screw rotors");
}

#[test]
fn a_motor_coordinate_out_of_range_is_an_error() {
    let a = Actuator {
        name: "spin".into(),
        joint_q: 0,
        joint_v: 0,
        transmission: Transmission::Elastic {
            motor_q: 0,
            motor_v: 5,
            ratio: N,
        },
        motor: MotorParams::default(),
        friction: FrictionParams::default(),
        nominal_ratio: N,
        effort: f64::INFINITY,
        velocity: f64::INFINITY,
    };
    let r = Plant::new(spinner(), vec![a], &[], vec![], PlantConfig::default());
    assert!(matches!(
        r,
        Err(biped_sim::error::SimError::InvalidParameter { .. })
    ));
}
