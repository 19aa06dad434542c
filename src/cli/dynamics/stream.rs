//! JSON Lines driver of `biped dynamics`: one request per input line, one answer per output line.

use crate::cli::json_lines;
use biped_dynamics::{forward_dynamics, inverse_dynamics, mass_matrix, Algorithm, Data, Model};
use nalgebra::DVector;
use serde::Deserialize;
use serde_json::json;
use std::io::{BufRead, Write};

/// What each input line asks for.
#[derive(Clone, Copy)]
pub enum Mode {
    /// `{"q", "v", "tau"}` -> `{"qdd"}`.
    Forward(Algorithm),
    /// `{"q"}` -> `{"M"}`.
    MassMatrix,
    /// `{"q", "v", "a"}` -> `{"tau"}`.
    Inverse,
}

/// A request line; which fields are required depends on the [`Mode`].
#[derive(Deserialize)]
struct Request {
    q: Option<Vec<f64>>,
    v: Option<Vec<f64>>,
    tau: Option<Vec<f64>>,
    a: Option<Vec<f64>>,
}

/// Answers every non-blank line of `input` on `output`; returns false if any line was bad.
/// Bad lines are answered with `{"error": "line N: .."}` and processing goes on (see
/// [`json_lines`]).
pub fn run(
    model: &Model,
    mode: Mode,
    input: impl BufRead,
    output: impl Write,
) -> std::io::Result<bool> {
    let mut data = Data::new(model);
    json_lines::serve(input, output, |line| answer(model, &mut data, mode, line))
}

/// The answer to one request line, or what is wrong with it.
fn answer(
    model: &Model,
    data: &mut Data,
    mode: Mode,
    line: &str,
) -> Result<serde_json::Value, String> {
    let req: Request = serde_json::from_str(line).map_err(|e| format!("bad JSON: {e}"))?;
    let q = field("q", &req.q, model.nq())?;
    match mode {
        Mode::Forward(algo) => {
            let v = field("v", &req.v, model.nv())?;
            let tau = field("tau", &req.tau, model.nv())?;
            let qdd = forward_dynamics(model, data, &q, &v, &tau, None, algo)
                .map_err(|e| e.to_string())?;
            Ok(json!({ "qdd": qdd.as_slice() }))
        }
        Mode::Inverse => {
            let v = field("v", &req.v, model.nv())?;
            let a = field("a", &req.a, model.nv())?;
            let tau = inverse_dynamics(model, data, &q, &v, &a, None).map_err(|e| e.to_string())?;
            Ok(json!({ "tau": tau.as_slice() }))
        }
        Mode::MassMatrix => {
            let m = mass_matrix(model, data, &q).map_err(|e| e.to_string())?;
            let rows: Vec<Vec<f64>> = m.row_iter().map(|r| r.iter().copied().collect()).collect();
            Ok(json!({ "M": rows }))
        }
    }
}

/// A required vector field with the expected length and finite entries.
fn field(name: &str, value: &Option<Vec<f64>>, len: usize) -> Result<DVector<f64>, String> {
    let values = value
        .as_ref()
        .ok_or_else(|| format!("missing field \"{name}\""))?;
    if values.len() != len {
        return Err(format!(
            "\"{name}\" has {} entries, expected {len}",
            values.len()
        ));
    }
    if let Some(i) = values.iter().position(|x| !x.is_finite()) {
        return Err(format!("\"{name}\"[{i}] is not finite"));
    }
    Ok(DVector::from_column_slice(values))
}
