//! End-to-end numerical input checks and memory bounds: free-flyer quaternion norms in
//! `biped dynamics`, O(n) dynamics of a large tree under an address-space limit, the Dill
//! range of `biped bench dynamics`, and calibration files with out-of-range values.

mod common;

use common::{json_lines, run};
use serde_json::json;
use std::path::PathBuf;
use std::process::{Command, Stdio};

/// The bundled G1 humanoid URDF.
fn g1() -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("crates/dynamics/data/g1_29dof_rev_1_0.urdf")
        .display()
        .to_string()
}

/// A request line for the floating G1 (nq = 36, nv = 35) at 0.8 m with quaternion `quat`.
fn g1_request(quat: [f64; 4]) -> String {
    let mut q = vec![0.0; 36];
    q[2] = 0.8;
    q[3..7].copy_from_slice(&quat);
    format!(
        "{}\n",
        json!({"q": q, "v": vec![0.0; 35], "tau": vec![0.0; 35]})
    )
}

#[test]
fn free_flyer_quaternion_norm_is_checked() {
    let quats = [
        [0.0, 0.0, 0.0, 1e155],
        [0.0, 0.0, 0.0, 2.0],
        [0.0, 0.0, 0.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
        [0.0, 0.0, 0.0, 1.005],
    ];
    let input: String = quats.iter().map(|q| g1_request(*q)).collect();
    let out = run(&["dynamics", "--urdf", &g1(), "--floating"], &input);
    assert_ne!(
        out.status.code(),
        Some(0),
        "bad lines make the exit status non-zero"
    );
    let lines = json_lines(&out);
    assert_eq!(lines.len(), 5);
    for (line, norm) in [(0, "1e155"), (1, "2e0")] {
        let e = lines[line]["error"].as_str().unwrap();
        assert!(
            e.contains("`root`") && e.contains(&format!("norm {norm}")),
            "{e}"
        );
    }
    assert!(lines[2]["error"].as_str().unwrap().contains("zero norm"));
    // Unit and within-tolerance quaternions: free fall, qdd_z = -9.81.
    for line in [3, 4] {
        let qdd = lines[line]["qdd"].as_array().unwrap();
        assert!(
            (qdd[2].as_f64().unwrap() + 9.81).abs() < 1e-9,
            "{:?}",
            lines[line]
        );
    }
    let mut q = vec![0.0; 36];
    q[6] = 1e155;
    let request = format!("{}\n", json!({ "q": q }));
    let m = run(
        &["dynamics", "--urdf", &g1(), "--floating", "--mass-matrix"],
        &request,
    );
    let e = json_lines(&m)[0]["error"].as_str().unwrap().to_string();
    assert!(e.contains("norm 1e155"), "{e}");
}

/// `biped ARGS` under an address-space limit of `kib` KiB (`ulimit -v`), `input` on stdin.
#[cfg(target_os = "linux")]
fn run_limited(kib: u64, args: &[&str], input: &str) -> std::process::Output {
    use std::io::Write;
    let script = format!("ulimit -v {kib} && exec \"$0\" \"$@\"");
    let mut child = Command::new("sh")
        .args(["-c", &script, env!("CARGO_BIN_EXE_biped")])
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("sh runs");
    let mut stdin = child.stdin.take().unwrap();
    // A child that dies early (out of memory) closes the pipe: its status tells.
    let _ = stdin.write_all(input.as_bytes());
    drop(stdin);
    child.wait_with_output().unwrap()
}

#[cfg(target_os = "linux")]
#[test]
fn o_n_dynamics_of_dill_14_runs_in_bounded_memory() {
    // Dill(14): 16384 bodies. A dense mass matrix alone is 2 GiB; the O(n) query fits in 1 GB.
    let n = 1 << 14;
    let line = format!(
        "{}\n",
        json!({"q": vec![0.5; n], "v": vec![1.0; n], "tau": vec![0.0; n]})
    );
    let out = run_limited(1_000_000, &["dynamics", "--dill", "14"], &line);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let qdd = json_lines(&out)[0]["qdd"].as_array().unwrap().len();
    assert_eq!(qdd, n);
    // The dense algorithm cannot have its 2 GiB there: a clear error line, not an abort.
    let out = run_limited(
        1_000_000,
        &["dynamics", "--dill", "14", "--algorithm", "crba"],
        &line,
    );
    assert_eq!(out.status.code(), Some(1));
    let e = json_lines(&out)[0]["error"].as_str().unwrap().to_string();
    assert!(
        e.contains("cannot allocate the 16384 x 16384 mass matrix"),
        "{e}"
    );
}

#[test]
fn bench_dill_range_is_validated_before_running() {
    let t = std::time::Instant::now();
    let out = run(&["bench", "dynamics", "--dill-range", "0..40"], "");
    assert_ne!(out.status.code(), Some(0));
    assert!(out.stdout.is_empty(), "no level was run");
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("0..40") && err.contains("0..16"), "{err}");
    // Levels 0-16 take minutes; the check comes first.
    assert!(t.elapsed().as_secs() < 20, "{:?}", t.elapsed());
}

/// The bundled calibration example with an absolute URDF path, edited by `edit`, written to
/// the test directory as `name`; its path.
fn calibration_file(name: &str, edit: impl FnOnce(String) -> String) -> String {
    let example = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/crates/robots/data/calibration_example.json"
    );
    let text = std::fs::read_to_string(example).unwrap().replace(
        "../../dynamics",
        concat!(env!("CARGO_MANIFEST_DIR"), "/crates/dynamics"),
    );
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&path, edit(text)).unwrap();
    path.display().to_string()
}

#[test]
fn calibration_rejects_out_of_range_values_and_accepts_a_byte_order_mark() {
    let huge_target = calibration_file("cal_huge_target.json", |t| {
        let at = t.find("\"xyz\": [").unwrap() + "\"xyz\": [".len();
        let end = at + t[at..].find(',').unwrap();
        format!("{}1e300{}", &t[..at], &t[end..])
    });
    let out = run(&["calibrate", &huge_target, "--json"], "");
    assert_ne!(out.status.code(), Some(0));
    assert!(out.stdout.is_empty(), "no report");
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("cal_huge_target.json:") && err.contains("xyz[0]"),
        "{err}"
    );
    assert!(err.contains("1e300 m is outside"), "{err}");
    let duplicate = calibration_file("cal_duplicate.json", |t| {
        t.replacen("\"left_hip_roll_joint\",", "\"left_hip_pitch_joint\",", 1)
    });
    let out = run(&["calibrate", &duplicate], "");
    assert_ne!(out.status.code(), Some(0));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("joints[1]: duplicate joint `left_hip_pitch_joint`"),
        "{err}"
    );
    let bom = calibration_file("cal_bom.json", |t| format!("\u{feff}{t}"));
    let out = run(&["calibrate", &bom, "--json"], "");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(json_lines(&out)[0]["offsets"].as_array().unwrap().len(), 12);
}
