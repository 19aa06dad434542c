//! End-to-end tests of the `biped ssv` command-line contract.

mod common;

use common::{json_lines, run};

/// Run `biped ssv query` with `input` on stdin; return (exit code, output lines).
fn query(input: &str) -> (i32, Vec<serde_json::Value>) {
    let out = run(&["ssv", "query"], input);
    (out.status.code().expect("exit code"), json_lines(&out))
}

fn vec3(v: &serde_json::Value) -> [f64; 3] {
    let a = v.as_array().expect("array of 3");
    [0, 1, 2].map(|i| a[i].as_f64().expect("number"))
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()))
}

#[test]
fn point_point_by_hand() {
    // Centres 5 apart along x, radii 1 and 1.5: d = 5 - 2.5, surface points at x = 1 and x = 3.5.
    let (code, out) =
        query(r#"{"a": {"point": [0,0,0], "radius": 1}, "b": {"point": [5,0,0], "radius": 1.5}}"#);
    assert_eq!(code, 0);
    assert!(close(out[0]["distance"].as_f64().unwrap(), 2.5));
    assert_eq!(vec3(&out[0]["point_a"]), [1.0, 0.0, 0.0]);
    assert_eq!(vec3(&out[0]["point_b"]), [3.5, 0.0, 0.0]);
}

#[test]
fn line_triangle_and_overlap_by_hand() {
    // Segment above a triangle in the plane z = 0, parallel at height 2; radii 0.5 each -> d = 1.
    // Two crossing capsules of radius 1: primitives intersect, d = -2.
    let input = concat!(
        r#"{"a": {"line": [[0.1,0.1,2],[0.2,0.1,2]], "radius": 0.5}, "b": {"triangle": [[0,0,0],[1,0,0],[0,1,0]], "radius": 0.5}}"#,
        "\n",
        r#"{"a": {"line": [[-1,0,0],[1,0,0]], "radius": 1}, "b": {"line": [[0,-1,0],[0,1,0]], "radius": 1}}"#,
        "\n"
    );
    let (code, out) = query(input);
    assert_eq!(code, 0);
    assert_eq!(out.len(), 2);
    assert!(close(out[0]["distance"].as_f64().unwrap(), 1.0));
    assert!(close(vec3(&out[0]["point_a"])[2], 1.5));
    assert!(close(vec3(&out[0]["point_b"])[2], 0.5));
    assert!(close(out[1]["distance"].as_f64().unwrap(), -2.0));
}

#[test]
fn bad_lines_get_errors_and_exit_1_but_processing_goes_on() {
    let input = concat!(
        "not json\n",
        r#"{"a": {"point": [0,0,0], "radius": -1}, "b": {"point": [1,0,0], "radius": 0}}"#,
        "\n",
        r#"{"a": {"point": [0,0,0], "line": [[0,0,0],[1,1,1]], "radius": 1}, "b": {"point": [1,0,0], "radius": 0}}"#,
        "\n",
        r#"{"a": {"point": [0,0,0], "radius": 0}, "b": {"point": [3,4,0], "radius": 0}}"#,
        "\n"
    );
    let (code, out) = query(input);
    assert_eq!(code, 1);
    assert_eq!(out.len(), 4);
    for (i, line) in out.iter().take(3).enumerate() {
        let msg = line["error"].as_str().expect("error line");
        assert!(msg.starts_with(&format!("line {}", i + 1)), "{msg}");
    }
    assert!(out[1]["error"].as_str().unwrap().contains("radius"));
    assert!(close(out[3]["distance"].as_f64().unwrap(), 5.0));
}

#[test]
fn bench_json_has_the_six_functions() {
    let out = run(&["ssv", "bench", "--json"], "");
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    for key in ["PP", "PL", "PT", "LL", "LT", "TT"] {
        assert!(v[key].as_f64().expect("ns") > 0.0, "{key}");
    }
}

/// `biped ssv model` on the bundled humanoid: the JSON report agrees with the library.
#[test]
fn model_report_matches_library() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/crates/ssv/data/humanoid.toml");
    let out = run(&["ssv", "model", file, "--pose", "standing", "--json"], "");
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let mut loaded = biped_ssv::format::load(file).expect("bundled model loads");
    let poses = loaded.poses["standing"].clone();
    loaded.model.update(&poses).expect("poses fit");
    let pairs = v["pairs"].as_array().expect("pairs");
    assert_eq!(pairs.len(), loaded.model.pairs().len());
    for (row, (_, result)) in pairs.iter().zip(loaded.model.distances()) {
        assert_eq!(row["distance"].as_f64(), result.distance());
    }
}

/// A bad model file gives one error line naming the file and line, and a non-zero exit.
#[test]
fn model_bad_file_names_file_and_line() {
    let dir = std::env::temp_dir().join(format!("biped-cli-ssv-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad.toml");
    std::fs::write(
        &path,
        "activation_distance = 0.05\nbodies = [\"a\"]\nx = \n",
    )
    .unwrap();
    let out = run(&["ssv", "model", path.to_str().unwrap()], "");
    assert!(!out.status.success());
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("bad.toml:3"), "{err}");
}
