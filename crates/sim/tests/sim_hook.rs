//! The controller hook (`Hooked`): it runs once per control cycle after the scenario's PD,
//! sees the PD's commands, and what it writes is what the plant holds; a hook that returns
//! commands of the wrong length or non-finite values ends the run with a typed error.

use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::controller::{Hook, Hooked};
use biped_sim::plant::PlantConfig;
use biped_sim::scenario::{self, ScenarioKind, ScenarioOptions};
use biped_sim::{Method, Settings, SimError};
use std::sync::{Arc, Mutex};

/// A 20-cycle stand of the Lola-like biped with `hook`; the commands held at each frame.
fn stand_with(hook: Hook) -> Result<Vec<Vec<f64>>, SimError> {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default())?;
    let mut stand = scenario::build(ScenarioKind::Stand, &mut lp.plant, &ScenarioOptions::lola())?;
    stand.duration = 0.02;
    let settings = Settings::fixed(stand.period());
    let mut held = Vec::new();
    let mut observe = |f: &biped_sim::simulation::Frame| {
        held.push(f.commands.values.clone());
        Ok(())
    };
    let wrap = |pd| Ok(Hooked::new(pd, Some(hook)));
    stand.run_wrapped(lp.plant, wrap, Method::Rk4, settings, &mut observe)?;
    Ok(held)
}

/// The time and the PD's commands of each call of the hook.
type Calls = Vec<(f64, Vec<f64>)>;

#[test]
fn the_hook_sees_the_pd_commands_and_its_commands_are_held() {
    let seen: Arc<Mutex<Calls>> = Arc::default();
    let log = seen.clone();
    let hook: Hook = Box::new(move |t, _sensors, commands| {
        log.lock().unwrap().push((t, commands.values.clone()));
        commands.values[0] += 1.5;
        Ok(())
    });
    let held = stand_with(hook).unwrap();
    let seen = seen.lock().unwrap();
    assert_eq!(seen.len(), 20, "one call per control cycle");
    for (k, (t, pd)) in seen.iter().enumerate() {
        assert!((t - k as f64 * 1e-3).abs() < 1e-12);
        // The frame of cycle k shows the commands held from t on: the PD's plus the offset.
        assert_eq!(held[k][0], pd[0] + 1.5);
        assert_eq!(held[k][1..], pd[1..]);
    }
}

#[test]
fn bad_hook_commands_are_typed_errors() {
    let short: Hook = Box::new(|_, _, c| {
        c.values.pop();
        Ok(())
    });
    let e = stand_with(short).unwrap_err();
    assert!(matches!(e, SimError::Length { .. }), "{e}");
    let nan: Hook = Box::new(|_, _, c| {
        c.values[3] = f64::NAN;
        Ok(())
    });
    let e = stand_with(nan).unwrap_err();
    assert!(matches!(e, SimError::NonFinite { index: 3, .. }), "{e}");
    let fails: Hook = Box::new(|t, _, _| match t > 0.005 {
        true => Err(SimError::Controller("gave up".into())),
        false => Ok(()),
    });
    let e = stand_with(fails).unwrap_err();
    assert_eq!(e.to_string(), "controller: gave up");
}
