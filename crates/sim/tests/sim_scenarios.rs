//! The three scenarios on Lola Type 2 (RK4 at the 1 ms control period) and Type 3 (RK4 at
//! 0.1 ms for its stiff gears), checked by their pass criteria: a standing robot comes to rest
//! and its contact force equals its weight within 0.1 %.

use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::controller::JointPd;
use biped_sim::drive::DriveMode;
use biped_sim::ode::{Method, Settings};
use biped_sim::plant::PlantConfig;
use biped_sim::scenario::{build, ScenarioKind, ScenarioOptions};
use biped_sim::simulation::{Simulation, Summary};

fn run(variant: LolaType, kind: ScenarioKind, h: f64, duration: Option<f64>) -> Summary {
    run_sim(variant, kind, h, duration).0
}

fn run_sim(
    variant: LolaType,
    kind: ScenarioKind,
    h: f64,
    duration: Option<f64>,
) -> (Summary, Simulation<JointPd>) {
    let mut lp = lola_plant(variant, PlantConfig::default()).unwrap();
    let opts = ScenarioOptions {
        duration,
        ..ScenarioOptions::lola()
    };
    let sc = build(kind, &mut lp.plant, &opts).unwrap();
    let (summary, sim) = sc
        .run_with(lp.plant, Method::Rk4, Settings::fixed(h), &mut |_| Ok(()))
        .unwrap();
    println!("{}", serde_json::to_string_pretty(&summary).unwrap());
    assert_eq!(summary.drive_mode, DriveMode::Torque);
    (summary, sim)
}

#[test]
fn stand_type2_comes_to_rest_and_carries_its_weight() {
    let (s, sim) = run_sim(LolaType::Type2, ScenarioKind::Stand, 1e-3, None);
    // At rest the sensors see the weight: F/T z-forces sum to m g (feet level), the IMU
    // reads the specific force +g along the (nearly upright) base z axis.
    let sensors = sim.sensors();
    let fz: f64 = sensors.foot_wrenches.iter().map(|w| w.lin.z).sum();
    assert!(
        (fz - s.weight).abs() < 2e-3 * s.weight,
        "F/T {fz} vs weight {}",
        s.weight
    );
    let imu = sensors.imu.expect("floating base has an IMU");
    let g = imu.linear_acceleration;
    assert!(
        (g.z - 9.81).abs() < 1e-2 && g.x.abs() < 2e-2 && g.y.abs() < 2e-2,
        "IMU {g:?}"
    );
    assert!(s.passed(), "{:?}", s.checks);
    // 16 sole points as in Table 2.3 plus 2 x 5 on the toes (the toe rectangles' 8 points,
    // their rear edges the soles' front edges): 2 bristle states each.
    assert_eq!(s.layout.table_2_3(), [31, 52, 0, 115]);
    let err = (s.final_contact_force - s.weight).abs() / s.weight;
    assert!(
        err < 1e-3,
        "contact force {} vs weight {}",
        s.final_contact_force,
        s.weight
    );
}

#[test]
fn drop_type2_lands_and_comes_to_rest() {
    let s = run(LolaType::Type2, ScenarioKind::Drop, 1e-3, None);
    assert!(s.passed(), "{:?}", s.checks);
    assert!(
        s.max_contact_force > s.weight,
        "the landing impact exceeds the weight"
    );
}

#[test]
fn sway_type2_shifts_the_pelvis_between_the_feet() {
    let s = run(LolaType::Type2, ScenarioKind::Sway, 1e-3, None);
    assert!(s.passed(), "{:?}", s.checks);
}

#[test]
fn stand_type3_comes_to_rest_and_carries_its_weight() {
    let s = run(LolaType::Type3, ScenarioKind::Stand, 1e-4, Some(4.0));
    assert_eq!(s.layout.table_2_3(), [47, 52, 0, 147]);
    assert!(s.passed(), "{:?}", s.checks);
}

#[test]
fn stand_type2_in_current_mode_with_an_ideal_current_loop() {
    let config = PlantConfig {
        mode: DriveMode::Current,
        ..PlantConfig::default()
    };
    let mut lp = lola_plant(LolaType::Type2, config).unwrap();
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &ScenarioOptions::lola()).unwrap();
    let plant = lp.plant;
    let (p2, q0) = (plant.clone(), sc.q0.clone());
    let wrap = |pd: biped_sim::controller::JointPd| pd.with_current_output(&p2, &q0);
    let (s, _) = sc
        .run_wrapped(plant, wrap, Method::Rk4, Settings::fixed(1e-3), &mut |_| {
            Ok(())
        })
        .unwrap();
    println!("{}", serde_json::to_string_pretty(&s.checks).unwrap());
    assert_eq!(s.drive_mode, DriveMode::Current);
    assert!(s.passed(), "{:?}", s.checks);
}

/// Voltage mode: the currents are states (L/R = 0.4 ms), so RK4 runs at 50 us; a 1 kHz joint
/// PD with current output over a 10 kHz current PI.
#[test]
fn stand_type2_in_voltage_mode_with_a_cascaded_current_loop() {
    use biped_sim::controller::{Cascade, CurrentPi};
    let config = PlantConfig {
        mode: DriveMode::Voltage,
        ..PlantConfig::default()
    };
    let mut lp = lola_plant(LolaType::Type2, config).unwrap();
    let opts = ScenarioOptions {
        duration: Some(1.0),
        ..ScenarioOptions::lola()
    };
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &opts).unwrap();
    let plant = lp.plant;
    let (p2, q0, n) = (plant.clone(), sc.q0.clone(), plant.actuators().len());
    let wrap = |pd: JointPd| {
        let outer = pd.with_current_output(&p2, &q0)?;
        Cascade::new(outer, CurrentPi::new(&p2, 1e-4, 2.0, 2000.0)?, n)
    };
    let settings = Settings::fixed(5e-5);
    let (s, sim) = sc
        .run_wrapped(plant, wrap, Method::Rk4, settings, &mut |_| Ok(()))
        .unwrap();
    println!("{}", serde_json::to_string_pretty(&s.checks).unwrap());
    assert_eq!(s.layout.ncurrent, 25);
    assert_eq!(s.control_cycles, 10_000);
    let fell = s
        .checks
        .iter()
        .find(|c| c.name.starts_with("min base"))
        .unwrap();
    assert!(fell.passed, "{fell:?}");
    let err = (s.final_contact_force - s.weight).abs() / s.weight;
    assert!(
        err < 1e-2,
        "contact force {} vs weight {}",
        s.final_contact_force,
        s.weight
    );
    assert!(
        sim.sensors().motor_currents.iter().any(|i| i.abs() > 0.1),
        "motors carry current"
    );
}

/// A sway amplitude that takes a sway joint past its end stop at either extreme is rejected
/// naming that joint; one just inside the smallest margin of the four joints' ranges (read
/// from the plant's stops about the stand pose) builds.
#[test]
fn sway_amplitude_beyond_a_joint_range_is_an_error() {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let opts = ScenarioOptions::lola();
    let q0 = build(ScenarioKind::Stand, &mut lp.plant, &opts).unwrap().q0;
    let joints = opts.sway_joints.clone().unwrap();
    let names = joints.hips.iter().chain(&joints.ankles);
    let stops = lp.plant.passive().stops();
    let (margin, tightest) = names
        .map(|n| {
            let s = stops.iter().find(|s| &s.name == n).unwrap();
            ((s.upper - q0[s.q]).min(q0[s.q] - s.lower), n.clone())
        })
        .fold((f64::INFINITY, String::new()), |a, b| {
            if b.0 < a.0 {
                b
            } else {
                a
            }
        });
    assert!(margin > 0.0 && margin < 1.0, "margin {margin}");
    let with = |a: f64| ScenarioOptions {
        sway_amplitude: a,
        ..opts.clone()
    };
    assert!(build(ScenarioKind::Sway, &mut lp.plant, &with(0.999 * margin)).is_ok());
    let e = build(ScenarioKind::Sway, &mut lp.plant, &with(1.001 * margin)).unwrap_err();
    let msg = e.to_string();
    assert!(
        msg.contains("sway amplitude") && msg.contains(&tightest),
        "{msg}"
    );
    for bad in [0.0, -0.1, f64::NAN] {
        assert!(build(ScenarioKind::Sway, &mut lp.plant, &with(bad)).is_err());
    }
}

/// An unknown sway joint is reported as a sway joint (not as a pose joint, whose errors the
/// caller attributes to the start pose), whichever of the four it is.
#[test]
fn unknown_sway_joint_is_a_sway_joint_error() {
    use biped_sim::scenario::SwayJoints;
    use biped_sim::SimError;
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let good = ScenarioOptions::lola().sway_joints.unwrap();
    for k in 0..4 {
        let mut names: Vec<String> = good.hips.iter().chain(&good.ankles).cloned().collect();
        names[k] = "no_such_joint".into();
        let opts = ScenarioOptions {
            sway_joints: Some(SwayJoints {
                hips: [names[0].clone(), names[1].clone()],
                ankles: [names[2].clone(), names[3].clone()],
            }),
            ..ScenarioOptions::lola()
        };
        match build(ScenarioKind::Sway, &mut lp.plant, &opts) {
            Err(SimError::Unknown { kind, name }) => {
                assert_eq!(
                    (kind, name.as_str()),
                    ("sway joint", "no_such_joint"),
                    "{k}"
                )
            }
            other => panic!("entry {k}: {other:?}"),
        }
    }
}
