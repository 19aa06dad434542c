//! End-to-end tests of `biped calibrate` on the bundled G1 example (thesis 3.5).

mod common;

use common::{json_lines, run};

const EXAMPLE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/crates/robots/data/calibration_example.json"
);

#[test]
fn json_report_recovers_reference_offsets() {
    let out = run(&["calibrate", EXAMPLE, "--json"], "");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json_lines(&out);
    assert_eq!(v.len(), 1, "one JSON object");
    let offsets = v[0]["offsets"].as_array().unwrap();
    assert_eq!(offsets.len(), 12);
    for o in offsets {
        let (x, r) = (
            o["offset"].as_f64().unwrap(),
            o["reference"].as_f64().unwrap(),
        );
        // Example generated with 1e-4 rad encoder noise (see calib_file.rs): 5 sigma.
        assert!((x - r).abs() < 5e-4, "{o}");
    }
    for p in v[0]["poses"].as_array().unwrap() {
        let (b, a) = (
            p["rms_before"].as_f64().unwrap(),
            p["rms_after"].as_f64().unwrap(),
        );
        assert!(a < 1e-2 * b, "{p}");
        assert_eq!(p["constraints"].as_array().unwrap().len(), 2);
    }
}

#[test]
fn text_report_lists_offsets_and_residuals() {
    let out = run(&["calibrate", EXAMPLE], "");
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("left_knee_joint"), "{text}");
    assert!(text.contains("observability: full rank"), "{text}");
    assert!(text.contains("pose 3: rms"), "{text}");
}

#[test]
fn bad_file_is_one_located_error_line() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"));
    let path = dir.join("cli_calibrate_bad.json");
    let good = std::fs::read_to_string(EXAMPLE).unwrap();
    let good = good.replace(
        "../../dynamics",
        concat!(env!("CARGO_MANIFEST_DIR"), "/crates/dynamics"),
    );
    std::fs::write(&path, good.replacen("\"left_knee_joint\"", "\"knee\"", 1)).unwrap();
    let out = run(&["calibrate", path.to_str().unwrap()], "");
    assert_ne!(out.status.code(), Some(0));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("cli_calibrate_bad.json:") && err.contains("joints[3]"),
        "{err}"
    );
    // Unobservable: calibrate an arm joint with the feet jig.
    std::fs::write(
        &path,
        good.replacen("\"left_knee_joint\"", "\"left_elbow_joint\"", 1),
    )
    .unwrap();
    let out = run(&["calibrate", path.to_str().unwrap(), "--json"], "");
    assert_ne!(out.status.code(), Some(0));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("unobservable") && err.contains("left_elbow_joint"),
        "{err}"
    );
}

#[test]
fn missing_file_is_an_error() {
    let out = run(&["calibrate", "/nonexistent/calib.json"], "");
    assert_ne!(out.status.code(), Some(0));
    assert!(String::from_utf8(out.stderr)
        .unwrap()
        .contains("/nonexistent/calib.json"));
}
