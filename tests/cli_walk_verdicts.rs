//! `biped walk` verdicts: a walk that cannot be kept exits non-zero with one line naming the
//! quantity, the joints, the time and the amount, and lists it in `summary.json`;
//! `--allow-violations` turns it into a warning; every method writes its full trajectory.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn walk(tag: &str, extra: &[&str]) -> (PathBuf, Output) {
    let dir = std::env::temp_dir().join(format!("biped_verdict_{tag}_{}", std::process::id()));
    let out = Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(["walk", "--steps", "2", "--method", "none", "--out"])
        .arg(&dir)
        .args(extra)
        .output()
        .unwrap();
    (dir, out)
}

fn summary(dir: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap()
}

/// Steps of 0.5 m taken slowly (2 s): the stance knee reaches its stretch limit before the
/// swing foot lands, so the IK cannot reach the footstep.
const INFEASIBLE: [&str; 4] = ["--step-length", "0.5", "--step-time", "2"];

#[test]
fn infeasible_walk_exits_non_zero_naming_the_joint_and_time() {
    let (dir, out) = walk("fail", &INFEASIBLE);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    for part in [
        "none walk: tracking",
        "l_shank",
        "t = ",
        "--allow-violations",
    ] {
        assert!(err.contains(part), "`{part}` missing in: {err}");
    }
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("tracking: MISSED by none"), "{stdout}");
    let s = summary(&dir);
    assert_eq!(s["status"], "completed");
    assert_eq!(s["none"]["verdicts"]["tracking"]["kept"], false);
    let tracking = &s["none"]["verdicts"]["tracking"];
    assert!(tracking["value"].as_f64().unwrap() > 0.02);
    assert!(tracking["at"].as_str().unwrap().contains("l_shank"));
    let listed = s["violations"].as_array().unwrap();
    assert!(listed[0]
        .as_str()
        .unwrap()
        .starts_with("none walk: tracking"));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn allow_violations_warns_and_succeeds() {
    let (dir, out) = walk(
        "allow",
        &[&INFEASIBLE[..], &["--allow-violations"]].concat(),
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(err.starts_with("warning: none walk: tracking"), "{err}");
    assert_eq!(summary(&dir)["violations"].as_array().unwrap().len(), 1);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn feasible_walk_keeps_every_verdict_and_writes_its_trajectory() {
    let (dir, out) = walk("ok", &[]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for line in [
        "tracking: kept",
        "joint limits: kept",
        "self-collision: none",
        "friction: kept",
    ] {
        assert!(stdout.contains(line), "`{line}` missing in: {stdout}");
    }
    let s = summary(&dir);
    assert_eq!(s["violations"].as_array().unwrap().len(), 0);
    for check in ["tracking", "joint_limits", "self_collision", "friction"] {
        assert_eq!(s["none"]["verdicts"][check]["kept"], true, "{check}");
    }
    let csv = std::fs::read_to_string(dir.join("none_trajectory.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    for col in [
        "time",
        "q[root.x]",
        "q[root.qw]",
        "q[l_toe]",
        "com.z",
        "zmp.x",
    ] {
        assert!(header.contains(&col), "{col} missing");
    }
    for col in ["l_sole.qw", "r_sole.x", "ground.fz", "ground.tau_n"] {
        assert!(header.contains(&col), "{col} missing");
    }
    let rows = summary(&dir)["none"]["cycles"].as_u64().unwrap() as usize;
    assert_eq!(csv.lines().count(), rows + 1);
    std::fs::remove_dir_all(&dir).ok();
}

/// The dynamic walk's contact verdict: 4 steps of 0.5 m hop at the step changes (both feet
/// off the ground for tens of ms); the run exits 1 with one line naming the phase, its length
/// and time as `summary.json` has them, and `--allow-violations` accepts it.
#[test]
fn a_hopping_dynamic_walk_violates_contact() {
    let dir = std::env::temp_dir().join(format!("biped_verdict_hop_{}", std::process::id()));
    let args = [
        "walk",
        "--steps",
        "4",
        "--step-length",
        "0.5",
        "--method",
        "compensation",
        "--dynamic",
    ];
    let run = |extra: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_biped"))
            .args(args)
            .arg("--out")
            .arg(&dir)
            .args(extra)
            .output()
            .unwrap()
    };
    let out = run(&[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{err}");
    let s = summary(&dir);
    let d = &s["dynamic"];
    assert_eq!(d["contact_kept"], false, "{d}");
    let (longest, at) = (
        d["longest_flight"].as_f64().unwrap(),
        d["longest_flight_at"].as_f64().unwrap(),
    );
    assert!(longest > 0.02, "{d}");
    let line = format!(
        "dynamic walk: contact: both feet off the ground for {longest:.3} s from t = {at:.3} s"
    );
    assert!(err.contains(&line), "`{line}` missing in: {err}");
    let listed = s["violations"].as_array().unwrap();
    assert!(
        listed
            .iter()
            .any(|v| v.as_str().unwrap().starts_with(&line)),
        "{listed:?}"
    );
    let out = run(&["--allow-violations"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(err.contains("warning: dynamic walk: contact"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// The contact verdict: three steps of 0.5 m with the arms held still lift the rear foot's toe
/// 8.7 mm off the ground at the first step change while the IK still tracks its tasks; the run
/// exits 1 with one line naming the foot, the amount and the time, `summary.json` has the
/// verdict and the method's CSV the lift per cycle.
#[test]
fn a_plan_lifting_a_supporting_foot_violates_contact() {
    let dir = std::env::temp_dir().join(format!("biped_verdict_lift_{}", std::process::id()));
    let out = Command::new(env!("CARGO_BIN_EXE_biped"))
        .args([
            "walk",
            "--steps",
            "3",
            "--step-length",
            "0.5",
            "--method",
            "none",
        ])
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    for part in [
        "none walk: contact: the right toe",
        "mm above it at t = ",
        "--allow-violations",
    ] {
        assert!(err.contains(part), "`{part}` missing in: {err}");
    }
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("tracking: kept"), "{stdout}");
    assert!(stdout.contains("contact: LIFTED by none"), "{stdout}");
    let s = summary(&dir);
    let contact = &s["none"]["verdicts"]["contact"];
    assert_eq!(contact["kept"], false, "{contact}");
    let lift = contact["value"].as_f64().unwrap();
    assert!(lift > 0.005 && lift <= s["none"]["max_foot_lift"].as_f64().unwrap());
    let csv = std::fs::read_to_string(dir.join("none.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    assert!(header.contains(&"foot_lift") && header.contains(&"task_error"));
    std::fs::remove_dir_all(&dir).ok();
}
