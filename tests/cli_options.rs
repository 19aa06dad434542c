//! Command-line option handling of every sub-command: a closed stdout ends a run quietly, every
//! bad option value is one error line naming the option and its valid range (never an internal
//! name, never a wrong option), negative numbers reach the range checks, file errors name the
//! path, options that would be ignored are refused, and an unbounded recording is refused
//! before it starts.

use std::os::fd::OwnedFd;
use std::os::unix::net::UnixStream;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

const G1: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/crates/dynamics/data/g1_29dof_rev_1_0.urdf"
);
const G1_FEET: &str = "left_ankle_roll_link,right_ankle_roll_link";
const HUMANOID: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/crates/ssv/data/humanoid.toml");
const CALIBRATION: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/crates/robots/data/calibration_example.json"
);

/// A fresh folder under the test target's temporary directory.
fn temp(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_options")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `biped ARGS` with empty stdin, run in the test target's temporary directory.
fn biped(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(args)
        .current_dir(env!("CARGO_TARGET_TMPDIR"))
        .stdin(Stdio::null())
        .output()
        .expect("binary runs")
}

/// `biped ARGS` with `input` on stdin and a stdout whose reader is gone before the run starts
/// (the peer of a socket pair, closed: every write fails with a broken pipe, deterministically).
fn biped_closed_stdout(args: &[&str], input: &str) -> Output {
    let (ours, theirs) = UnixStream::pair().unwrap();
    drop(ours);
    let dir = temp(&format!("pipe_{}", args.join("_").replace('/', "_")));
    let input_file = dir.join("stdin");
    std::fs::write(&input_file, input).unwrap();
    Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(args)
        .current_dir(&dir)
        .stdin(std::fs::File::open(&input_file).unwrap())
        .stdout(Stdio::from(OwnedFd::from(theirs)))
        .stderr(Stdio::piped())
        .output()
        .expect("binary runs")
}

/// Asserts that `biped ARGS` ends quietly with status 0 when stdout's reader is gone.
fn ends_quietly(args: &[&str], input: &str) {
    let out = biped_closed_stdout(args, input);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    assert_ne!(out.status.code(), Some(101), "{args:?}: {err}");
    assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
    assert!(err.trim().is_empty(), "{args:?}: {err}");
}

/// Asserts that `biped ARGS` fails with one stderr line that contains every `expected` part.
fn fails_with(args: &[&str], expected: &[&str]) -> String {
    let out = biped(args);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(!out.status.success(), "{args:?} succeeded: {err}");
    assert_ne!(out.status.code(), Some(101), "{args:?}: {err}");
    assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
    for e in expected {
        assert!(err.contains(e), "{args:?}: `{}` lacks `{e}`", err.trim());
    }
    err
}

/// `simulate --out <tmp> --duration 0.01 ARGS`.
fn simulate_args<'a>(out: &'a str, args: &[&'a str]) -> Vec<&'a str> {
    let mut v = vec!["simulate", "--out", out, "--duration", "0.01"];
    v.extend_from_slice(args);
    v
}

#[test]
fn closed_stdout_ends_quietly() {
    let query = "{\"a\": {\"point\": [0,0,0], \"radius\": 0.1}, \"b\": {\"point\": [1,0,0], \"radius\": 0.1}}\n";
    let state = "{\"q\": [0,0,0,0], \"v\": [0,0,0,0], \"tau\": [0,0,0,0]}\n";
    let cases: &[(&[&str], &str)] = &[
        (&["ssv", "model", HUMANOID], ""),
        (&["ssv", "model", HUMANOID, "--json"], ""),
        (&["ssv", "bench"], ""),
        (&["ssv", "query"], query),
        (&["simulate", "--duration", "0.01", "--out", "sim"], ""),
        (&["model", "--lola", "type2"], ""),
        (&["dynamics", "--dill", "2"], state),
        (&["--help"], ""),
    ];
    for (args, input) in cases {
        ends_quietly(args, input);
    }
}

/// The sub-commands whose output code is still printed with `println!` (their files are being
/// rewritten elsewhere): to be enabled when they write through `cli::out`.
#[test]
fn closed_stdout_ends_quietly_in_calibrate_walk_and_bench() {
    ends_quietly(&["calibrate", CALIBRATION], "");
    ends_quietly(&["walk", "--steps", "1", "--out", "walk"], "");
    ends_quietly(&["bench", "dynamics", "--dill", "2"], "");
}

#[test]
fn step_longer_than_the_control_period_is_refused() {
    let dir = temp("step");
    let out = dir.to_str().unwrap();
    fails_with(
        &simulate_args(out, &["--step", "1"]),
        &[
            "--step: 1 s is out of range",
            "<= 0.001 s",
            "control period",
        ],
    );
    fails_with(
        &simulate_args(out, &["--lola", "type3", "--step", "2e-3"]),
        &["--step", "<= 0.001 s"],
    );
}

/// A step that does not divide the control period is rounded down to one that does, and that
/// step is what the report and the summary say.
#[test]
fn the_reported_step_is_the_step_taken() {
    let dir = temp("step_taken");
    let out = biped(&simulate_args(dir.to_str().unwrap(), &["--step", "3e-4"]));
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("(h = 0.00025 s)"), "{text}");
    let summary = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&summary).unwrap();
    assert_eq!(v["step"].as_f64(), Some(0.00025));
    // 10 ms in steps of a quarter of the 1 ms period.
    assert_eq!(v["steps"].as_u64(), Some(40));
}

/// Values that used to be blamed on another option or reported under an internal name.
#[test]
fn errors_name_the_option_not_an_internal_name() {
    let dir = temp("names");
    let out = dir.to_str().unwrap();
    let g1 = ["--urdf", G1, "--floating", "--feet", G1_FEET];
    let cases: &[(&[&str], &[&str])] = &[
        (
            &[&g1[..], &["--scenario", "sway", "--sway-joints", "a,b,c,d"]].concat(),
            &["--sway-joints", "`a`"],
        ),
        (
            &["--contact", "1e5,0"],
            &["--contact: damping 0 N s/m is out of range", ">= 0.01"],
        ),
        (
            &["--contact", "1e300,1e300"],
            &[
                "--contact: stiffness 1e300 N/m is out of range",
                "<= 1e8 N/m",
            ],
        ),
        (
            &["--integrator", "dopri5", "--tolerances", "1e-300,1e-300"],
            &["--tolerances: rtol 1e-300 is out of range", ">= 1e-12"],
        ),
        (
            &[&g1[..], &["--sole-size", "1e300,1e300"]].concat(),
            &["--sole-size: length 1e300 m is out of range", "<= 1 m"],
        ),
        (
            &["--pose", "l_shank=100"],
            &["--pose: `l_shank` 100 rad is out of range"],
        ),
        (&["--friction", "nan"], &["--friction: NaN is out of range"]),
        (
            &["--scenario", "sway", "--sway", "0.1,1e9"],
            &["--sway: period 1e9 s is out of range"],
        ),
    ];
    for (args, expected) in cases {
        let err = fails_with(&simulate_args(out, args), expected);
        for internal in ["contact.", "argument `", "result `"] {
            assert!(!err.contains(internal), "{args:?}: {err}");
        }
    }
}

/// Negative values of numeric options reach the range checks, written with a space.
#[test]
fn negative_numbers_reach_the_range_checks() {
    let dir = temp("negative");
    let out = dir.to_str().unwrap();
    fails_with(
        &["walk", "--step-length", "-5"],
        &["--step-length: -5 m", ">= -0.6"],
    );
    fails_with(&["walk", "--steps", "-1"], &["--steps: -1 is out of range"]);
    fails_with(&["walk", "--step-time", "-1e-3"], &["--step-time"]);
    fails_with(
        &simulate_args(
            out,
            &[
                "--urdf",
                G1,
                "--floating",
                "--feet",
                G1_FEET,
                "--sole-size",
                "-1,1",
            ],
        ),
        &["--sole-size: length -1 m is out of range"],
    );
    fails_with(
        &simulate_args(out, &["--step", "-1e-3"]),
        &["--step: -0.001 s is out of range"],
    );
    fails_with(&simulate_args(out, &["--every", "-2"]), &["--every: -2"]);
    fails_with(&["model", "--dill", "-3"], &["--dill"]);
    fails_with(
        &["bench", "dynamics", "--dill-range", "-1..3"],
        &["--dill-range"],
    );
    // A negative value in range is accepted: a backward walk of one step.
    let walk = temp("walk_back");
    let ok = biped(&[
        "walk",
        "--steps",
        "1",
        "--step-length",
        "-0.2",
        "--method",
        "none",
        "--out",
        walk.to_str().unwrap(),
    ]);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
}

#[test]
fn file_errors_name_the_path() {
    // `bench dynamics --dill-range` writes its plot under `out/`: here `out` is a file.
    let dir = temp("plot");
    std::fs::write(dir.join("out"), "").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(["bench", "dynamics", "--dill-range", "1..1"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains("folder out: File exists"), "{err}");
}

#[test]
fn walk_output_folder_error_names_the_path() {
    fails_with(&["walk", "--steps", "1", "--out", "/proc/x"], &["/proc/x"]);
}

/// URDF import options with another model source, and options that the other options would
/// make meaningless, are errors instead of being ignored.
#[test]
fn ignored_options_are_refused() {
    let dir = temp("ignored");
    let out = dir.to_str().unwrap();
    let only_urdf = "only applies with --urdf FILE";
    fails_with(
        &["model", "--dill", "2", "--floating"],
        &["--floating", only_urdf],
    );
    fails_with(
        &["model", "--lola", "type2", "--floating"],
        &["--floating", only_urdf],
    );
    fails_with(
        &["model", "--lola", "type2", "--reject-mimic"],
        &["--reject-mimic", only_urdf],
    );
    fails_with(
        &["dynamics", "--dill", "2", "--floating"],
        &["--floating", only_urdf],
    );
    fails_with(
        &["bench", "dynamics", "--dill-range", "1..2", "--floating"],
        &["--floating", only_urdf],
    );
    for flag in [
        &["--floating"][..],
        &["--feet", G1_FEET],
        &["--sole-center", "0,0,0"],
        &["--armature", "*=0.1"],
        &["--srdf", "x.srdf"],
    ] {
        let args = [&["--lola", "type2"][..], flag].concat();
        fails_with(&simulate_args(out, &args), &[flag[0]]);
    }
    fails_with(
        &simulate_args(
            out,
            &[
                "--urdf",
                G1,
                "--floating",
                "--feet",
                "left_ankle_roll_link,left_ankle_roll_link",
            ],
        ),
        &["--feet", "`left_ankle_roll_link` is given twice"],
    );
    let g1 = ["--urdf", G1, "--floating", "--feet", G1_FEET];
    let hips =
        "left_hip_roll_joint,left_hip_roll_joint,left_ankle_roll_joint,right_ankle_roll_joint";
    fails_with(
        &simulate_args(
            out,
            &[&g1[..], &["--scenario", "sway", "--sway-joints", hips]].concat(),
        ),
        &["--sway-joints", "given twice"],
    );
    let four =
        "left_hip_roll_joint,right_hip_roll_joint,left_ankle_roll_joint,right_ankle_roll_joint";
    fails_with(
        &simulate_args(out, &[&g1[..], &["--sway-joints", four]].concat()),
        &["--sway-joints: only applies with --scenario sway"],
    );
    fails_with(
        &[
            "dynamics",
            "--dill",
            "2",
            "--algorithm",
            "crba",
            "--mass-matrix",
        ],
        &["--algorithm", "--mass-matrix"],
    );
    fails_with(
        &["model", "--dill", "40"],
        &["--dill: level 40", "valid levels are 0..16"],
    );
    fails_with(
        &["bench", "dynamics", "--dill-range", "0..40"],
        &["--dill-range", "valid levels are 0..16"],
    );
}

/// A run whose recording would not fit the memory cap is refused at once, with the size and
/// the way out; durations beyond a million seconds are out of range.
#[test]
fn unbounded_recording_is_refused_up_front() {
    let dir = temp("recording");
    let out = dir.to_str().unwrap();
    let start = Instant::now();
    let err = fails_with(
        &["simulate", "--duration", "1e6", "--out", out],
        &[
            "--duration",
            "1000000001 rows",
            "GiB",
            "1 GiB cap",
            "--every ",
        ],
    );
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "took {:?}",
        start.elapsed()
    );
    assert!(!dir.join("signals.csv").exists());
    // The suggested `--every` is a whole number >= 2.
    let n: u64 = err
        .split("--every ")
        .nth(1)
        .unwrap()
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(n >= 2, "{err}");
    fails_with(
        &["simulate", "--duration", "1e7", "--out", out],
        &["--duration: 1e7 s is out of range", "<= 1e6 s"],
    );
    fails_with(
        &["simulate", "--duration", "1e-4", "--out", out],
        &["--duration", ">= 0.001", "control period"],
    );
}

/// Command-line errors found by the argument parser are one line too.
#[test]
fn parser_errors_are_one_line() {
    fails_with(&["walk", "--open-loop"], &["--dynamic"]);
    fails_with(&["walk", "--no-such-option"], &["--no-such-option"]);
    fails_with(&["model"], &["--urdf", "--dill", "--lola"]);
    fails_with(&["walk", "--method", "foo"], &["--method: ", "`foo`"]);
}
