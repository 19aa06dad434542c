//! `biped walk`: summary.json with the four methods and their fields, CSV and SVG files; with
//! `--dynamic` also `dynamic.csv`, its plots and the `"dynamic"` entry; bad arguments fail with
//! one line.

use std::process::Command;

fn biped() -> Command {
    Command::new(env!("CARGO_BIN_EXE_biped"))
}

#[test]
fn two_steps_write_summary_csv_and_svg() {
    let dir = std::env::temp_dir().join(format!("biped_walk_{}", std::process::id()));
    let out = biped()
        .args(["walk", "--steps", "2", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    for m in ["none", "reference", "compensation", "minimization"] {
        for key in [
            "peak_abs_Lz",
            "peak_abs_dLz",
            "peak_abs_tau_z",
            "min_distance",
            "ik_us_median",
            "ik_us_p99",
        ] {
            let x = v[m][key].as_f64().unwrap_or(f64::NAN);
            assert!(x.is_finite(), "{m}.{key} = {x}");
        }
        let csv = std::fs::read_to_string(dir.join(format!("{m}.csv"))).unwrap();
        assert!(csv.lines().next().unwrap().contains("tau_z"));
        assert!(csv.lines().count() > 1000);
    }
    for svg in ["lz.svg", "tau_z.svg"] {
        let s = std::fs::read_to_string(dir.join(svg)).unwrap();
        assert!(s.contains("<svg"));
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_arguments_fail_with_one_line() {
    for args in [
        vec!["walk", "--method", "foo"],
        vec!["walk", "--steps", "0"],
        vec!["walk", "--step-time=-1"],
        vec!["walk", "--step-length=nan"],
        vec!["walk", "--dynamic", "--steps", "0"],
        vec!["walk", "--dynamic", "--method", "foo"],
        vec!["walk", "--dynamic", "--step-time=-1"],
    ] {
        let out = biped().args(&args).output().unwrap();
        assert!(!out.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
    }
}

/// `biped walk --steps 4 --method none --dynamic EXTRA --out DIR` with a fresh temp DIR.
fn dynamic_walk(tag: &str, extra: &[&str]) -> (std::path::PathBuf, std::process::Output) {
    let dir = std::env::temp_dir().join(format!("biped_walk_{tag}_{}", std::process::id()));
    let out = biped()
        .args(["walk", "--steps", "4", "--method", "none", "--dynamic"])
        .args(extra)
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    (dir, out)
}

#[test]
fn dynamic_walk_writes_csv_plots_and_summary_entry() {
    let (dir, out) = dynamic_walk("dyn", &[]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("dynamic (none): walked"), "{stdout}");
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert!(
        v["none"]["peak_abs_Lz"].as_f64().is_some(),
        "method entry kept"
    );
    assert!(v.get("minimization").is_none(), "only the chosen method");
    let d = &v["dynamic"];
    assert_eq!(d["walked"], serde_json::Value::Bool(true), "{d}");
    assert_eq!(
        d["end_stops"], true,
        "the plant has end stops by default: {d}"
    );
    assert_eq!(
        d["limit_excess"], 0.0,
        "the reference stays inside the ranges: {d}"
    );
    assert!(d["fell_at"].is_null());
    for key in [
        "distance",
        "planned_distance",
        "max_tilt",
        "min_base_height",
        "max_tracking_error",
        "realtime_factor",
        "rhs_evaluations",
        "max_friction_usage",
        "max_slip_speed",
        "max_slip_distance",
    ] {
        let x = d[key].as_f64().unwrap_or(f64::NAN);
        assert!(x.is_finite(), "dynamic.{key} = {x}");
    }
    // the friction verdict and the divergence flag are serialised beside the fall verdict
    assert_eq!(d["friction_kept"], true, "{d}");
    assert!(d["slip_at"].is_null(), "{d}");
    assert_eq!(d["diverged"], false, "{d}");
    assert!(d["distance"].as_f64().unwrap() >= 0.8 * d["planned_distance"].as_f64().unwrap());
    let csv = std::fs::read_to_string(dir.join("dynamic.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    for col in ["base_x", "base_z", "trunk_tilt", "fz_left", "tau_z_right"] {
        assert!(header.contains(col), "{header}");
    }
    assert!(csv.lines().count() > 3000);
    check_flight(&csv, d, &stdout);
    for svg in [
        "dynamic_base.svg",
        "dynamic_tilt.svg",
        "dynamic_fz.svg",
        "dynamic_tau_z.svg",
    ] {
        let s = std::fs::read_to_string(dir.join(svg)).unwrap();
        assert!(s.contains("<svg"), "{svg}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn open_loop_dynamic_walk_falls_with_one_line_error() {
    let (dir, out) = dynamic_walk("fall", &["--open-loop"]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    // stderr also carries the kinematic walk's progress line; the error is one line
    let errors: Vec<&str> = err.lines().filter(|l| l.starts_with("error")).collect();
    assert_eq!(errors.len(), 1, "{err}");
    assert!(errors[0].contains("fell"), "{err}");
    assert_eq!(err.trim().lines().last(), Some(errors[0]));
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["dynamic"]["walked"], serde_json::Value::Bool(false));
    assert!(v["dynamic"]["fell_at"].as_f64().is_some());
    assert!(dir.join("dynamic.csv").exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// The flight figures of the summary recomputed from `dynamic.csv`: the rows where neither
/// side has a contact point down, their longest run, and the largest and mean total force;
/// the terminal line says whether both feet left the ground.
fn check_flight(csv: &str, d: &serde_json::Value, stdout: &str) {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (pl, pr) = (
        col("points_in_contact_left"),
        col("points_in_contact_right"),
    );
    let (fl, fr) = (col("fz_left"), col("fz_right"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let airborne: Vec<bool> = rows.iter().map(|r| r[pl] + r[pr] == 0.0).collect();
    let (mut longest, mut run) = (0usize, 0usize);
    for &a in &airborne {
        run = if a { run + 1 } else { 0 };
        longest = longest.max(run);
    }
    let dt = 1e-3;
    let total = airborne.iter().filter(|a| **a).count() as f64 * dt;
    let num = |k: &str| d[k].as_f64().unwrap();
    assert!((num("flight_time") - total).abs() < 1e-9, "{d}");
    assert!(
        (num("longest_flight") - longest as f64 * dt).abs() < 1e-9,
        "{d}"
    );
    let force: Vec<f64> = rows.iter().map(|r| r[fl] + r[fr]).collect();
    let peak = force.iter().copied().fold(0.0, f64::max);
    let mean = force.iter().sum::<f64>() / force.len() as f64;
    assert!(
        (num("peak_ground_force") - peak).abs() <= 1e-9 * peak,
        "{d}"
    );
    assert!(
        (num("mean_ground_force") - mean).abs() <= 1e-6 * mean,
        "{d}"
    );
    let expected = match longest {
        0 => "dynamic contact: a foot on the ground throughout",
        _ => "dynamic contact: BOTH FEET OFF the ground for",
    };
    assert!(stdout.contains(expected), "{stdout}");
}
