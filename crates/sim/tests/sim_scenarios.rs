//! The three scenarios on Lola Type 2 / Type 3 with RK4 at the 1 ms control period.

use biped_robots::lola::LolaType;
use biped_sim::ode::Method;
use biped_sim::plant::{lola_plant, PlantConfig};
use biped_sim::scenario::{build, ScenarioKind, ScenarioOptions};

fn run(
    variant: LolaType,
    kind: ScenarioKind,
    duration: Option<f64>,
) -> biped_sim::simulation::Summary {
    let mut lp = lola_plant(variant, PlantConfig::default()).unwrap();
    let opts = ScenarioOptions {
        duration,
        ..ScenarioOptions::lola()
    };
    let sc = build(kind, &mut lp.plant, &opts).unwrap();
    let (summary, _) = sc.run(lp.plant, Method::Rk4, &mut |_| Ok(())).unwrap();
    println!("{}", serde_json::to_string_pretty(&summary).unwrap());
    summary
}

#[test]
fn stand_type2_comes_to_rest_and_carries_its_weight() {
    let s = run(LolaType::Type2, ScenarioKind::Stand, None);
    assert!(s.passed(), "{:?}", s.checks);
}

#[test]
#[ignore]
fn debug_stand() {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let opts = ScenarioOptions {
        duration: Some(3.0),
        ..ScenarioOptions::lola()
    };
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &opts).unwrap();
    let mut k = 0;
    let (summary, _) = sc
        .run(lp.plant, Method::Rk4, &mut |f| {
            if k % 100 == 0 {
                let o = &f.plant.last_outputs().contact;
                println!(
                    "t={:.2} base=({:.4},{:.4},{:.4}) quat=({:.4},{:.4},{:.4}) fz=({:.1},{:.1}) cop_l={:?} maxv={:.3e}",
                    f.t, f.z[0], f.z[1], f.z[2], f.z[3], f.z[4], f.z[5],
                    o.feet[0].force.z, o.feet[1].force.z,
                    o.feet[0].cop.map(|c| (c.x, c.y)),
                    f.z[32..63].iter().fold(0.0f64, |m, v| m.max(v.abs()))
                );
            }
            k += 1;
            Ok(())
        })
        .unwrap();
    println!("{}", serde_json::to_string_pretty(&summary.checks).unwrap());
}

#[test]
#[ignore]
fn debug_gains() {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let q0 = lp.plant.model().neutral();
    let m = lp.plant.actuator_inertias(&q0).unwrap();
    for (a, (s, r)) in lp.plant.actuators().iter().zip(&m) {
        println!(
            "{:20} sub {:10.4} rest {:10.4} nominal {:8.2} {:?}",
            a.name, s, r, a.nominal_ratio, a.transmission
        );
    }
}
