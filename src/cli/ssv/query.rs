//! `biped ssv query`: JSON Lines in, one JSON line out per query.

use crate::cli::{json_lines, CliResult};
use biped_ssv::{distance, Lss, Pss, Ssv, SsvError, Tss};
use nalgebra::Point3;
use serde::{Deserialize, Serialize};
use std::io::BufWriter;
use std::process::ExitCode;

/// One SSV as written in a query: exactly one of `point`, `line`, `triangle`, plus `radius`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ShapeJson {
    point: Option<[f64; 3]>,
    line: Option<[[f64; 3]; 2]>,
    triangle: Option<[[f64; 3]; 3]>,
    radius: f64,
}

/// One query line `{"a": S, "b": S}`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct QueryJson {
    a: ShapeJson,
    b: ShapeJson,
}

/// One answer line.
#[derive(Serialize)]
struct AnswerJson {
    distance: f64,
    point_a: [f64; 3],
    point_b: [f64; 3],
}

fn pt(p: [f64; 3]) -> Point3<f64> {
    Point3::from(p)
}

impl ShapeJson {
    fn to_ssv(&self, name: &str) -> Result<Ssv, String> {
        let wrap = |e: SsvError| format!("\"{name}\": {e}");
        match (self.point, self.line, self.triangle) {
            (Some(p), None, None) => Pss::new(pt(p), self.radius).map(Ssv::from).map_err(wrap),
            (None, Some([a, b]), None) => Lss::new(pt(a), pt(b), self.radius)
                .map(Ssv::from)
                .map_err(wrap),
            (None, None, Some([a, b, c])) => Tss::new(pt(a), pt(b), pt(c), self.radius)
                .map(Ssv::from)
                .map_err(wrap),
            _ => Err(format!(
                "\"{name}\": needs exactly one of \"point\", \"line\", \"triangle\""
            )),
        }
    }
}

/// Answer one query line, or say what is wrong with it.
fn answer(line: &str) -> Result<AnswerJson, String> {
    let q: QueryJson = serde_json::from_str(line).map_err(|e| e.to_string())?;
    let (a, b) = (q.a.to_ssv("a")?, q.b.to_ssv("b")?);
    let r = distance(&a, &b);
    Ok(AnswerJson {
        distance: r.distance,
        point_a: r.point_a.coords.into(),
        point_b: r.point_b.coords.into(),
    })
}

/// Run the query loop over stdin (see [`json_lines`]); exit 1 if any line was bad.
pub fn run() -> CliResult {
    let stdin = std::io::stdin().lock();
    let out = BufWriter::new(std::io::stdout().lock());
    Ok(match json_lines::serve(stdin, out, answer)? {
        true => ExitCode::SUCCESS,
        false => ExitCode::FAILURE,
    })
}
