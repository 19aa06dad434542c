//! Helpers shared by the end-to-end CLI tests: run the built `biped` binary, read its output.

// Each test binary uses its own subset of these helpers.
#![allow(dead_code)]

use serde_json::Value;
use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Runs `biped ARGS` with `input` on stdin.
pub fn run(args: &[&str], input: &str) -> Output {
    run_bytes(args, input.as_bytes())
}

/// Runs `biped ARGS` with the bytes `input` on stdin.
pub fn run_bytes(args: &[&str], input: &[u8]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(args)
        .current_dir(env!("CARGO_TARGET_TMPDIR"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let mut stdin = child.stdin.take().expect("stdin");
    let bytes = input.to_vec();
    // Write from a thread: the child may fill its stdout pipe before reading all its input.
    let writer = std::thread::spawn(move || stdin.write_all(&bytes));
    let out = child.wait_with_output().expect("finishes");
    writer.join().expect("writer").expect("write stdin");
    out
}

/// Every stdout line parsed as JSON.
pub fn json_lines(out: &Output) -> Vec<Value> {
    String::from_utf8(out.stdout.clone())
        .expect("utf8")
        .lines()
        .map(|l| serde_json::from_str(l).expect("every output line is JSON"))
        .collect()
}

/// A JSON array of numbers.
pub fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

/// `biped ARGS` with JSON requests on stdin; returns `key` of every answer.
pub fn answers(args: &[&str], requests: &[Value], key: &str) -> Vec<Vec<f64>> {
    let input: String = requests.iter().map(|r| format!("{r}\n")).collect();
    let out = run(args, &input);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let lines = json_lines(&out);
    assert_eq!(lines.len(), requests.len());
    lines.iter().map(|l| floats(&l[key])).collect()
}
