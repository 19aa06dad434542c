//! `biped model`, `biped dynamics`, `biped bench dynamics`: the dynamics library on the command line.

mod bench;
mod plot;
mod source;
mod stream;

use super::CliResult;
use clap::{ArgGroup, Args, ValueEnum};
use source::SourceArgs;
use std::io::Write;
use std::process::ExitCode;

/// Arguments of `biped model`.
#[derive(Args)]
#[command(group(ArgGroup::new("source").required(true).args(["urdf", "dill"])))]
pub struct ModelArgs {
    #[command(flatten)]
    source: SourceArgs,
    /// Print one JSON object `{"nq", "nv", "joints", "bodies", "neutral"}`.
    #[arg(long)]
    json: bool,
}

/// Forward-dynamics algorithm selectable on the command line.
#[derive(Clone, Copy, ValueEnum)]
pub enum AlgorithmArg {
    /// O(n) three-pass algorithm (Alg. 2.1-2.4).
    On,
    /// CRBA mass matrix, RNEA bias, dense Cholesky.
    Crba,
    /// CRBA with the sparse LTL factorisation of Featherstone and Orin.
    Sparse,
}

impl From<AlgorithmArg> for biped_dynamics::Algorithm {
    fn from(a: AlgorithmArg) -> Self {
        match a {
            AlgorithmArg::On => Self::On,
            AlgorithmArg::Crba => Self::Crba,
            AlgorithmArg::Sparse => Self::Sparse,
        }
    }
}

/// Arguments of `biped dynamics`.
#[derive(Args)]
#[command(group(ArgGroup::new("source").required(true).args(["urdf", "dill"])))]
#[command(group(ArgGroup::new("mode").args(["mass_matrix", "inverse"])))]
pub struct DynamicsArgs {
    #[command(flatten)]
    source: SourceArgs,
    /// Forward-dynamics algorithm (default `on`; not with --mass-matrix or --inverse).
    #[arg(long, value_enum)]
    algorithm: Option<AlgorithmArg>,
    /// Read `{"q"}` lines and write the mass matrix `{"M": [[..], ..]}`.
    #[arg(long)]
    mass_matrix: bool,
    /// Read `{"q", "v", "a"}` lines and write the joint forces `{"tau"}` (RNEA).
    #[arg(long)]
    inverse: bool,
}

/// Arguments of `biped bench dynamics`.
#[derive(Args)]
#[command(group(ArgGroup::new("source").required(true).args(["urdf", "dill", "dill_range"])))]
pub struct BenchArgs {
    #[command(flatten)]
    source: SourceArgs,
    /// Dill levels `A..B` (inclusive); also writes a run-time plot like Fig. 2.19 under `out/`.
    #[arg(long, value_name = "A..B", value_parser = parse_range, allow_hyphen_values = true)]
    dill_range: Option<(u32, u32)>,
    /// Print JSON (`{"on": ns, "crba": ns, "sparse": ns, ..}`; an array with `"n"` for a range).
    #[arg(long)]
    json: bool,
}

/// Parses `A..B` (inclusive, A <= B <= the largest Dill level).
fn parse_range(text: &str) -> Result<(u32, u32), String> {
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| format!("expected A..B, got \"{text}\""))?;
    let parse = |s: &str| {
        s.trim()
            .parse::<u32>()
            .map_err(|e| format!("\"{s}\" in \"{text}\": {e}"))
    };
    let (a, b) = (parse(a)?, parse(b)?);
    if a > b {
        return Err(format!("empty range {a}..{b}"));
    }
    let max = biped_dynamics::dill::MAX_DILL_LEVEL;
    if b > max {
        return Err(format!(
            "level {b} is too large (valid levels are 0..{max})"
        ));
    }
    Ok((a, b))
}

/// Run `biped model`.
pub fn run_model(args: ModelArgs) -> CliResult {
    let loaded = args.source.to_source()?.load()?;
    let model = &loaded.model;
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    if args.json {
        serde_json::to_writer(&mut out, &source::describe(model))?;
        writeln!(out)?;
    } else {
        writeln!(
            out,
            "{}: nq = {}, nv = {}, {} bodies",
            loaded.label,
            model.nq(),
            model.nv(),
            model.nbodies()
        )?;
        for j in model.joints() {
            writeln!(
                out,
                "  {:<32} q[{}..{}] v[{}..{}]",
                j.name,
                j.q_index,
                j.q_index + j.nq,
                j.v_index,
                j.v_index + j.nv
            )?;
        }
    }
    out.flush()?;
    Ok(ExitCode::SUCCESS)
}

/// Run `biped dynamics`.
pub fn run_dynamics(args: DynamicsArgs) -> CliResult {
    let loaded = args.source.to_source()?.load()?;
    if args.algorithm.is_some() && (args.mass_matrix || args.inverse) {
        let other = if args.mass_matrix {
            "--mass-matrix"
        } else {
            "--inverse"
        };
        return Err(format!("--algorithm: only applies to forward dynamics, not {other}").into());
    }
    let mode = if args.mass_matrix {
        stream::Mode::MassMatrix
    } else if args.inverse {
        stream::Mode::Inverse
    } else {
        stream::Mode::Forward(args.algorithm.unwrap_or(AlgorithmArg::On).into())
    };
    let stdin = std::io::stdin().lock();
    let stdout = std::io::BufWriter::new(std::io::stdout().lock());
    let all_good = stream::run(&loaded.model, mode, stdin, stdout)?;
    Ok(if all_good {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}

/// Run `biped bench dynamics`.
pub fn run_bench(args: BenchArgs) -> CliResult {
    match args.dill_range {
        Some((a, b)) => {
            args.source.check_urdf_only()?;
            bench::run_range(a, b, args.json)
        }
        None => bench::run_one(&args.source.to_source()?, args.json),
    }
}
