//! Recorded signals: names and CSV output, and a physics check on the recorded centroidal
//! angular momentum — without contact it is conserved (gravity acts at the CoM, drive torques
//! are internal), whatever the joint PD does.

use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::drive::FrictionParams;
use biped_sim::ode::Method;
use biped_sim::plant::PlantConfig;
use biped_sim::record::Recorder;
use biped_sim::scenario::{build, ScenarioKind, ScenarioOptions};
use biped_sim::simulation::Signals;

#[test]
fn flying_robot_records_conserved_centroidal_momentum_and_writes_csv() {
    let config = PlantConfig {
        friction: FrictionParams::none(),
        ..PlantConfig::default()
    };
    let mut lp = lola_plant(LolaType::Type2, config).unwrap();
    let opts = ScenarioOptions {
        drop_height: 2.0,
        duration: Some(0.3),
        ..ScenarioOptions::lola()
    };
    let mut sc = build(ScenarioKind::Drop, &mut lp.plant, &opts).unwrap();
    // Spin the base so that there is angular momentum to conserve, and start the PD away from
    // its target so that the joints move.
    let l = lp.plant.layout();
    sc.z0[l.v().start + 3] = 0.5;
    sc.z0[l.v().start + 5] = -0.3;
    sc.z0[l.q().start + 10] += 0.1;
    let mut signals = Signals::new(&lp.plant, true);
    let names = signals.names().to_vec();
    assert!(names.iter().any(|n| n == "left.tz") && names.iter().any(|n| n == "L_G.z"));
    let mut rec = Recorder::new();
    let (_, _) = sc
        .run(lp.plant, Method::Rk4, &mut |f| signals.record(f, &mut rec))
        .unwrap();
    assert_eq!(rec.len(), 301);
    let lz = rec.column("L_G.x").unwrap();
    let scale = lz.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    assert!(scale > 0.1, "the base spin gives angular momentum");
    for c in ["L_G.x", "L_G.y", "L_G.z"] {
        let col = rec.column(c).unwrap();
        let drift = col.iter().map(|x| (x - col[0]).abs()).fold(0.0, f64::max);
        assert!(drift < 1e-4 * scale, "{c} drifts by {drift} (RK4 at 1 ms)");
    }
    assert!(
        rec.column("left.fz").unwrap().iter().all(|&f| f == 0.0),
        "no contact in flight"
    );
    let dir = std::env::temp_dir().join(format!("biped_sim_record_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("signals.csv");
    rec.write_csv(&path).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let header = text.lines().next().unwrap();
    assert!(header.starts_with("time,q[root.x],"), "{header}");
    assert_eq!(text.lines().count(), 302);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A recorder whose columns do not line up with the signals (some registered before) gets the
/// same values per name as a fresh one (the block write and the per-signal write agree).
#[test]
fn recording_into_a_prefilled_recorder_matches_a_fresh_one() {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let opts = ScenarioOptions {
        duration: Some(0.01),
        ..ScenarioOptions::lola()
    };
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &opts).unwrap();
    let (mut a, mut b) = (Signals::new(&lp.plant, true), Signals::new(&lp.plant, true));
    let (mut fresh, mut mixed) = (Recorder::new(), Recorder::new());
    mixed.register("extra").unwrap();
    mixed.register("v[root.wx]").unwrap();
    let (_, _) = sc
        .run(lp.plant, Method::Rk4, &mut |f| {
            a.record(f, &mut fresh)?;
            b.record(f, &mut mixed)
        })
        .unwrap();
    assert_eq!(fresh.len(), 11);
    for name in a.names() {
        let (x, y) = (fresh.column(name).unwrap(), mixed.column(name).unwrap());
        assert!(x.iter().all(|v| v.is_finite()), "{name}");
        assert_eq!(x, y, "{name}");
    }
    assert!(mixed.column("extra").unwrap().iter().all(|v| v.is_nan()));
}
