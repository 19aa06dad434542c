//! No heap allocation per right-hand side or per control cycle (issue item 9): a counting
//! global allocator around the Lola Type 2 plant.

use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::ode::{Method, OdeSystem};
use biped_sim::plant::PlantConfig;
use biped_sim::scenario::{build, ScenarioKind, ScenarioOptions};
use biped_sim::simulation::Simulation;
use biped_test_support::alloc::{count, Counting};

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn rhs_and_control_cycles_do_not_allocate() {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &ScenarioOptions::lola()).unwrap();
    let mut plant = lp.plant.clone();
    let z = sc.z0.clone();
    let mut zdot = vec![0.0; z.len()];
    plant.rhs(0.0, &z, &mut zdot).unwrap();
    let n = count(|| {
        for _ in 0..100 {
            plant.rhs(0.0, &z, &mut zdot).unwrap();
        }
    });
    assert_eq!(n, 0, "{n} allocations in 100 right-hand sides");

    // Whole loop: allocations of a run must not grow with the number of cycles.
    let mut sim = Simulation::new(lp.plant, sc.controller, Method::Rk4, sc.z0).unwrap();
    sim.run(0.01, &mut |_| Ok(())).unwrap();
    let short = count(|| {
        sim.run(0.01, &mut |_| Ok(())).unwrap();
    });
    let long = count(|| {
        sim.run(0.1, &mut |_| Ok(())).unwrap();
    });
    assert_eq!(
        short, long,
        "a 10x longer run allocated {long} times vs {short}"
    );
}
