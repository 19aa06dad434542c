//! A URDF robot with a floating base (Unitree G1 from `crates/dynamics/data`) in the `stand`
//! scenario: feet = the ankle-roll links, sole rectangle spanning the URDF's four contact
//! spheres of each foot (centres x in [-0.05, 0.12], y in [-0.03, 0.03], z = -0.03, radius
//! 5 mm).

use biped_sim::contact::ContactParams;
use biped_sim::ode::{Method, Settings};
use biped_sim::plant::{urdf_plant, Armature, PlantConfig, UrdfFeet};
use biped_sim::scenario::{build, ScenarioKind, ScenarioOptions};
use biped_sim::simulation::Summary;
use nalgebra::Vector3;
use std::path::Path;

/// Reflected rotor inertias `N^2 J` of the G1's joints \[kg m^2], from Unitree's motor data as
/// listed in mujocolab/mjlab's G1 configuration (rotor inertias and planetary stages of the 7520-14.3, 7520-22.5, 5020-16 and 4010-25
/// motors; the ankles and waist pitch/roll are driven by two 5020 each), first match wins.
const G1_ARMATURE: [(&str, f64); 11] = [
    ("*_hip_pitch_joint", 0.0102),
    ("*_hip_yaw_joint", 0.0102),
    ("waist_yaw_joint", 0.0102),
    ("*_hip_roll_joint", 0.0251),
    ("*_knee_joint", 0.0251),
    ("*_ankle_*", 0.00722),
    ("waist_roll_joint", 0.00722),
    ("waist_pitch_joint", 0.00722),
    ("*_wrist_pitch_joint", 0.00425),
    ("*_wrist_yaw_joint", 0.00425),
    ("*", 0.00361),
];

/// `stand` on the G1 in a bent-knee pose for `duration`, with `armature` rotors and PD
/// bandwidth `bandwidth`.
fn g1_stand(armature: &[Armature], bandwidth: f64, duration: f64) -> Summary {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../dynamics/data/g1_29dof_rev_1_0.urdf");
    let mut feet = UrdfFeet::new("left_ankle_roll_link", "right_ankle_roll_link");
    feet.center = Vector3::new(0.035, 0.0, -0.035);
    feet.length = 0.17;
    feet.width = 0.055;
    let config = PlantConfig {
        contact: ContactParams::light_feet(),
        ..PlantConfig::default()
    };
    let mut plant = urdf_plant(&path, &feet, armature, config).unwrap();
    assert_eq!(plant.actuators().len(), 29);
    assert_eq!(plant.layout().ncontact, 32);
    let mut pose = Vec::new();
    for side in ["left", "right"] {
        pose.push((format!("{side}_hip_pitch_joint"), -0.2));
        pose.push((format!("{side}_knee_joint"), 0.4));
        pose.push((format!("{side}_ankle_pitch_joint"), -0.2));
    }
    let opts = ScenarioOptions {
        pose,
        duration: Some(duration),
        bandwidth,
        ..ScenarioOptions::default()
    };
    let sc = build(ScenarioKind::Stand, &mut plant, &opts).unwrap();
    let (s, _) = sc
        .run_with(plant, Method::Rk4, Settings::fixed(1e-3), &mut |_| Ok(()))
        .unwrap();
    println!("{}", serde_json::to_string_pretty(&s.checks).unwrap());
    s
}

#[test]
fn g1_stands_on_its_soles_and_carries_its_weight() {
    let s = g1_stand(&[], ScenarioOptions::default().bandwidth, 3.0);
    // Known limitation without rotors: the G1's ankle-roll joints (articulated inertia
    // ~1e-4 kg m^2, no rotor inertia in the URDF) keep a limit cycle on the 55 mm wide soles
    // under the ZOH-capped PD, so `stand`'s rest criterion is not met; the robot stands and
    // carries its weight.
    let fell = s
        .checks
        .iter()
        .find(|c| c.name.starts_with("min base"))
        .unwrap();
    assert!(fell.passed, "the G1 fell: {fell:?}");
    let err = (s.final_contact_force - s.weight).abs() / s.weight;
    assert!(
        err < 0.05,
        "contact force {} vs weight {}",
        s.final_contact_force,
        s.weight
    );
}

/// With its motors' rotor inertia (geared rotor bodies) and a 20 rad/s PD the G1 comes to
/// rest: every `stand` criterion holds, and the residual motion decays (not a limit cycle).
#[test]
fn g1_with_rotors_comes_to_rest() {
    let armature: Vec<Armature> = G1_ARMATURE
        .iter()
        .map(|(p, a)| Armature {
            pattern: p.to_string(),
            inertia: *a,
            required: true,
        })
        .collect();
    let short = g1_stand(&armature, 20.0, 3.0);
    assert!(short.checks.iter().all(|c| c.passed), "{:?}", short.checks);
    let long = g1_stand(&armature, 20.0, 8.0);
    assert!(long.checks.iter().all(|c| c.passed), "{:?}", long.checks);
    let rest = |s: &Summary| {
        let c = s
            .checks
            .iter()
            .find(|c| c.name.starts_with("final max |v|"));
        c.expect("rest criterion").value
    };
    assert!(
        rest(&long) < 0.1 * rest(&short),
        "still moving: max |v| {} at 3 s, {} at 8 s",
        rest(&short),
        rest(&long)
    );
    let err = (long.final_contact_force - long.weight).abs() / long.weight;
    assert!(
        err < 1e-4,
        "contact force {} vs weight {}",
        long.final_contact_force,
        long.weight
    );
}

#[test]
fn armature_patterns_must_name_revolute_joints() {
    let typo = |required| Armature {
        pattern: "*_elbow_jiont".into(),
        inertia: 0.01,
        required,
    };
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../dynamics/data/g1_29dof_rev_1_0.urdf");
    let feet = UrdfFeet::new("left_ankle_roll_link", "right_ankle_roll_link");
    let err = urdf_plant(&path, &feet, &[typo(true)], PlantConfig::default()).unwrap_err();
    assert!(
        err.to_string().contains("matches no revolute joint"),
        "{err}"
    );
    // An optional entry (an SRDF rotor of a joint the URDF lacks) is skipped: no rotor body.
    let bare = urdf_plant(&path, &feet, &[], PlantConfig::default()).unwrap();
    let skipped = urdf_plant(&path, &feet, &[typo(false)], PlantConfig::default()).unwrap();
    assert_eq!(skipped.model().nbodies(), bare.model().nbodies());
    let negative = [Armature {
        pattern: "*_knee_joint".into(),
        inertia: -0.01,
        required: false,
    }];
    let err = urdf_plant(&path, &feet, &negative, PlantConfig::default()).unwrap_err();
    assert!(err.to_string().contains("armature"), "{err}");
}

/// The G1 plant carries the URDF's joint ranges as end stops and its efforts as torque limits
/// (read back from the importer's `JointProps`); switching the layer off leaves none.
#[test]
fn g1_plant_has_the_urdf_ranges_and_efforts() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../dynamics/data/g1_29dof_rev_1_0.urdf");
    let opts = biped_dynamics::urdf::UrdfOptions {
        floating: true,
        reject_mimic: false,
    };
    let props = biped_dynamics::urdf::load_file(&path, &opts)
        .unwrap()
        .joints;
    let feet = UrdfFeet::new("left_ankle_roll_link", "right_ankle_roll_link");
    let plant = urdf_plant(&path, &feet, &[], PlantConfig::default()).unwrap();
    let stops = plant.passive().stops();
    assert_eq!(stops.len(), props.len());
    assert!(
        plant.passive().friction().is_empty(),
        "the G1 has no <dynamics>"
    );
    for j in &props {
        let s = stops.iter().find(|s| s.name == j.name).unwrap();
        assert_eq!(Some([s.lower, s.upper]), j.range, "{}", j.name);
        let a = plant.actuators().iter().find(|a| a.name == j.name).unwrap();
        assert_eq!((Some(a.effort), a.joint_v), (j.effort, s.v), "{}", j.name);
        let n_kt = a.nominal_ratio * a.motor.torque_constant;
        assert!((a.motor.max_current * n_kt - a.effort).abs() < 1e-12 * a.effort);
    }
    let mut config = PlantConfig::default();
    config.passive.end_stops = false;
    let plant = urdf_plant(&path, &feet, &[], config).unwrap();
    assert!(plant.passive().is_empty());
}
