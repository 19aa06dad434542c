//! End-to-end tests of `biped bench ik`: the JSON line, errors for a bad robot, and the
//! tracking and limit checks of the run.

mod common;

use common::{json_lines, run};
use std::path::{Path, PathBuf};

/// The repository root.
fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A copy of the bundled G1 description with absolute paths, edited by `edit`, written to
/// the test's temporary folder as `name`.
fn g1_variant(name: &str, mut edit: impl FnMut(&str) -> Option<String>) -> PathBuf {
    let text = std::fs::read_to_string(root().join("crates/robots/data/g1.toml")).unwrap();
    let urdf = root().join("crates/dynamics/data/g1_29dof_rev_1_0.urdf");
    let ssv = root().join("crates/robots/data/g1_ssv.toml");
    let lines: Vec<String> = text
        .lines()
        .filter_map(&mut edit)
        .map(|l| match l {
            l if l.starts_with("urdf = ") => format!("urdf = {:?}", urdf.display().to_string()),
            l if l.starts_with("model = ") => format!("model = {:?}", ssv.display().to_string()),
            l => l,
        })
        .collect();
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&path, lines.join("\n")).unwrap();
    path
}

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn json_is_one_line_of_two_timings() {
    let out = run(
        &["bench", "ik", "--robot", "g1", "--steps", "50", "--json"],
        "",
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let lines = json_lines(&out);
    assert_eq!(lines.len(), 1);
    let v = &lines[0];
    let keys: Vec<&String> = v.as_object().unwrap().keys().collect();
    assert_eq!(keys, ["full", "peer_tasks"]);
    for set in ["peer_tasks", "full"] {
        let t = v[set].as_object().unwrap();
        assert_eq!(t.len(), 2, "{set}: {t:?}");
        let (median, p99) = (
            t["median_us"].as_f64().unwrap(),
            t["p99_us"].as_f64().unwrap(),
        );
        // one step of a 35-DoF IK is more than 100 ns and far less than a 1 ms cycle's worth
        assert!(median > 0.1 && median < 1e4, "{set}: median {median} us");
        assert!(p99 >= median, "{set}: p99 {p99} < median {median}");
    }
}

#[test]
fn text_run_tracks_and_keeps_the_joint_limits() {
    let out = run(&["bench", "ik", "--robot", "g1", "--steps", "300"], "");
    assert!(out.status.success(), "{}", stderr(&out));
    let text = String::from_utf8(out.stdout).unwrap();
    let sets: Vec<&str> = text.lines().skip(1).collect();
    assert_eq!(sets.len(), 2, "{text}");
    for line in sets {
        let after = |key: &str| -> f64 {
            let rest =
                &line[line.find(key).unwrap_or_else(|| panic!("{key} in {line}")) + key.len()..];
            let word = rest.split_whitespace().next().unwrap();
            word.trim_end_matches([',', ';']).parse().unwrap()
        };
        // the URDF limits are kept with the default margin of 0.01 rad
        assert!(after("joint margin >=") >= 0.01 - 1e-9, "{line}");
        assert!(after("worst foot") < 2e-3, "{line}");
        assert!(after("CoM") < 2e-3, "{line}");
    }
    assert!(text.contains("closest active pair"), "{text}");
}

#[test]
fn comfort_variant_runs() {
    let args = [
        "bench",
        "ik",
        "--robot",
        "g1",
        "--steps",
        "50",
        "--posture",
        "comfort",
        "--json",
    ];
    let out = run(&args, "");
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(json_lines(&out).len(), 1);
}

#[test]
fn unknown_robot_is_one_line_naming_the_option() {
    let out = run(&["bench", "ik", "--robot", "nosuchbot"], "");
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("--robot") && err.contains("nosuchbot"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
}

#[test]
fn bad_description_file_is_located() {
    let missing = Path::new(env!("CARGO_TARGET_TMPDIR")).join("missing_robot.toml");
    let out = run(
        &["bench", "ik", "--robot", &missing.display().to_string()],
        "",
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("missing_robot.toml"),
        "{}",
        stderr(&out)
    );

    let bad = g1_variant("bench_ik_bad_knee.toml", |l| {
        Some(if l.starts_with("left_knee_joint = ") {
            "left_knee_joint = -0.5".into()
        } else {
            l.into()
        })
    });
    let out = run(&["bench", "ik", "--robot", &bad.display().to_string()], "");
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("bench_ik_bad_knee.toml:") && err.contains("left_knee_joint"),
        "{err}"
    );
}

#[test]
fn a_description_without_collision_model_cannot_run_the_full_set() {
    let mut in_collision = false;
    let path = g1_variant("bench_ik_no_collision.toml", move |l| {
        if l.starts_with('[') {
            in_collision = l == "[collision]";
        }
        (!in_collision).then(|| l.to_string())
    });
    let out = run(
        &[
            "bench",
            "ik",
            "--robot",
            &path.display().to_string(),
            "--steps",
            "20",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("[collision]"), "{}", stderr(&out));
}

#[test]
fn an_ik_that_does_not_track_fails_the_bench() {
    // straight legs at the start: singular for the step's vertical foot motion, so the
    // velocity-limited IK falls behind the moving foot target
    let path = g1_variant("bench_ik_straight.toml", |l| {
        let leg = [
            "_hip_pitch_joint = ",
            "_knee_joint = ",
            "_ankle_pitch_joint = ",
        ];
        (!leg.iter().any(|k| l.contains(k))).then(|| l.to_string())
    });
    let out = run(
        &[
            "bench",
            "ik",
            "--robot",
            &path.display().to_string(),
            "--steps",
            "200",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("did not track"), "{}", stderr(&out));
}

#[test]
fn steps_out_of_range_is_a_usage_error_naming_the_option() {
    for steps in ["0", "10000001", "-3"] {
        let out = run(&["bench", "ik", "--robot", "g1", "--steps", steps], "");
        assert_eq!(out.status.code(), Some(2), "--steps {steps}");
        let err = stderr(&out);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains("--steps"), "{err}");
    }
}

#[test]
fn a_start_inside_the_limit_margin_may_not_come_closer() {
    // the left knee starts 0.007 rad above its lower limit -0.087267, inside the IK's margin
    // of 0.01: the run passes if it never comes closer than that
    let path = g1_variant("bench_ik_knee_in_margin.toml", |l| {
        Some(if l.starts_with("left_knee_joint = ") {
            "left_knee_joint = -0.080267".into()
        } else {
            l.into()
        })
    });
    let out = run(
        &[
            "bench",
            "ik",
            "--robot",
            &path.display().to_string(),
            "--steps",
            "50",
        ],
        "",
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let text = String::from_utf8(out.stdout).unwrap();
    for line in text.lines().skip(1) {
        let m: f64 = line.split("joint margin >= ").nth(1).unwrap()[..6]
            .parse()
            .unwrap();
        assert!((0.007 - 1e-9..0.01).contains(&m), "{line}");
    }
}
