//! Files written by `biped simulate`: `signals.csv` (every recorded signal), its recording for
//! replay, SVG plots of the quantities one checks first and `summary.json`.

use super::setup::Info;
use super::Outcome;
use crate::cli::outdir::{self, OutputDir, Status};
use biped_dynamics::Model;
use biped_sim::glob::glob_match;
use biped_sim::plant::Plant;
use biped_sim::record::replay::{replay, write_csv_gz, FRAME_RATE};
use biped_sim::record::{RecordError, Recorder};
use biped_sim::simulation::Frame;
use biped_sim::SimError;
use serde_json::json;
use std::path::Path;

/// Result of this module.
type OutResult<T> = Result<T, Box<dyn std::error::Error>>;

/// At most this many signals per plot (the largest by excursion).
const MAX_LINES: usize = 8;

/// The recording for replay (docs/recording.md) of `signals.csv`.
pub const RECORDING: &str = "recording.csv.gz";

/// Writes [`RECORDING`] of the signals `rec` of a plant of `model` into `dir`.
fn write_recording(rec: &Recorder, model: &Model, dir: &Path) -> Result<(), RecordError> {
    let recording = replay(model, rec, FRAME_RATE)?;
    write_csv_gz(&recording, &dir.join(RECORDING))
}

/// Column of the total vertical contact force, recorded besides the library's signals.
pub const TOTAL_FZ: &str = "contact.fz";

/// Registers the total-force column of [`record_total`] (before the run, see `Recorder::prefault`).
pub fn register_total(rec: &mut Recorder) -> Result<(), SimError> {
    rec.register(TOTAL_FZ)
        .map(|_| ())
        .map_err(|e| SimError::Output(e.to_string()))
}

/// Records the total vertical contact force of `f` in the current row of `rec`.
pub fn record_total(f: &Frame, rec: &mut Recorder) -> Result<(), SimError> {
    let fz: f64 = f
        .plant
        .last_outputs()
        .contact
        .feet
        .iter()
        .map(|w| w.force.z)
        .sum();
    rec.set(TOTAL_FZ, fz)
        .map_err(|e| SimError::Output(e.to_string()))
}

/// Ends a run that stopped at `t` with `err`: the signals recorded until then and a
/// `summary.json` marked failed or interrupted replace the output directory; returns the
/// error line.
pub fn abandon(
    out: OutputDir,
    rec: &Recorder,
    model: &Model,
    info: &Info,
    t: f64,
    err: &SimError,
) -> String {
    let status = match err {
        SimError::Stopped(_) => Status::Interrupted,
        _ => Status::Failed,
    };
    let mut files = Vec::new();
    let mut kept = String::new();
    if !rec.is_empty() && rec.write_csv(&out.path().join("signals.csv")).is_ok() {
        files.push("signals.csv");
        kept = format!(
            "; signals until then in {}",
            out.target().join("signals.csv").display()
        );
        if write_recording(rec, model, out.path()).is_ok() {
            files.push(RECORDING);
        }
    }
    let base = json!({
        "model": info.model,
        "scenario": info.scenario,
        "stopped_at": t,
        "files": files,
    });
    let reason = abandoned_line(t, err);
    let note = out.abandon(status, &reason, Some(base));
    format!("{reason}{kept}{note}")
}

/// Why a run stopped at `t` with `err`, in one line.
pub fn abandoned_line(t: f64, err: &SimError) -> String {
    match err {
        SimError::Stopped(why) => format!("simulation interrupted after t = {t:.4} s: {why}"),
        _ => format!("simulation failed after t = {t:.4} s: {err}"),
    }
}

/// One line of a plot: legend label and recorder column.
pub struct Line {
    label: String,
    column: String,
}

impl Line {
    fn new(label: impl Into<String>, column: impl Into<String>) -> Self {
        Self {
            label: label.into(),
            column: column.into(),
        }
    }
}

/// One SVG: file name, title (without the run description), lines and y-axis label.
pub struct Plot {
    file: String,
    title: String,
    lines: Vec<Line>,
    y_label: &'static str,
}

/// Lines `<foot>.<c>` for every foot and component.
fn per_foot(plant: &Plant, components: &[&str]) -> Vec<Line> {
    let mut lines = Vec::new();
    for foot in plant.contact().specs() {
        for c in components {
            let name = format!("{}.{c}", foot.name);
            lines.push(Line::new(name.clone(), name));
        }
    }
    lines
}

/// The plots of a run: base and CoM height, contact forces, foot shear and torques, angular
/// momentum about the CoM, joint angles and motor currents (the largest [`MAX_LINES`]).
fn plots(rec: &Recorder, plant: &Plant) -> Vec<Plot> {
    let plot = |file: &str, title: &str, lines, y_label| Plot {
        file: file.to_string(),
        title: title.to_string(),
        lines,
        y_label,
    };
    let mut out = Vec::new();
    if let Some((qi, _)) = plant.floating_base() {
        let base = vec![Line::new("base z", q_column(plant, qi + 2))];
        out.push(plot("base_height.svg", "Base height", base, "height [m]"));
    }
    let com = vec![Line::new("CoM z", "com.z")];
    out.push(plot(
        "com_height.svg",
        "Centre-of-mass height",
        com,
        "height [m]",
    ));
    let mut fz = per_foot(plant, &["fz"]);
    fz.push(Line::new("total", TOTAL_FZ));
    out.push(plot(
        "contact_forces.svg",
        "Vertical contact forces",
        fz,
        "force [N]",
    ));
    let shear = per_foot(plant, &["fx", "fy"]);
    out.push(plot(
        "foot_shear.svg",
        "Tangential foot forces",
        shear,
        "force [N]",
    ));
    let torques = per_foot(plant, &["tx", "ty", "tz"]);
    let title = "Foot torques about the sole point";
    out.push(plot("foot_torques.svg", title, torques, "torque [N m]"));
    let l_g = ["x", "y", "z"].map(|c| Line::new(format!("L_G.{c}"), format!("L_G.{c}")));
    let title = "Angular momentum about the CoM";
    out.push(plot(
        "angular_momentum.svg",
        title,
        l_g.into(),
        "L_G [N m s]",
    ));
    let acts = plant.actuators();
    let q_names = plant.model().q_names();
    let angles = acts
        .iter()
        .map(|a| Line::new(&a.name, format!("q[{}]", q_names[a.joint_q])));
    let title = selected("Joint angles", acts.len());
    out.push(plot(
        "joint_angles.svg",
        &title,
        largest(rec, angles),
        "angle [rad]",
    ));
    let currents = largest(
        rec,
        acts.iter()
            .map(|a| Line::new(&a.name, format!("i[{}]", a.name))),
    );
    if !currents.is_empty() {
        let title = selected("Motor currents", acts.len());
        out.push(plot("motor_currents.svg", &title, currents, "current [A]"));
    }
    out
}

/// The plots of `--plot` (each a comma-separated list of column names or `*` patterns of
/// `rec`, whose columns are registered), as `plot_<k>.svg`; an entry that matches no column is
/// an error.
pub fn chosen_plots(rec: &Recorder, options: &[String]) -> OutResult<Vec<Plot>> {
    let mut out = Vec::new();
    for (k, text) in options.iter().enumerate() {
        let mut lines: Vec<Line> = Vec::new();
        for pattern in text.split(',').map(str::trim) {
            let names = rec.column_names().iter();
            let found: Vec<&String> = names.filter(|c| glob_match(pattern, c)).collect();
            if found.is_empty() {
                let some: Vec<&str> = rec
                    .column_names()
                    .iter()
                    .take(4)
                    .map(|c| c.as_str())
                    .collect();
                return Err(format!(
                    "--plot: `{pattern}` matches no recorded signal (columns of signals.csv: {}, ...)",
                    some.join(", ")
                )
                .into());
            }
            for c in found {
                if !lines.iter().any(|l| &l.column == c) {
                    lines.push(Line::new(c.clone(), c.clone()));
                }
            }
        }
        out.push(Plot {
            file: format!("plot_{}.svg", k + 1),
            title: format!("Signals {text}"),
            lines,
            y_label: "value",
        });
    }
    Ok(out)
}

/// Writes the CSV, the plots (the standard ones, then the `chosen` ones) and `summary.json`
/// into `dir`; returns the file names.
pub fn write_all(done: &Outcome, chosen: &[Plot], dir: &Path) -> OutResult<Vec<String>> {
    let (rec, plant, info) = (&done.rec, done.sim.plant(), &done.info);
    let mut files = vec!["signals.csv".to_string(), RECORDING.to_string()];
    rec.write_csv(&dir.join(&files[0]))?;
    write_recording(rec, plant.model(), dir)?;
    for p in plots(rec, plant).iter().chain(chosen) {
        let title = format!(
            "{} ({} {}, {})",
            p.title, info.model, info.scenario, info.method
        );
        plot(rec, &dir.join(&p.file), &title, &p.lines, p.y_label)?;
        files.push(p.file.clone());
    }
    files.push("summary.json".to_string());
    let mut json = done.summary_json(&files).map_err(|e| e.to_string())?;
    if let Some(map) = json.as_object_mut() {
        outdir::stamp(map, Status::Completed);
    }
    outdir::write_json(&dir.join("summary.json"), &json)?;
    Ok(files)
}

/// The `signals.csv` column of position coordinate `i` (`q[<coordinate name>]`).
pub fn q_column(plant: &Plant, i: usize) -> String {
    let names = plant.model().q_names();
    format!("q[{}]", names.get(i).map_or("?", String::as_str))
}

/// Plot title noting a selection of the largest signals.
fn selected(what: &str, n: usize) -> String {
    match n > MAX_LINES {
        true => format!("{what}, {MAX_LINES} largest of {n}"),
        false => what.to_string(),
    }
}

/// The [`MAX_LINES`] lines with the largest excursion from their first value (lines whose
/// column is missing or constant are dropped).
fn largest(rec: &Recorder, lines: impl Iterator<Item = Line>) -> Vec<Line> {
    let excursion = |col: &[f64]| {
        let first = col.first().copied().unwrap_or(0.0);
        col.iter().map(|x| (x - first).abs()).fold(0.0, f64::max)
    };
    let mut scored: Vec<(f64, Line)> = lines
        .filter_map(|l| rec.column(&l.column).ok().map(|c| (excursion(&c), l)))
        .filter(|(e, _)| *e > 0.0)
        .collect();
    scored.sort_by(|a, b| b.0.total_cmp(&a.0));
    scored.into_iter().take(MAX_LINES).map(|(_, l)| l).collect()
}

/// Plots `lines` of `rec` under their labels (copied into a small recorder of their own).
fn plot(rec: &Recorder, path: &Path, title: &str, lines: &[Line], y_label: &str) -> OutResult<()> {
    let cols = lines
        .iter()
        .map(|l| rec.column(&l.column))
        .collect::<Result<Vec<_>, _>>()?;
    let mut view = Recorder::with_capacity(rec.len());
    let ids = lines
        .iter()
        .map(|l| view.register(&l.label))
        .collect::<Result<Vec<_>, _>>()?;
    for (row, &t) in rec.time().iter().enumerate() {
        view.sample(t)?;
        for (id, col) in ids.iter().zip(&cols) {
            view.set_id(*id, &col[row..=row])?;
        }
    }
    let labels: Vec<&str> = lines.iter().map(|l| l.label.as_str()).collect();
    view.plot_svg(path, title, &labels, y_label)?;
    Ok(())
}
