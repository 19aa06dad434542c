//! Helpers of the JSON Lines tests of `biped ssv query` and `biped dynamics`: check that every
//! non-blank input line got one answer or one error naming its line, with finite numbers only.

// Each test binary uses its own subset of these helpers.
#![allow(dead_code)]

use serde_json::Value;
use std::process::Output;

/// 1-based numbers of the lines of `input` that need an answer: all but the blank ones (a
/// byte-order mark at the start does not count; a line that is not UTF-8 is not blank).
pub fn answered_lines(input: &[u8]) -> Vec<usize> {
    let input = input.strip_prefix(b"\xef\xbb\xbf").unwrap_or(input);
    let input = input.strip_suffix(b"\n").unwrap_or(input);
    if input.is_empty() {
        return Vec::new();
    }
    input
        .split(|&b| b == b'\n')
        .enumerate()
        .filter(|(_, line)| std::str::from_utf8(line).map_or(true, |t| !t.trim().is_empty()))
        .map(|(i, _)| i + 1)
        .collect()
}

/// True if every number in `v` is finite (serde_json writes NaN and infinities as `null`,
/// which must not appear in an answer either).
pub fn all_finite(v: &Value) -> bool {
    match v {
        Value::Null => false,
        Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        Value::Array(items) => items.iter().all(all_finite),
        Value::Object(map) => map.values().all(all_finite),
        _ => true,
    }
}

/// Checks the output of a JSON Lines command on `input`: one JSON line per answered input
/// line, in order; an error names its line, an answer has the key `key` and finite numbers
/// only. Returns the number of errors.
pub fn check_answers(input: &[u8], out: &Output, key: &str) -> Result<usize, String> {
    let text = String::from_utf8(out.stdout.clone()).map_err(|e| e.to_string())?;
    let lines: Vec<&str> = text.lines().collect();
    let expected = answered_lines(input);
    if lines.len() != expected.len() {
        return Err(format!(
            "{} answers for {} lines",
            lines.len(),
            expected.len()
        ));
    }
    let mut errors = 0;
    for (line, n) in lines.iter().zip(expected) {
        let v: Value = serde_json::from_str(line).map_err(|e| format!("{e}: {line}"))?;
        if let Some(msg) = v.get("error") {
            let msg = msg.as_str().unwrap_or_default();
            if !msg.starts_with(&format!("line {n}: ")) {
                return Err(format!("error for line {n}: {msg}"));
            }
            errors += 1;
        } else if v.get(key).is_none() || !all_finite(&v) {
            return Err(format!("answer for line {n}: {line}"));
        }
    }
    let code = out.status.code();
    match (errors, code) {
        (0, Some(0)) | (1.., Some(1)) => Ok(errors),
        _ => Err(format!("{errors} errors, exit code {code:?}")),
    }
}
