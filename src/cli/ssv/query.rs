//! `biped ssv query`: JSON Lines in, one JSON line out per query.

use crate::cli::{json_lines, CliResult};
use std::io::BufWriter;
use std::process::ExitCode;

/// Run the query loop over stdin (see [`json_lines`]); exit 1 if any line was bad.
pub fn run() -> CliResult {
    let stdin = std::io::stdin().lock();
    let out = BufWriter::new(std::io::stdout().lock());
    Ok(
        match json_lines::serve(stdin, out, biped_ssv::query::answer)? {
            true => ExitCode::SUCCESS,
            false => ExitCode::FAILURE,
        },
    )
}
