//! Output directories of `biped simulate` and `biped walk`: one run's complete files or a
//! clearly marked failed / interrupted result, never a mix; a second run into a directory in
//! use is refused.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A fresh directory under the test's temporary folder.
fn fresh(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("outputs")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `biped ARGS` started in the background (stderr piped).
fn spawn(args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs")
}

/// `biped ARGS` to its end: (success, stderr).
fn finish(args: &[&str]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(args)
        .output()
        .expect("binary runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn summary(dir: &Path) -> Value {
    let text = std::fs::read_to_string(dir.join("summary.json")).expect("summary.json");
    serde_json::from_str(&text).expect("summary is JSON")
}

/// Sorted file names in `dir`.
fn files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Waits until `path` exists (the background run has taken its lock and started).
fn wait_for(path: &Path, cond: impl Fn(&Path) -> bool) {
    let start = Instant::now();
    while !cond(path) {
        assert!(start.elapsed() < Duration::from_secs(60), "timed out");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Whether a `.NAME.partial-*` sibling of `dir` exists.
fn staging_exists(dir: &Path) -> bool {
    let name = dir.file_name().unwrap().to_string_lossy().into_owned();
    let parent = dir.parent().unwrap();
    std::fs::read_dir(parent).unwrap().any(|e| {
        let f = e.unwrap().file_name().to_string_lossy().into_owned();
        f.starts_with(&format!(".{name}.partial-"))
    })
}

/// Whether the staging sibling of `dir` holds `file` (written whole, so complete).
fn staged(dir: &Path, file: &str) -> bool {
    let name = dir.file_name().unwrap().to_string_lossy().into_owned();
    let parent = dir.parent().unwrap();
    std::fs::read_dir(parent).unwrap().any(|e| {
        let e = e.unwrap();
        let f = e.file_name().to_string_lossy().into_owned();
        f.starts_with(&format!(".{name}.partial-")) && e.path().join(file).exists()
    })
}

/// Sends SIGTERM to `child`.
fn terminate(child: &Child) {
    let pid = child.id().to_string();
    let ok = Command::new("kill").args(["-TERM", &pid]).status().unwrap();
    assert!(ok.success());
}

#[test]
fn a_second_run_into_a_directory_in_use_is_refused() {
    let dir = fresh("concurrent").join("D");
    let d = dir.to_str().unwrap();
    let mut first = spawn(&["simulate", "--duration", "30", "--every", "10", "--out", d]);
    wait_for(&dir, staging_exists);
    let (ok, err) = finish(&[
        "simulate",
        "--scenario",
        "drop",
        "--duration",
        "1",
        "--out",
        d,
    ]);
    assert!(!ok, "second run must fail");
    assert!(err.contains("another biped run"), "{err}");
    assert!(first.wait().unwrap().success());
    let s = summary(&dir);
    assert_eq!(s["status"], "completed");
    assert_eq!(s["scenario"], "stand");
    let csv = std::fs::read_to_string(dir.join("signals.csv")).unwrap();
    let widths: Vec<usize> = csv.lines().map(|l| l.split(',').count()).collect();
    assert!(widths.windows(2).all(|w| w[0] == w[1]), "rows of one width");
}

#[test]
fn a_failed_run_replaces_the_previous_result_with_a_marked_one() {
    let dir = fresh("failed").join("D");
    let d = dir.to_str().unwrap();
    let (ok, err) = finish(&["simulate", "--duration", "0.3", "--out", d]);
    assert!(ok, "{err}");
    assert!(dir.join("com_height.svg").exists());
    // Type 3's stiff gears diverge at 1 ms steps.
    let (ok, err) = finish(&["simulate", "--lola", "type3", "--step", "1e-3", "--out", d]);
    assert!(!ok);
    assert!(err.contains("marked failed"), "{err}");
    let s = summary(&dir);
    assert_eq!(s["status"], "failed");
    assert!(
        s["reason"]
            .as_str()
            .unwrap()
            .contains("simulation failed after"),
        "{s}"
    );
    assert_eq!(
        files(&dir),
        [
            ".biped-output",
            "recording.csv.gz",
            "signals.csv",
            "summary.json"
        ],
        "nothing of the previous run is left beside the failed one"
    );
}

#[test]
fn sigterm_marks_the_result_interrupted() {
    let dir = fresh("sigterm").join("D");
    let d = dir.to_str().unwrap();
    let (ok, err) = finish(&["simulate", "--duration", "0.3", "--out", d]);
    assert!(ok, "{err}");
    let mut child = spawn(&[
        "simulate",
        "--duration",
        "1000",
        "--every",
        "100",
        "--out",
        d,
    ]);
    wait_for(&dir, staging_exists);
    std::thread::sleep(Duration::from_millis(300));
    terminate(&child);
    let status = child.wait().unwrap();
    assert!(!status.success());
    let s = summary(&dir);
    assert_eq!(s["status"], "interrupted", "{s}");
    assert!(s["stopped_at"].as_f64().unwrap() > 0.0);
    assert!(!dir.join("com_height.svg").exists(), "no stale plots");
    assert!(!staging_exists(&dir));
}

#[test]
fn a_walk_interrupted_after_its_first_method_says_so() {
    let dir = fresh("walk").join("W");
    let d = dir.to_str().unwrap();
    let (ok, err) = finish(&["walk", "--steps", "2", "--out", d]);
    assert!(ok, "{err}");
    let child = spawn(&["walk", "--steps", "30", "--out", d]);
    wait_for(&dir, |d| staged(d, "none.csv"));
    terminate(&child);
    let mut child = child;
    assert!(!child.wait().unwrap().success());
    let s = summary(&dir);
    assert_eq!(s["status"], "interrupted", "{s}");
    assert!(s.get("none").is_some(), "the finished method is kept: {s}");
    assert!(s.get("minimization").is_none(), "{s}");
}

#[test]
fn a_directory_of_other_files_is_not_replaced() {
    let dir = fresh("foreign").join("mine");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("thesis.tex"), "keep me").unwrap();
    let (ok, err) = finish(&[
        "simulate",
        "--duration",
        "0.1",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(!ok);
    assert!(
        err.contains("--out") && err.contains("not a biped result"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("thesis.tex")).unwrap(),
        "keep me"
    );
}

#[test]
fn a_killed_run_leaves_the_previous_result_and_its_leftovers_are_removed() {
    let dir = fresh("killed").join("D");
    let d = dir.to_str().unwrap();
    let (ok, err) = finish(&["simulate", "--duration", "0.3", "--out", d]);
    assert!(ok, "{err}");
    let before = std::fs::read(dir.join("summary.json")).unwrap();
    let mut child = spawn(&[
        "simulate",
        "--duration",
        "1000",
        "--every",
        "100",
        "--out",
        d,
    ]);
    wait_for(&dir, staging_exists);
    child.kill().unwrap();
    child.wait().unwrap();
    assert_eq!(std::fs::read(dir.join("summary.json")).unwrap(), before);
    assert!(staging_exists(&dir), "SIGKILL leaves the staging directory");
    let (ok, err) = finish(&["simulate", "--duration", "0.2", "--out", d]);
    assert!(ok, "{err}");
    assert!(!staging_exists(&dir), "the next run removes it");
    assert_eq!(summary(&dir)["status"], "completed");
}
