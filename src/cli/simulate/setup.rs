//! From command-line options to a ready-to-run job: the plant (Lola or URDF), the scenario and
//! the integrator. Every input error names the option it comes from.

use super::model::{lola_source, urdf_only, urdf_source};
use super::parse::parse_pose;
use super::recording::Recording;
use super::SimulateArgs;
use crate::cli::range::simulate::{BANDWIDTH, DURATION, EVERY, STEP, SWAY, TOLERANCES};
use biped_sim::controller::{Hook, Hooked, JointPd};
use biped_sim::ode::{Method, Settings};
use biped_sim::plant::Plant;
use biped_sim::scenario::{build, Scenario, ScenarioKind};
use biped_sim::simulation::{Frame, Signals, Simulation, Summary};
use biped_sim::SimError;

/// Error of this module: one line naming the option.
type SetupError = Box<dyn std::error::Error>;

/// Largest number of recorded rows reserved up front (longer runs grow the recorder).
const MAX_RESERVED_ROWS: usize = 1 << 16;

/// What the run was, for the report and `summary.json`.
#[derive(Debug, Clone)]
pub struct Info {
    /// Model label, e.g. `Lola Type2` or the URDF path.
    pub model: String,
    /// Scenario name.
    pub scenario: &'static str,
    /// Integration method.
    pub method: Method,
    /// How the integrator steps.
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
    every: u64,
}

impl Job {
    /// Parses and validates every option, builds the plant and the scenario.
    pub fn from_args(a: &SimulateArgs) -> Result<Self, SetupError> {
        let kind: ScenarioKind = a.scenario.parse().map_err(|e| format!("--scenario: {e}"))?;
        let method: Method = a
            .integrator
            .parse()
            .map_err(|e| format!("--integrator: {e}"))?;
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
        merge_pose(&mut options.pose, pose);
        let period = options.period;
        if let Some(text) = &a.duration {
            let at_least = DURATION.at_least(period, "at least one control period");
            options.duration = Some(at_least.parse(text)?);
        }
        if let Some(text) = &a.bandwidth {
            options.bandwidth = BANDWIDTH.parse(text)?;
        }
        options.stance_damping = !a.no_stance_damping;
        if let Some(text) = &a.sway {
            [options.sway_amplitude, options.sway_period] = sway_motion(text, kind)?;
        }
        let (settings, step) = integrator_settings(a, method, default_step, period)?;
        let every = EVERY.parse_whole(&a.every)?;
        let scenario = build(kind, &mut plant, &options).map_err(|e| scenario_error(kind, e))?;
        let info = Info {
            model: label,
            scenario: name(kind),
            method,
            step,
        };
        let job = Self {
            plant,
            scenario,
            kind,
            settings,
            info,
            every,
        };
        let columns = Signals::new(&job.plant, true).names().len() as u64;
        job.recording().check_size(columns, job.scenario.duration)?;
        Ok(job)
    }

    /// Scenario name (`stand`, `drop`, `sway`).
    pub fn scenario_name(&self) -> &'static str {
        name(self.kind)
    }

    /// Description of the run.
    pub fn info(&self) -> Info {
        self.info.clone()
    }

    /// The recorded control periods.
    pub fn recording(&self) -> Recording {
        Recording::new(self.scenario.duration, self.scenario.period(), self.every)
    }

    /// Rows the recorder should reserve.
    pub fn rows(&self) -> usize {
        let rows = usize::try_from(self.recording().rows()).unwrap_or(usize::MAX);
        rows.min(MAX_RESERVED_ROWS)
    }

    /// Runs the scenario, its joint PD followed by `hook` if given, with `observer` called
    /// once per control period and at the end.
    pub fn run(
        self,
        hook: Option<Hook>,
        observer: &mut dyn FnMut(&Frame) -> Result<(), SimError>,
    ) -> Result<(Summary, Simulation<Hooked<JointPd>>), SimError> {
        let method = self.info.method;
        let wrap = |pd| Ok(Hooked::new(pd, hook));
        self.scenario
            .run_wrapped(self.plant, wrap, method, self.settings, observer)
    }
}

/// Sets the angles of `given` in `pose`, replacing entries of the same joint.
fn merge_pose(pose: &mut Vec<(String, f64)>, given: Vec<(String, f64)>) {
    for (name, angle) in given {
        match pose.iter_mut().find(|(n, _)| *n == name) {
            Some(entry) => entry.1 = angle,
            None => pose.push((name, angle)),
        }
    }
}

/// `--sway AMPLITUDE,PERIOD`, only with `--scenario sway`.
fn sway_motion(text: &str, kind: ScenarioKind) -> Result<[f64; 2], String> {
    if kind != ScenarioKind::Sway {
        return Err("--sway: only applies with --scenario sway".into());
    }
    SWAY.parse(text)
}

/// The scenario builder's error `e`, attributed to the option it comes from: the start pose,
/// the sway joints or the sway motion, else the scenario.
fn scenario_error(kind: ScenarioKind, e: SimError) -> String {
    let option = match &e {
        SimError::Unknown { kind: "joint", .. } => Some("--pose"),
        SimError::Unknown {
            kind: "sway joint", ..
        } => Some("--sway-joints"),
        SimError::InvalidParameter { what, .. } if what.starts_with("pose ") => Some("--pose"),
        SimError::InvalidParameter { what, .. } if what.starts_with("sway") => Some("--sway"),
        _ => None,
    };
    match option {
        Some(option) => format!("{option}: {e}"),
        None => format!("scenario {}: {e}", name(kind)),
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

/// Integrator settings and the step rule from `--step` / `--tolerances`. A fixed step is at
/// most the control `period`, and the simulation takes a whole number of equal steps per
/// period: the step rule is that step, `period / ceil(period / h)`.
fn integrator_settings(
    a: &SimulateArgs,
    method: Method,
    default_step: f64,
    period: f64,
) -> Result<(Settings, StepRule), SetupError> {
    if method.is_fixed_step() {
        if a.tolerances.is_some() {
            return Err(
                format!("--tolerances: only dopri5 is adaptive, {method} uses --step").into(),
            );
        }
        let h = match &a.step {
            Some(text) => STEP
                .at_most(period, "at most the control period")
                .parse(text)?,
            None => default_step,
        };
        let taken = period / (period / h).ceil();
        Ok((Settings::fixed(h), StepRule::Fixed(taken)))
    } else {
        if a.step.is_some() {
            return Err("--step: dopri5 chooses its own steps, use --tolerances RTOL,ATOL".into());
        }
        let d = Settings::default();
        let [rtol, atol] = match &a.tolerances {
            Some(text) => TOLERANCES.parse(text)?,
            None => [d.rtol, d.atol],
        };
        let s = Settings::tolerances(rtol, atol);
        s.validate().map_err(|e| format!("--tolerances: {e}"))?;
        Ok((s, StepRule::Adaptive(rtol, atol)))
    }
}
