//! From command-line options to a ready-to-run job: the plant (Lola or URDF), the scenario and
//! the integrator. Every input error names the option it comes from.

use super::SimulateArgs;
use biped_robots::lola::LolaType;
use biped_sim::controller::JointPd;
use biped_sim::ode::{Method, Settings};
use biped_sim::plant::{lola_plant, urdf_plant, Plant, PlantConfig, UrdfFeet};
use biped_sim::scenario::{build, Scenario, ScenarioKind, ScenarioOptions, SwayJoints};
use biped_sim::simulation::{Frame, Simulation, Summary};
use biped_sim::SimError;
use nalgebra::Vector3;
use std::path::Path;

/// Error of this module: one line naming the option.
type SetupError = Box<dyn std::error::Error>;

/// Fixed step of Type 3 \[s]: its elastic gears (~9000 rad/s on the toe) need <= 0.25 ms.
const TYPE3_STEP: f64 = 1e-4;

/// Contact stiffness and damping per point of URDF robots \[N/m, N s/m]: their feet carry no
/// reflected rotor inertia, so Lola's 2e5 / 400 puts the foot's damping eigenvalue
/// (`8 d / m_foot`, ~5000 1/s on the G1) outside RK4's stability region at 1 ms.
const URDF_CONTACT: [f64; 2] = [5e4, 100.0];

/// Largest number of recorded rows reserved up front (longer runs grow the recorder).
const MAX_RESERVED_ROWS: usize = 1 << 20;

/// What the run was, for the report and `summary.json`.
#[derive(Debug, Clone)]
pub struct Info {
    /// Model label, e.g. `Lola Type2` or the URDF path.
    pub model: String,
    /// Scenario name.
    pub scenario: &'static str,
    /// Integration method.
    pub method: Method,
    /// Fixed step \[s] (fixed-step methods) or `(rtol, atol)` (dopri5).
    pub step: StepRule,
}

/// Step rule of the integrator.
#[derive(Debug, Clone, Copy)]
pub enum StepRule {
    /// Fixed step \[s].
    Fixed(f64),
    /// Adaptive with relative and absolute tolerances.
    Adaptive(f64, f64),
}

/// Plant, scenario and integrator, ready to run.
pub struct Job {
    /// The plant.
    pub plant: Plant,
    /// The scenario built on it.
    pub scenario: Scenario,
    kind: ScenarioKind,
    settings: Settings,
    info: Info,
}

impl Job {
    /// Parses and validates every option, builds the plant and the scenario.
    pub fn from_args(a: &SimulateArgs) -> Result<Self, SetupError> {
        let kind: ScenarioKind = a.scenario.parse().map_err(|e| format!("--scenario: {e}"))?;
        let method: Method = a
            .integrator
            .parse()
            .map_err(|e| format!("--integrator: {e}"))?;
        let duration = positive("--duration", &a.duration)?;
        let pose = match &a.pose {
            Some(text) => parse_pose(text)?,
            None => Vec::new(),
        };
        let (mut plant, mut options, label, default_step) = match &a.urdf {
            Some(path) => urdf_source(a, path, kind)?,
            None => {
                urdf_only(a)?;
                lola_source(a)?
            }
        };
        for (name, angle) in pose {
            match options.pose.iter_mut().find(|(n, _)| *n == name) {
                Some(entry) => entry.1 = angle,
                None => options.pose.push((name, angle)),
            }
        }
        if duration < 0.5 * options.period {
            let p = options.period;
            return Err(format!(
                "--duration: {duration} s is shorter than one control period ({p} s)"
            )
            .into());
        }
        options.duration = Some(duration);
        let (settings, step) = integrator_settings(a, method, default_step)?;
        let scenario = build(kind, &mut plant, &options).map_err(|e| match e {
            SimError::Unknown { kind: "joint", .. } => format!("--pose: {e}"),
            e => format!("scenario {}: {e}", name(kind)),
        })?;
        let info = Info {
            model: label,
            scenario: name(kind),
            method,
            step,
        };
        Ok(Self {
            plant,
            scenario,
            kind,
            settings,
            info,
        })
    }

    /// Scenario name (`stand`, `drop`, `sway`).
    pub fn scenario_name(&self) -> &'static str {
        name(self.kind)
    }

    /// Description of the run.
    pub fn info(&self) -> Info {
        self.info.clone()
    }

    /// Rows the recorder should reserve (one per control period plus the final state).
    pub fn rows(&self) -> usize {
        let cycles = self.scenario.duration / self.scenario.period();
        (cycles.round() as usize)
            .saturating_add(1)
            .min(MAX_RESERVED_ROWS)
    }

    /// Runs the scenario with `observer` called once per control period and at the end.
    pub fn run(
        self,
        observer: &mut dyn FnMut(&Frame) -> Result<(), SimError>,
    ) -> Result<(Summary, Simulation<JointPd>), SimError> {
        let method = self.info.method;
        self.scenario
            .run_with(self.plant, method, self.settings, observer)
    }
}

/// Lower-case scenario name.
fn name(kind: ScenarioKind) -> &'static str {
    match kind {
        ScenarioKind::Drop => "drop",
        ScenarioKind::Stand => "stand",
        ScenarioKind::Sway => "sway",
    }
}

/// Plant, scenario options, label and default fixed step of the Lola-like biped.
type Source = (Plant, ScenarioOptions, String, f64);

/// The Lola-like biped of `crates/robots/data/lola.toml`.
fn lola_source(a: &SimulateArgs) -> Result<Source, SetupError> {
    let text = a.lola.as_deref().unwrap_or("type2");
    let variant: LolaType = text.parse().map_err(|e| format!("--lola: {e}"))?;
    let lp = lola_plant(variant, plant_config(a, None)?)?;
    let options = ScenarioOptions::lola();
    let step = match variant {
        LolaType::Type2 => options.period,
        LolaType::Type3 => TYPE3_STEP,
    };
    Ok((lp.plant, options, format!("Lola {variant:?}"), step))
}

/// Rejects the URDF options without `--urdf`.
fn urdf_only(a: &SimulateArgs) -> Result<(), String> {
    let given = [
        ("--floating", a.floating),
        ("--feet", a.feet.is_some()),
        ("--sole-center", a.sole_center.is_some()),
        ("--sole-size", a.sole_size.is_some()),
        ("--sway-joints", a.sway_joints.is_some()),
    ];
    match given.iter().find(|(_, on)| *on) {
        Some((option, _)) => Err(format!("{option}: only applies with --urdf FILE")),
        None => Ok(()),
    }
}

/// A floating-base URDF robot with the sole rectangles and sway joints of the options.
fn urdf_source(a: &SimulateArgs, path: &Path, kind: ScenarioKind) -> Result<Source, SetupError> {
    if a.lola.is_some() {
        return Err("--lola: give either --lola TYPE or --urdf FILE, not both".into());
    }
    if !a.floating {
        return Err(
            "--urdf: add --floating (the scenarios put a free-floating robot on the ground)".into(),
        );
    }
    let feet_text = a
        .feet
        .as_deref()
        .ok_or("--urdf: add --feet LEFT,RIGHT (the links carrying the soles)")?;
    let links = names(feet_text, 2, "--feet", "LEFT,RIGHT")?;
    let mut feet = UrdfFeet::new(&links[0], &links[1]);
    if let Some(text) = &a.sole_center {
        let c = numbers(text, 3, "--sole-center")?;
        feet.center = Vector3::new(c[0], c[1], c[2]);
    }
    if let Some(text) = &a.sole_size {
        let s = numbers(text, 2, "--sole-size")?;
        if s.iter().any(|x| *x <= 0.0) {
            return Err(format!("--sole-size: length and width must be > 0, got {text}").into());
        }
        (feet.length, feet.width) = (s[0], s[1]);
    }
    let config = plant_config(a, Some(URDF_CONTACT))?;
    let plant = urdf_plant(path, &feet, config).map_err(|e| match e {
        SimError::InvalidParameter { what, reason } if what == "urdf" => reason,
        e @ SimError::Unknown { .. } => format!("--feet: {e} in {}", path.display()),
        e => format!("{}: {e}", path.display()),
    })?;
    let sway_joints =
        match &a.sway_joints {
            Some(text) => {
                let j = names(text, 4, "--sway-joints", "HIP_L,HIP_R,ANKLE_L,ANKLE_R")?;
                Some(SwayJoints {
                    hips: [j[0].clone(), j[1].clone()],
                    ankles: [j[2].clone(), j[3].clone()],
                })
            }
            None if kind == ScenarioKind::Sway => return Err(
                "--scenario sway on a URDF robot needs --sway-joints HIP_L,HIP_R,ANKLE_L,ANKLE_R"
                    .into(),
            ),
            None => None,
        };
    let options = ScenarioOptions {
        sway_joints,
        ..ScenarioOptions::default()
    };
    let step = options.period;
    Ok((plant, options, path.display().to_string(), step))
}

/// Plant options: `--contact K,D` (else `default` or the library's contact law).
fn plant_config(a: &SimulateArgs, default: Option<[f64; 2]>) -> Result<PlantConfig, SetupError> {
    let mut config = PlantConfig::default();
    let kd = match &a.contact {
        Some(text) => {
            let v = numbers(text, 2, "--contact")?;
            if v[0] <= 0.0 || v[1] < 0.0 {
                return Err(
                    format!("--contact: need stiffness > 0 and damping >= 0, got {text}").into(),
                );
            }
            Some([v[0], v[1]])
        }
        None => default,
    };
    if let Some([k, d]) = kd {
        let c = &mut config.contact;
        (c.stiffness, c.damping) = (k, d);
        (c.tangential_stiffness, c.tangential_damping) = (k, d);
    }
    Ok(config)
}

/// Integrator settings and the step rule from `--step` / `--tolerances`.
fn integrator_settings(
    a: &SimulateArgs,
    method: Method,
    default_step: f64,
) -> Result<(Settings, StepRule), SetupError> {
    if method.is_fixed_step() {
        if a.tolerances.is_some() {
            return Err(
                format!("--tolerances: only dopri5 is adaptive, {method} uses --step").into(),
            );
        }
        let h = match &a.step {
            Some(text) => positive("--step", text)?,
            None => default_step,
        };
        Ok((Settings::fixed(h), StepRule::Fixed(h)))
    } else {
        if a.step.is_some() {
            return Err("--step: dopri5 chooses its own steps, use --tolerances RTOL,ATOL".into());
        }
        let d = Settings::default();
        let (rtol, atol) = match &a.tolerances {
            Some(text) => {
                let t = numbers(text, 2, "--tolerances")?;
                (t[0], t[1])
            }
            None => (d.rtol, d.atol),
        };
        let s = Settings::tolerances(rtol, atol);
        s.validate().map_err(|e| format!("--tolerances: {e}"))?;
        Ok((s, StepRule::Adaptive(rtol, atol)))
    }
}

/// A finite number > 0.
fn positive(option: &str, text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 => Ok(x),
        Ok(x) => Err(format!("{option}: must be finite and > 0, got {x}")),
        Err(e) => Err(format!("{option}: \"{text}\" is not a number ({e})")),
    }
}

/// Exactly `n` comma-separated finite numbers.
fn numbers(text: &str, n: usize, option: &str) -> Result<Vec<f64>, String> {
    let parsed: Result<Vec<f64>, _> = text.split(',').map(|s| s.trim().parse::<f64>()).collect();
    match parsed {
        Ok(v) if v.len() == n && v.iter().all(|x| x.is_finite()) => Ok(v),
        _ => Err(format!(
            "{option}: expected {n} comma-separated finite numbers, got \"{text}\""
        )),
    }
}

/// Exactly `n` comma-separated non-empty names.
fn names(text: &str, n: usize, option: &str, shape: &str) -> Result<Vec<String>, String> {
    let v: Vec<String> = text.split(',').map(|s| s.trim().to_string()).collect();
    if v.len() != n || v.iter().any(String::is_empty) {
        return Err(format!("{option}: expected {shape}, got \"{text}\""));
    }
    Ok(v)
}

/// `JOINT=ANGLE` pairs separated by commas.
fn parse_pose(text: &str) -> Result<Vec<(String, f64)>, String> {
    text.split(',')
        .map(|item| {
            let bad =
                || format!("--pose: expected JOINT=ANGLE with a finite angle, got \"{item}\"");
            let (joint, angle) = item.split_once('=').ok_or_else(bad)?;
            let angle: f64 = angle.trim().parse().map_err(|_| bad())?;
            if joint.trim().is_empty() || !angle.is_finite() {
                return Err(bad());
            }
            Ok((joint.trim().to_string(), angle))
        })
        .collect()
}
