//! `biped ssv model FILE --pose NAME`: segment-pair distances of a collision model (6.6-6.8).

use crate::cli::out::outln;
use crate::cli::CliResult;
use biped_ssv::format;
use biped_ssv::{CollisionModel, PairDistance, PairQuery};
use clap::Args;
use serde::Serialize;
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `biped ssv model`.
#[derive(Args)]
pub struct ModelArgs {
    /// Collision-model file (TOML, format in `biped_ssv::format`).
    file: PathBuf,
    /// Posture from the file's `[pose.<name>]` sections (default: the first one).
    #[arg(long)]
    pose: Option<String>,
    /// Only compute pairs closer than the activation distance (what avoidance needs).
    #[arg(long)]
    within_activation: bool,
    /// Print JSON instead of a table.
    #[arg(long)]
    json: bool,
}

/// One pair's line of the report.
#[derive(Serialize)]
struct PairReport<'a> {
    a: &'a str,
    b: &'a str,
    /// Signed distance in m, or `None` when beyond d_a.
    distance: Option<f64>,
    point_a: Option<[f64; 3]>,
    point_b: Option<[f64; 3]>,
}

fn reports(model: &CollisionModel) -> Vec<PairReport<'_>> {
    let segments = model.segments();
    model
        .distances()
        .map(|(pair, result)| {
            let closest = match result {
                PairDistance::Computed(c) => Some(c.result),
                PairDistance::Beyond => None,
            };
            PairReport {
                a: segments[pair.a].name(),
                b: segments[pair.b].name(),
                distance: closest.map(|r| r.distance),
                point_a: closest.map(|r| r.point_a.coords.into()),
                point_b: closest.map(|r| r.point_b.coords.into()),
            }
        })
        .collect()
}

/// Load, pose, evaluate and print.
pub fn run(args: ModelArgs) -> CliResult {
    let mut loaded = format::load(&args.file)?;
    let file = args.file.display();
    let (name, poses) = match &args.pose {
        Some(name) => loaded
            .poses
            .get_key_value(name)
            .ok_or_else(|| format!("{file}: no [pose.{name}] section"))?,
        None => loaded
            .poses
            .iter()
            .next()
            .ok_or_else(|| format!("{file}: no [pose.<name>] section to evaluate"))?,
    };
    let model = &mut loaded.model;
    if args.within_activation {
        model.set_pair_query(PairQuery::WithinActivation);
    }
    model.update(poses)?;
    let rows = reports(model);
    if args.json {
        let json = serde_json::json!({ "pose": name, "activation_distance":
            model.activation_distance(), "pairs": rows });
        outln!("{json}")?;
        return Ok(ExitCode::SUCCESS);
    }
    outln!(
        "{file}, pose {name}, d_a = {} m",
        model.activation_distance()
    )?;
    for row in &rows {
        let d = row
            .distance
            .map_or_else(|| "beyond d_a".to_string(), |d| format!("{d:.6} m"));
        outln!("{:>20} - {:<20} {d}", row.a, row.b)?;
    }
    if let Some((pair, closest)) = model.min_distance() {
        let p = model.pairs()[pair];
        let names = (model.segments()[p.a].name(), model.segments()[p.b].name());
        outln!(
            "closest pair: {} - {} at {:.6} m",
            names.0,
            names.1,
            closest.result.distance
        )?;
    }
    Ok(ExitCode::SUCCESS)
}
