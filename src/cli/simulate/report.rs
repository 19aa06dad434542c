//! `summary.json` (the library's `Summary` plus the run's description) and the text report on
//! stdout.

use super::setup::{Info, StepRule};
use crate::cli::out::outln;
use biped_sim::controller::{Controller, JointPd, StanceDamping};
use biped_sim::plant::Plant;
use biped_sim::record::Recorder;
use biped_sim::scenario::REST_CHECK;
use biped_sim::simulation::Summary;
use serde_json::{json, Value};
use std::path::Path;

/// Result of this module.
type OutResult<T> = Result<T, Box<dyn std::error::Error>>;

/// `summary.json`: the library summary plus the run's description and final heights.
pub fn summary_json(
    s: &Summary,
    base: Option<f64>,
    plant: &Plant,
    info: &Info,
    files: &[String],
) -> OutResult<Value> {
    let mut v = serde_json::to_value(s)?;
    let (step, tolerances) = match info.step {
        StepRule::Fixed(h) => (json!(h), Value::Null),
        StepRule::Adaptive(r, a) => (Value::Null, json!({"rtol": r, "atol": a})),
    };
    let extra = json!({
        "model": info.model,
        "scenario": info.scenario,
        "step": step,
        "tolerances": tolerances,
        "passed": s.passed(),
        "final_base_height": base,
        "final_com_height": s.final_com[2],
        "actuators": plant.actuators().len(),
        "files": files,
    });
    if let (Value::Object(map), Value::Object(more)) = (&mut v, extra) {
        map.extend(more);
    }
    Ok(v)
}

/// Height of the floating base in the last recorded row.
pub fn final_base_height(rec: &Recorder, plant: &Plant) -> Option<f64> {
    let (qi, _) = plant.floating_base()?;
    rec.column(&super::output::q_column(plant, qi + 2))
        .ok()?
        .last()
        .copied()
}

/// The IMU damping through the ankles in one line: how many ankles, gain and cutoff ranges.
fn stance_line(d: &StanceDamping) -> String {
    let range = |f: fn(&biped_sim::controller::StanceAnkle) -> f64| {
        let it = d.ankles().iter().map(f);
        let lo = it.clone().fold(f64::INFINITY, f64::min);
        let hi = it.fold(f64::NEG_INFINITY, f64::max);
        if lo == hi {
            format!("{lo:.3e}")
        } else {
            format!("{lo:.3e}-{hi:.3e}")
        }
    };
    format!(
        "stance damping: {} ankles, gain {} N m s/rad, gyroscope low-pass {} rad/s",
        d.ankles().len(),
        range(|a| a.gain),
        range(|a| a.cutoff)
    )
}

/// For a failed rest check on a model without rotors whose fastest coordinate is an actuated
/// joint that the zero-order hold left with under half the damping its bandwidth asks for (a
/// light subtree, typically a URDF joint without its motor's rotor inertia): its capped gains
/// and what to add.
fn rest_hint(s: &Summary, plant: &Plant, pd: &JointPd) -> Option<String> {
    let failed =
        !plant.model().has_rotors() && s.checks.iter().any(|c| c.name == REST_CHECK && !c.passed);
    let joint = s.final_fastest.as_deref().filter(|_| failed)?;
    let k = plant.actuators().iter().position(|a| a.name == joint)?;
    let (kd, want) = (pd.kd()[k], pd.kd_wanted().nth(k)?);
    let kp = pd.kp()[k];
    (kd < 0.5 * want).then(|| {
        format!(
            "the {:.0} Hz hold caps `{joint}`'s gains at k_p {kp:.2e} N m/rad, k_d {kd:.2e} \
             N m s/rad (its bandwidth asks for k_d {want:.2e}): a joint that moves this little \
             inertia needs its motor's rotor inertia (--armature) to be held",
            1.0 / pd.period()
        )
    })
}

/// Text report on stdout: what ran, how fast, the checks, where the files are.
pub fn print_report(
    s: &Summary,
    plant: &Plant,
    rec: &Recorder,
    info: &Info,
    pd: &JointPd,
    dir: &Path,
    files: &[String],
) -> std::io::Result<()> {
    let step = match info.step {
        StepRule::Fixed(h) => format!("h = {h} s"),
        StepRule::Adaptive(r, a) => format!("rtol {r:e}, atol {a:e}"),
    };
    outln!(
        "{} on {}, {} ({step})",
        info.scenario,
        info.model,
        info.method
    )?;
    outln!(
        "  {:.3} s simulated in {:.3} s: realtime factor {:.3}; {} steps, {} rhs evaluations",
        s.sim_time,
        s.wall_time,
        s.realtime_factor,
        s.steps,
        s.rhs_evaluations
    )?;
    if let Some(z) = final_base_height(rec, plant) {
        outln!(
            "  final base height {z:.4} m, CoM height {:.4} m",
            s.final_com[2]
        )?;
    }
    outln!(
        "  contact force: final {:.1} N, max {:.1} N (weight {:.1} N)",
        s.final_contact_force,
        s.max_contact_force,
        s.weight
    )?;
    let p = &s.passive;
    if let Some(f) = &p.fastest {
        outln!(
            "  joint layer: {} end stops, {} damping/friction laws (fastest: {} of `{}`, {:.3e} 1/s)",
            p.end_stops, p.friction_laws, f.law, f.joint, f.rate
        )?;
    }
    if let Some(d) = pd.stance_damping() {
        outln!("  {}", stance_line(d))?;
    }
    if let Some(m) = &s.drive_limits.most {
        outln!(
            "  drive limits cut commands in {} of {} control cycles (most often `{}`: {})",
            s.drive_limits.cycles,
            s.control_cycles,
            m.joint,
            m.cycles
        )?;
    }
    for c in &s.checks {
        let verdict = if c.passed { "ok" } else { "FAILED" };
        let at = match (&s.final_fastest, c.name == REST_CHECK && !c.passed) {
            (Some(j), true) => format!(", fastest `{j}`"),
            _ => String::new(),
        };
        outln!(
            "  {verdict:>6}: {} {:.3e} (limit {:.3e}){at}",
            c.name,
            c.value,
            c.limit
        )?;
    }
    if let Some(h) = rest_hint(s, plant, pd) {
        outln!("  hint: {h}")?;
    }
    let failed = s.checks.iter().filter(|c| !c.passed).count();
    match failed {
        0 => outln!("  pass criteria: all {} hold", s.checks.len())?,
        n => outln!("  pass criteria: {n} of {} FAILED", s.checks.len())?,
    }
    outln!("wrote {}: {}", dir.display(), files.join(", "))
}
