//! A diverging run is told apart from a setup error (`SimError::is_divergence`): absurd joint
//! gains blow the standing robot up within a few control periods.

use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::controller::JointPd;
use biped_sim::plant::PlantConfig;
use biped_sim::scenario::{build, ScenarioKind, ScenarioOptions};
use biped_sim::simulation::Simulation;
use biped_sim::{Method, SimError};

#[test]
fn absurd_gains_diverge_and_say_so() {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &ScenarioOptions::lola()).unwrap();
    let n = lp.plant.actuators().len();
    let target: Vec<f64> = lp
        .plant
        .actuators()
        .iter()
        .map(|a| sc.q0[a.joint_q])
        .collect();
    // k_p T^2 / m ~ 1e3 per joint: the sampled loop grows by orders of magnitude per period.
    let pd = JointPd::new(1e-3, target, vec![1e9; n], vec![0.0; n]).unwrap();
    let mut sim = Simulation::new(lp.plant, pd, Method::Rk4, sc.z0.clone()).unwrap();
    // Gravity deflects the joints from the targets at once; the loop amplifies it.
    let e = sim.run(1.0, &mut |_| Ok(())).unwrap_err();
    println!("t = {}: {e}", sim.time());
    assert!(e.is_divergence(), "{e:?}");
    assert!(sim.time() < 0.5, "diverged early: t = {}", sim.time());
    assert!(sim.time() > 0.0);
    // Setup errors and stops are not divergences.
    let setup = sim.run(-1.0, &mut |_| Ok(())).unwrap_err();
    assert!(!setup.is_divergence(), "{setup:?}");
    assert!(!SimError::Stopped("signal".into()).is_divergence());
    assert!(!SimError::Integrator("bad settings".into()).is_divergence());
}
