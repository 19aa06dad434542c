//! IMU damping through the ankles (`StanceDamping`, `JointPd::with_stance_damping`): which
//! joints are the ankles, the filtered law itself, and that it damps the rigid rocking of a
//! stiffly held robot on its soles, a mode the joint PD does not see.

use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::controller::StanceDamping;
use biped_sim::ode::{Method, Settings};
use biped_sim::plant::{urdf_plant, AnkleAxis, PlantConfig, UrdfFeet};
use biped_sim::scenario::{build, ScenarioKind, ScenarioOptions};
use biped_sim::simulation::Summary;
use nalgebra::Vector3;
use std::path::Path;

/// Names of the ankle actuators the plant finds, with each axis's dominant base-frame
/// component (0 = x, roll; 1 = y, pitch).
fn ankle_names(plant: &mut biped_sim::plant::Plant) -> Vec<(String, usize)> {
    let q = plant.model().neutral();
    let ankles = plant.ankle_axes(&q).unwrap();
    ankles
        .iter()
        .map(|a| {
            assert!(a.axis.z == 0.0 && a.axis.norm() > 0.9, "{a:?}");
            let dominant = if a.axis.x.abs() > a.axis.y.abs() {
                0
            } else {
                1
            };
            (plant.actuators()[a.actuator].name.clone(), dominant)
        })
        .collect()
}

#[test]
fn the_ankles_are_each_foots_roll_and_pitch_joints() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../dynamics/data/g1_29dof_rev_1_0.urdf");
    let feet = UrdfFeet::new("left_ankle_roll_link", "right_ankle_roll_link");
    let mut g1 = urdf_plant(&path, &feet, &[], PlantConfig::default()).unwrap();
    // Named so by the URDF: the roll joint carries the foot, the pitch joint the roll link.
    let expected: Vec<(String, usize)> = ["left", "right"]
        .iter()
        .flat_map(|s| {
            [
                (format!("{s}_ankle_roll_joint"), 0),
                (format!("{s}_ankle_pitch_joint"), 1),
            ]
        })
        .collect();
    assert_eq!(ankle_names(&mut g1), expected);
    let mut lola = lola_plant(LolaType::Type2, PlantConfig::default())
        .unwrap()
        .plant;
    let names: Vec<String> = ankle_names(&mut lola).into_iter().map(|(n, _)| n).collect();
    assert_eq!(
        names,
        ["l_foot", "l_ankle_cross", "r_foot", "r_ankle_cross"]
    );
}

#[test]
fn the_law_is_a_first_order_low_pass_of_the_gyroscope() {
    let (c, w, t) = (300.0, 40.0, 1e-3);
    let axis = Vector3::new(0.0, 1.0, 0.0);
    let ankles = [AnkleAxis { actuator: 1, axis }];
    let mut s = StanceDamping::new(&ankles, &[(0.0, w), (c, w)], t)
        .unwrap()
        .unwrap();
    let omega = Vector3::new(0.3, -0.2, 0.5);
    let alpha = 1.0 - (-w * t).exp();
    for n in 1..=50 {
        let mut tau = [0.0, 1.0];
        s.add_to(&omega, &mut tau);
        // Step response of y_k = y_(k-1) + alpha (u - y_(k-1)), y_0 = 0.
        let expected = 1.0 + c * omega.y * (1.0 - (1.0 - alpha).powi(n));
        assert_eq!(tau[0], 0.0);
        assert!(
            (tau[1] - expected).abs() < 1e-12 * c,
            "step {n}: {} vs {expected}",
            tau[1]
        );
    }
    // No positive gain: no damping; bad gains, cutoffs and indices are errors.
    assert!(StanceDamping::new(&ankles, &[(0.0, w), (0.0, w)], t)
        .unwrap()
        .is_none());
    for bad in [
        [(0.0, w), (-1.0, w)],
        [(0.0, w), (c, 0.0)],
        [(0.0, w), (f64::NAN, w)],
    ] {
        assert!(StanceDamping::new(&ankles, &bad, t).is_err(), "{bad:?}");
    }
    assert!(StanceDamping::new(&ankles, &[(c, w)], t).is_err());
}

fn lola_stand(stance_damping: bool) -> Summary {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let opts = ScenarioOptions {
        stance_damping,
        ..ScenarioOptions::lola()
    };
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &opts).unwrap();
    assert_eq!(sc.controller.stance_damping().is_some(), stance_damping);
    let (s, _) = sc
        .run_with(
            lp.plant,
            Method::Rk4,
            Settings::fixed(1e-3),
            &mut |_| Ok(()),
        )
        .unwrap();
    s
}

/// Lola stands at rest either way, but the damping the hold's cap takes from the stance
/// ankles leaves a slowly decaying stance motion after 3 s; with the IMU damping through the
/// ankles it has decayed by orders of magnitude more.
#[test]
fn it_damps_the_stance_motion() {
    let (off, on) = (lola_stand(false), lola_stand(true));
    assert!(
        off.passed() && on.passed(),
        "{:?} {:?}",
        off.checks,
        on.checks
    );
    assert!(
        on.final_max_speed < 1e-2 * off.final_max_speed,
        "{} vs {}",
        on.final_max_speed,
        off.final_max_speed
    );
}
