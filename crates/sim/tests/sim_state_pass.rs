//! The plant's state pass (`Plant::state_outputs`, the sensors' sample each control cycle):
//! its outputs are the right-hand side's at the same state bit for bit and the foot-chain
//! route's (`Plant::outputs`) to round-off; a right-hand side right after it, also after a new
//! command as in the control loop, reuses its kinematics (observed by a marker the skipped pass
//! leaves) and equals a right-hand side on a plant without that pass bit for bit. In a
//! simulation the recorder's CoM and `L_G` come from that pass and equal an independent pass
//! bit for bit and `A_G v` to round-off; away from it the recorder's own pass gives the same.

mod common;

use biped_dynamics::dynamics::forward_dynamics_kinematics_current as current;
use biped_dynamics::{centroidal_momentum, Centroidal, Data};
use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::controller::Commands;
use biped_sim::drive::DriveMode;
use biped_sim::ode::{Method, OdeSystem};
use biped_sim::plant::{Plant, PlantConfig, PlantOutputs};
use biped_sim::scenario::{build, Scenario, ScenarioKind, ScenarioOptions};
use biped_sim::sensors::Sensors;
use biped_sim::simulation::{Frame, Signals};
use nalgebra::{DVector, Vector3};
use rand::{Rng, SeedableRng};

const MARK: f64 = 1234.5;

/// A standing Lola plant in `mode` and its scenario.
fn stand(kind: LolaType, mode: DriveMode) -> (Plant, Scenario) {
    let config = PlantConfig {
        mode,
        ..PlantConfig::default()
    };
    let mut lp = lola_plant(kind, config).unwrap();
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &ScenarioOptions::lola()).unwrap();
    (lp.plant, sc)
}

/// Random commands of the plant's kind.
fn commands(p: &Plant, rng: &mut rand::rngs::StdRng) -> Commands {
    let values = (0..p.actuators().len())
        .map(|_| rng.random_range(-2.0..2.0))
        .collect();
    Commands {
        mode: p.mode(),
        values,
    }
}

/// Bitwise equality of two outputs.
fn assert_same(a: &PlantOutputs, b: &PlantOutputs) {
    assert_eq!(a.contact.feet, b.contact.feet);
    assert_eq!(a.contact.foot_states, b.contact.foot_states);
    assert_eq!(a.contact.point_forces, b.contact.point_forces);
    assert_eq!(a.drives, b.drives);
}

/// State pass vs right-hand side vs foot chains at one random state; returns the points in
/// contact.
fn check(kind: LolaType, mode: DriveMode, seed: u64) -> usize {
    let (mut p, sc) = stand(kind, mode);
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let z = common::random_stand_state(&p, &sc.z0, &mut rng);
    let (c0, c1) = (commands(&p, &mut rng), commands(&p, &mut rng));
    let mut fresh = p.clone();
    let n = z.len();
    // The state pass equals the right-hand side's outputs at the same state and command.
    p.set_commands(&c0).unwrap();
    let pass = p.state_outputs(&z).unwrap().clone();
    let fext = p.external_wrenches().to_vec();
    p.rhs(0.0, &z, &mut vec![0.0; n]).unwrap();
    assert_same(&pass, p.last_outputs());
    assert_eq!(fext, p.external_wrenches());
    // ... and the foot-chain route to round-off.
    let chain = p.outputs(&z).unwrap();
    for (a, b) in pass.contact.feet.iter().zip(&chain.contact.feet) {
        assert_eq!(a.points_in_contact, b.points_in_contact);
        assert!((a.force - b.force).norm() <= 1e-9 * (1.0 + b.force.norm()));
        assert!((a.torque - b.torque).norm() <= 1e-9 * (1.0 + b.torque.norm()));
    }
    // Control loop order: state pass with the old command, new command, right-hand side.
    p.state_outputs(&z).unwrap();
    p.set_commands(&c1).unwrap();
    let mut zdot = vec![0.0; n];
    p.rhs(0.0, &z, &mut zdot).unwrap();
    fresh.set_commands(&c1).unwrap();
    let mut zref = vec![0.0; n];
    fresh.rhs(0.0, &z, &mut zref).unwrap();
    assert_eq!(zdot, zref, "{kind:?} {mode:?} seed {seed}");
    assert_same(p.last_outputs(), fresh.last_outputs());
    // A second right-hand side at the state (after a solve on the reused pass) is the same.
    p.rhs(0.0, &z, &mut zdot).unwrap();
    assert_eq!(zdot, zref, "{kind:?} {mode:?} seed {seed}: repeated rhs");
    // The right-hand side reused the pass: a marker put between them survives.
    p.state_outputs(&z).unwrap();
    p.model_and_data().1.world_pos[0] = Vector3::repeat(MARK);
    p.rhs(0.0, &z, &mut zdot).unwrap();
    assert_eq!(p.data().world_pos[0].x, MARK, "pass not reused");
    pass.contact.feet.iter().map(|f| f.points_in_contact).sum()
}

#[test]
fn state_pass_equals_rhs_and_is_reused_type2() {
    for (s, mode) in [DriveMode::Torque, DriveMode::Current, DriveMode::Voltage]
        .into_iter()
        .enumerate()
    {
        let touching: Vec<usize> = (0..3)
            .map(|k| check(LolaType::Type2, mode, 10 * s as u64 + k))
            .collect();
        assert!(touching.iter().any(|&n| n > 0), "{touching:?}");
    }
}

#[test]
fn state_pass_equals_rhs_and_is_reused_type3() {
    let touching: usize = (0..2)
        .map(|k| check(LolaType::Type3, DriveMode::Torque, 100 + k))
        .sum();
    assert!(touching > 0);
}

/// CoM and `h_G` of a fresh pass at the frame's state, and `A_G v` there.
fn independent(f: &Frame) -> ([f64; 6], [f64; 6]) {
    let (m, l) = (f.plant.model(), f.plant.layout());
    let q = DVector::from_column_slice(&f.z[l.q()]);
    let v = DVector::from_column_slice(&f.z[l.v()]);
    let s = centroidal_momentum(m, &mut Data::new(m), &q, &v).unwrap();
    let mut c = Centroidal::new(m);
    c.compute(m, &mut Data::new(m), &q, &v).unwrap();
    let h = c.momentum().unwrap();
    let six = |a: Vector3<f64>, b: Vector3<f64>| [a.x, a.y, a.z, b.x, b.y, b.z];
    (six(s.com, s.momentum.ang), six(c.com(), h.ang))
}

/// Asserts the last six recorded values (com, L_G) equal `own` exactly and `ag` to round-off.
fn assert_momentum(values: &[f64], (own, ag): ([f64; 6], [f64; 6])) {
    let got = &values[values.len() - 6..];
    assert_eq!(got, own);
    let scale = 1.0 + ag.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (a, b) in got.iter().zip(ag) {
        assert!((a - b).abs() <= 1e-10 * scale, "{a} vs A_G v {b}");
    }
}

#[test]
fn recorded_momentum_comes_from_the_plant_pass_and_equals_own_passes() {
    let (plant, mut sc) = stand(LolaType::Type2, DriveMode::Torque);
    sc.duration = 0.02;
    let l = plant.layout();
    sc.z0[l.v().start + 3] = 0.4; // some angular momentum
    let mut signals = Signals::new(&plant, true);
    let mut frames = 0;
    let mut observer = |f: &Frame| {
        let (q, v) = (&f.z[l.q()], &f.z[l.v()]);
        assert!(
            current(f.plant.data(), q, v),
            "the sensors' pass is at the frame"
        );
        let values = signals.values(f)?.to_vec();
        assert_momentum(&values, independent(f));
        frames += 1;
        Ok(())
    };
    let (_, sim) = sc.run(plant, Method::Rk4, &mut observer).unwrap();
    assert_eq!(frames, 21);
    // Away from the plant's pass (it holds another state) the recorder's own pass gives the
    // same values.
    let mut plant = sim.plant().clone();
    let z = sim.state().to_vec();
    let mut elsewhere = z.clone();
    elsewhere[l.v().start] += 1e-3;
    plant.state_outputs(&elsewhere).unwrap();
    assert!(!current(plant.data(), &z[l.q()], &z[l.v()]));
    let commands = Commands::new(plant.mode(), plant.actuators().len());
    let sensors = Sensors::new(&plant);
    let frame = Frame {
        t: 0.0,
        z: &z,
        plant: &plant,
        sensors: &sensors,
        commands: &commands,
    };
    let values = signals.values(&frame).unwrap().to_vec();
    assert_momentum(&values, independent(&frame));
}
