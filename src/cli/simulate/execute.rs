//! One `biped simulate` run as a library call, shared by the command line and the Python
//! package: options to a prepared job with its recorder, the run (with an optional controller
//! hook and a stop check), and the summary of `summary.json`.

use super::output;
use super::report::{final_base_height, summary_json};
use super::setup::{Info, Job};
use super::SimulateArgs;
use biped_dynamics::Model;
use biped_sim::controller::{Hook, Hooked, JointPd};
use biped_sim::record::Recorder;
use biped_sim::simulation::{Frame, Signals, Simulation, Summary};
use biped_sim::SimError;
use serde_json::{json, Value};

/// Error of preparing a run: one line naming the option.
pub type SetupError = Box<dyn std::error::Error + Send + Sync>;

/// Parses the options of `biped simulate` given as command-line words (without the program
/// and sub-command names), e.g. `["--scenario", "drop", "--duration", "1"]`.
pub fn parse_args<I, S>(words: I) -> Result<SimulateArgs, String>
where
    I: IntoIterator<Item = S>,
    S: Into<String>,
{
    crate::cli::words::parse("simulate", words)
}

/// A validated run: plant, scenario and a recorder with every column registered.
pub struct Prepared {
    /// The job.
    pub job: Job,
    /// The recorder the run fills (columns registered, no rows yet).
    pub rec: Recorder,
    signals: Signals,
}

/// A finished run.
pub struct Outcome {
    /// The library summary.
    pub summary: Summary,
    /// The simulation at its final state (plant, controller, sensors).
    pub sim: Simulation<Hooked<JointPd>>,
    /// The recorded signals.
    pub rec: Recorder,
    /// What the run was.
    pub info: Info,
}

/// A run that ended early: what was recorded until `t` and why it stopped.
pub struct Abandoned {
    /// The signals recorded until the error.
    pub rec: Recorder,
    /// What the run was.
    pub info: Info,
    /// Time of the last control period reached \[s].
    pub t: f64,
    /// Why it stopped.
    pub error: SimError,
    /// The simulated plant's model (of the recorded `q[NAME]` columns).
    pub model: Model,
}

impl Prepared {
    /// Validates `args` and builds the job (every error names its option).
    pub fn new(args: &SimulateArgs) -> Result<Self, SetupError> {
        let job = Job::from_args(args).map_err(|e| e.to_string())?;
        let mut signals = Signals::new(&job.plant, true);
        let mut rec = Recorder::with_capacity(job.rows());
        signals.register(&mut rec)?;
        output::register_total(&mut rec)?;
        Ok(Self { job, rec, signals })
    }

    /// Runs the scenario with `hook` after its joint PD each cycle; `stop` is asked once per
    /// control period with the time and the duration, and may end the run (its error says
    /// why).
    pub fn run(
        self,
        hook: Option<Hook>,
        stop: &mut dyn FnMut(f64, f64) -> Result<(), SimError>,
    ) -> Result<Outcome, Box<Abandoned>> {
        let Self {
            job,
            mut rec,
            mut signals,
        } = self;
        let due = job.recording();
        let info = job.info();
        let duration = job.scenario.duration;
        let model = job.plant.model().clone();
        let mut last_t = 0.0;
        let mut observe = |f: &Frame| -> Result<(), SimError> {
            stop(f.t, duration)?;
            last_t = f.t;
            if due.at(f.t) {
                signals.record(f, &mut rec)?;
                output::record_total(f, &mut rec)?;
            }
            Ok(())
        };
        match job.run(hook, &mut observe) {
            Ok((summary, sim)) => Ok(Outcome {
                summary,
                sim,
                rec,
                info,
            }),
            Err(error) => Err(Box::new(Abandoned {
                rec,
                info,
                t: last_t,
                error,
                model,
            })),
        }
    }
}

impl Outcome {
    /// `summary.json` of this run listing `files`, with the final state (`t`, `q`, `v`).
    pub fn summary_json(&self, files: &[String]) -> Result<Value, SetupError> {
        let plant = self.sim.plant();
        let base = final_base_height(&self.rec, plant);
        let mut v = summary_json(&self.summary, base, plant, &self.info, files)
            .map_err(|e| e.to_string())?;
        let layout = plant.layout();
        let z = self.sim.state();
        let fin = json!({
            "t": self.sim.time(),
            "q": &z[layout.q()],
            "v": &z[layout.v()],
        });
        if let Some(map) = v.as_object_mut() {
            map.insert("final".into(), fin);
        }
        Ok(v)
    }
}
