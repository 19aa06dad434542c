//! From command-line options to a ready-to-run job: the plant (Lola or URDF), the scenario and
//! the integrator. Every input error names the option it comes from.

use super::model::{lola_source, urdf_only, urdf_source};
use super::parse::{count, numbers, parse_pose, positive};
use super::SimulateArgs;
use biped_sim::controller::JointPd;
use biped_sim::ode::{Method, Settings};
use biped_sim::plant::Plant;
use biped_sim::scenario::{build, Scenario, ScenarioKind};
use biped_sim::simulation::{Frame, Simulation, Summary};
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

/// Which control periods are recorded: every `every`-th and the last.
#[derive(Debug, Clone, Copy)]
pub struct Recording {
    period: f64,
    every: u64,
    cycles: u64,
}

impl Recording {
    /// Whether the frame at time `t` is recorded.
    pub fn at(&self, t: f64) -> bool {
        let k = (t / self.period).round() as u64;
        k.checked_rem(self.every) == Some(0) || k >= self.cycles
    }

    /// Number of recorded rows.
    pub fn rows(&self) -> u64 {
        self.cycles / self.every + 1 + u64::from(self.cycles.checked_rem(self.every) != Some(0))
    }
}

impl Job {
    /// Parses and validates every option, builds the plant and the scenario.
    pub fn from_args(a: &SimulateArgs) -> Result<Self, SetupError> {
        let kind: ScenarioKind = a.scenario.parse().map_err(|e| format!("--scenario: {e}"))?;
        let method: Method = a
            .integrator
            .parse()
            .map_err(|e| format!("--integrator: {e}"))?;
        let duration = match &a.duration {
            Some(text) => Some(positive("--duration", text)?),
            None => None,
        };
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
        if let Some(d) = duration.filter(|d| *d < 0.5 * options.period) {
            let p = options.period;
            let why = format!("--duration: {d} s is shorter than one control period ({p} s)");
            return Err(why.into());
        }
        options.duration = duration;
        if let Some(text) = &a.bandwidth {
            options.bandwidth = positive("--bandwidth", text)?;
        }
        options.stance_damping = !a.no_stance_damping;
        if let Some(text) = &a.sway {
            [options.sway_amplitude, options.sway_period] = sway_motion(text, kind)?;
        }
        let (settings, step) = integrator_settings(a, method, default_step)?;
        let every = count("--every", &a.every)?;
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
            every,
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

    /// The recorded control periods.
    pub fn recording(&self) -> Recording {
        let cycles = (self.scenario.duration / self.scenario.period()).round() as u64;
        Recording {
            period: self.scenario.period(),
            every: self.every,
            cycles,
        }
    }

    /// Rows the recorder should reserve.
    pub fn rows(&self) -> usize {
        let rows = usize::try_from(self.recording().rows()).unwrap_or(usize::MAX);
        rows.min(MAX_RESERVED_ROWS)
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

/// Sets the angles of `given` in `pose`, replacing entries of the same joint.
fn merge_pose(pose: &mut Vec<(String, f64)>, given: Vec<(String, f64)>) {
    for (name, angle) in given {
        match pose.iter_mut().find(|(n, _)| *n == name) {
            Some(entry) => entry.1 = angle,
            None => pose.push((name, angle)),
        }
    }
}

/// `--sway AMPLITUDE,PERIOD`: both finite and > 0, and only with `--scenario sway`.
fn sway_motion(text: &str, kind: ScenarioKind) -> Result<[f64; 2], String> {
    if kind != ScenarioKind::Sway {
        return Err("--sway: only applies with --scenario sway".into());
    }
    match numbers(text, 2, "--sway")?[..] {
        [a, t] if a > 0.0 && t > 0.0 => Ok([a, t]),
        _ => Err(format!(
            "--sway: need amplitude > 0 rad and period > 0 s, got \"{text}\""
        )),
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

#[cfg(test)]
mod tests {
    use super::Recording;

    /// `rows()` counts what `at()` selects, over the control times of a run.
    #[test]
    fn recorded_rows_match_the_selection() {
        for (cycles, every) in [(200, 1), (200, 10), (205, 10), (7, 3), (3, 5), (1, 1)] {
            let r = Recording {
                period: 1e-3,
                every,
                cycles,
            };
            let selected = (0..=cycles).filter(|k| r.at(*k as f64 * 1e-3)).count() as u64;
            assert_eq!(selected, r.rows(), "{cycles} cycles, every {every}");
            assert!(r.at(0.0) && r.at(cycles as f64 * 1e-3), "first and last");
        }
    }
}
