//! End-to-end tests of the `biped model`, `biped dynamics` and `biped bench dynamics` contract.

mod common;

use common::{answers, floats, json_lines, run};

use rand::{Rng, SeedableRng};
use serde_json::{json, Value};
use std::path::PathBuf;

/// The bundled G1 humanoid URDF.
fn g1() -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("crates/dynamics/data/g1_29dof_rev_1_0.urdf")
        .display()
        .to_string()
}

/// `biped model SOURCE --json`.
fn model_json(source: &[&str]) -> Value {
    let args: Vec<&str> = ["model"]
        .iter()
        .chain(source)
        .chain(&["--json"])
        .copied()
        .collect();
    let out = run(&args, "");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    json_lines(&out).remove(0)
}

#[test]
fn model_json_of_dill() {
    let m = model_json(&["--dill", "3"]);
    assert_eq!((m["nq"].as_u64(), m["nv"].as_u64()), (Some(8), Some(8)));
    let joints = m["joints"].as_array().unwrap();
    assert_eq!(joints.len(), 8);
    assert!(joints
        .iter()
        .all(|j| j["nq"] == 1 && j["nv"] == 1 && j["name"].is_string()));
    assert_eq!(m["bodies"].as_array().unwrap().len(), 8);
    assert_eq!(floats(&m["neutral"]), vec![0.0; 8]);
}

#[test]
fn model_json_of_floating_urdf_starts_with_root() {
    let m = model_json(&["--urdf", &g1(), "--floating"]);
    let joints = m["joints"].as_array().unwrap();
    assert_eq!(joints[0], json!({"name": "root", "nq": 7, "nv": 6}));
    let nq: u64 = joints.iter().map(|j| j["nq"].as_u64().unwrap()).sum();
    let nv: u64 = joints.iter().map(|j| j["nv"].as_u64().unwrap()).sum();
    assert_eq!((m["nq"].as_u64(), m["nv"].as_u64()), (Some(nq), Some(nv)));
    let neutral = floats(&m["neutral"]);
    assert_eq!(neutral.len() as u64, nq);
    assert_eq!(&neutral[..7], &[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
    let fixed = model_json(&["--urdf", &g1()]);
    assert_eq!(fixed["nv"].as_u64(), Some(nv - 6));
}

#[test]
fn bad_urdf_is_one_located_error_line() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let path = dir.join("zero_axis.urdf");
    std::fs::write(
        &path,
        "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n\
         <joint name=\"j\" type=\"continuous\">\n<parent link=\"a\"/><child link=\"b\"/>\
         <axis xyz=\"0 0 0\"/></joint>\n</robot>\n",
    )
    .unwrap();
    let out = run(&["model", "--urdf", path.to_str().unwrap(), "--json"], "");
    assert!(!out.status.success());
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    let expected = format!("{}:4: joint \"j\"", path.display());
    assert!(err.contains(&expected) && err.contains("axis"), "{err}");
    let out = run(&["model", "--urdf", "/no/such/file.urdf"], "");
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("/no/such/file.urdf"));
}

/// Random states for a model described by `biped model --json`: (q, v, other nv-vector).
fn random_states(model: &Value, count: usize, seed: u64) -> Vec<(Vec<f64>, Vec<f64>, Vec<f64>)> {
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let nv = model["nv"].as_u64().unwrap() as usize;
    let mut uniform =
        |n: usize| -> Vec<f64> { (0..n).map(|_| rng.random_range(-1.0..1.0)).collect() };
    (0..count)
        .map(|_| {
            let mut q = Vec::new();
            for j in model["joints"].as_array().unwrap() {
                let mut part = uniform(j["nq"].as_u64().unwrap() as usize);
                if part.len() == 7 {
                    let norm = part[3..].iter().map(|x| x * x).sum::<f64>().sqrt();
                    part[3..].iter_mut().for_each(|x| *x /= norm);
                }
                q.extend(part);
            }
            (q, uniform(nv), uniform(nv))
        })
        .collect()
}

/// Runs `biped dynamics SOURCE EXTRA` over `requests`; every answer must carry `key`.
fn dynamics(source: &[&str], extra: &[&str], requests: &[Value], key: &str) -> Vec<Vec<f64>> {
    let args: Vec<&str> = ["dynamics"]
        .iter()
        .chain(source)
        .chain(extra)
        .copied()
        .collect();
    answers(&args, requests, key)
}

/// Largest |a - b| relative to max(1, |b|).
fn max_rel(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs() / y.abs().max(1.0))
        .fold(0.0, f64::max)
}

/// Forward dynamics of every algorithm, fed back to `--inverse`, returns the input torques.
fn round_trip(source: &[&str]) {
    let model = model_json(source);
    let states = random_states(&model, 5, 7);
    let fwd: Vec<Value> = states
        .iter()
        .map(|(q, v, tau)| json!({"q": q, "v": v, "tau": tau}))
        .collect();
    for algo in ["on", "crba", "sparse"] {
        let qdd = dynamics(source, &["--algorithm", algo], &fwd, "qdd");
        let inv: Vec<Value> = states
            .iter()
            .zip(&qdd)
            .map(|((q, v, _), a)| json!({"q": q, "v": v, "a": a}))
            .collect();
        let tau = dynamics(source, &["--inverse"], &inv, "tau");
        for ((_, _, tau_in), tau_out) in states.iter().zip(&tau) {
            let err = max_rel(tau_out, tau_in);
            assert!(err < 1e-8, "{source:?} {algo}: round-trip error {err}");
        }
    }
}

#[test]
fn forward_then_inverse_round_trips_on_dill() {
    round_trip(&["--dill", "4"]);
}

#[test]
fn forward_then_inverse_round_trips_on_floating_humanoid() {
    round_trip(&["--urdf", &g1(), "--floating"]);
}

#[test]
fn mass_matrix_is_the_linear_part_of_inverse_dynamics() {
    let path = g1();
    let source = ["--urdf", path.as_str(), "--floating"];
    let model = model_json(&source);
    let states = random_states(&model, 3, 11);
    let mm: Vec<Value> = states.iter().map(|(q, _, _)| json!({"q": q})).collect();
    let out = run(
        &["dynamics", source[0], source[1], source[2], "--mass-matrix"],
        &mm.iter().map(|r| format!("{r}\n")).collect::<String>(),
    );
    assert!(out.status.success());
    let matrices = json_lines(&out);
    for ((q, v, a), m) in states.iter().zip(&matrices) {
        let rows: Vec<Vec<f64>> = m["M"].as_array().unwrap().iter().map(floats).collect();
        let n = a.len();
        assert_eq!(rows.len(), n);
        for (i, row) in rows.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                assert!((x - rows[j][i]).abs() <= 1e-12 * row[i].abs().max(1.0));
            }
        }
        let zero = vec![0.0; n];
        let req = [
            json!({"q": q, "v": v, "a": a}),
            json!({"q": q, "v": v, "a": zero}),
        ];
        let tau = dynamics(&source, &["--inverse"], &req, "tau");
        let m_a: Vec<f64> = rows
            .iter()
            .map(|r| r.iter().zip(a).map(|(x, y)| x * y).sum())
            .collect();
        let diff: Vec<f64> = tau[0].iter().zip(&tau[1]).map(|(x, y)| x - y).collect();
        assert!(max_rel(&diff, &m_a) < 1e-9, "M a != tau(a) - tau(0)");
    }
}

#[test]
fn bad_lines_get_located_errors_and_processing_goes_on() {
    let good = json!({"q": [0.1, 0.2], "v": [0.0, 1.0], "tau": [0.0, 0.0]}).to_string();
    let input = format!(
        "{good}\nnot json\n{}\n\n{}\n{}\n{good}\n",
        json!({"q": [0.1], "v": [0.0, 1.0], "tau": [0.0, 0.0]}),
        json!({"q": [0.1, 0.2], "v": [0.0, 1.0]}),
        r#"{"q": [0.1, 0.2], "v": [0.0, 1e999], "tau": [0.0, 0.0]}"#,
    );
    let out = run(&["dynamics", "--dill", "1"], &input);
    assert_eq!(out.status.code(), Some(1));
    let lines = json_lines(&out);
    assert_eq!(
        lines.len(),
        6,
        "blank lines are skipped, every other line answered"
    );
    assert!(lines[0]["qdd"].is_array() && lines[5]["qdd"].is_array());
    let errors: Vec<&str> = lines[1..5]
        .iter()
        .map(|l| l["error"].as_str().unwrap())
        .collect();
    assert!(errors[0].starts_with("line 2:"), "{}", errors[0]);
    assert!(
        errors[1].starts_with("line 3:") && errors[1].contains("\"q\""),
        "{}",
        errors[1]
    );
    assert!(
        errors[2].starts_with("line 5:") && errors[2].contains("tau"),
        "{}",
        errors[2]
    );
    assert!(errors[3].starts_with("line 6:"), "{}", errors[3]);
    let ok = run(&["dynamics", "--dill", "1"], &format!("{good}\n"));
    assert_eq!(ok.status.code(), Some(0));
}

#[test]
fn bench_json_shapes_and_plot() {
    let out = run(&["bench", "dynamics", "--dill", "2", "--json"], "");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let t = json_lines(&out).remove(0);
    for key in ["on", "crba", "sparse"] {
        assert!(t[key].as_f64().unwrap() > 0.0, "{key}");
    }
    let out = run(&["bench", "dynamics", "--dill-range", "1..2", "--json"], "");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rows = json_lines(&out).remove(0);
    let rows = rows.as_array().unwrap();
    assert_eq!(rows.len(), 2);
    assert_eq!(
        (rows[0]["n"].as_u64(), rows[1]["n"].as_u64()),
        (Some(1), Some(2))
    );
    let svg = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("out/dill_fd_runtime_1-2.svg");
    assert!(std::fs::read_to_string(svg).unwrap().contains("<svg"));
    assert!(String::from_utf8_lossy(&out.stderr).contains("out/dill_fd_runtime_1-2.svg"));
}

#[test]
fn mimic_warns_by_default_and_reject_mimic_fails() {
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("mimic.urdf");
    std::fs::write(
        &path,
        "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"><inertial><mass value=\"1\"/>\
         <inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>\n\
         <joint name=\"j\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/>\
         <mimic joint=\"k\"/></joint>\n</robot>\n",
    )
    .unwrap();
    let file = path.to_str().unwrap();
    let out = run(&["model", "--urdf", file, "--json"], "");
    assert!(out.status.success());
    let err = String::from_utf8(out.stderr.clone()).unwrap();
    assert!(
        err.starts_with("warning:") && err.contains("joint \"j\""),
        "{err}"
    );
    assert_eq!(json_lines(&out).remove(0)["nv"].as_u64(), Some(1));
    let out = run(&["model", "--urdf", file, "--reject-mimic", "--json"], "");
    assert!(!out.status.success());
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains(&format!("{file}:4: joint \"j\": mimic")),
        "{err}"
    );
}

mod jsonl;

/// Valid requests for Dill(1) (two revolute bodies) in each mode.
fn requests() -> [(&'static str, String); 3] {
    [
        (
            "qdd",
            json!({"q": [0.1, 0.2], "v": [0.0, 1.0], "tau": [0.5, -0.5]}).to_string(),
        ),
        (
            "tau",
            json!({"q": [0.1, 0.2], "v": [0.0, 1.0], "a": [0.5, -0.5]}).to_string(),
        ),
        ("M", json!({"q": [0.1, 0.2]}).to_string()),
    ]
}

/// The arguments of `biped dynamics` for Dill(1) in the mode answering with `key`.
fn mode_args(key: &str) -> Vec<&'static str> {
    let mode = match key {
        "qdd" => None,
        "tau" => Some("--inverse"),
        _ => Some("--mass-matrix"),
    };
    ["dynamics", "--dill", "1"]
        .into_iter()
        .chain(mode)
        .collect()
}

/// A UTF-8 byte-order mark before the first request is ignored (it was a JSON syntax error).
#[test]
fn byte_order_mark_is_ignored() {
    for (key, request) in requests() {
        let out = run(&mode_args(key), &format!("\u{feff}{request}\n{request}\n"));
        assert_eq!(out.status.code(), Some(0), "{key}");
        let lines = json_lines(&out);
        assert_eq!(lines[0], lines[1], "{key}");
    }
}

/// Characters of JSON structure and numbers, for the corruptions below.
const JSON_ALPHABET: &[u8] = b"{}[],:\"-+.eE09 \nqvta";

/// One corrupted request: text corruptions (byte edits read back as UTF-8, structural
/// edits, edge numbers) or raw byte edits that may leave invalid UTF-8.
fn corrupted(request: String) -> impl proptest::strategy::Strategy<Value = Vec<u8>> {
    use biped_test_support::mutate;
    use proptest::prelude::*;
    let bytes = request.clone().into_bytes();
    prop_oneof![
        mutate::corruptions(JSON_ALPHABET, 4).prop_map(move |c| c.apply(&request).into_bytes()),
        mutate::byte_edits(3).prop_map(move |e| mutate::apply(&bytes, &e)),
    ]
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(100))]

    /// For each mode, batches of 1 to 30 corrupted requests (100 runs per mode, about 1 500
    /// lines each): every non-blank line gets one answer with finite numbers or one error
    /// naming it, in order, and the exit code says whether any line was bad.
    #[test]
    fn corrupted_requests_get_one_finite_answer_or_error_each(
        batches in requests().map(|(_, r)| proptest::collection::vec(corrupted(r), 1..30)),
    ) {
        for ((key, _), batch) in requests().iter().zip(batches) {
            let input: Vec<u8> = batch.iter().flat_map(|q| q.iter().chain(b"\n")).copied().collect();
            let out = common::run_bytes(&mode_args(key), &input);
            let checked = jsonl::check_answers(&input, &out, key);
            proptest::prop_assert!(checked.is_ok(), "{}: {:?}", key, checked);
        }
    }
}

/// 20 000 nested elements in a URDF: one located error line and exit code 1 (the process
/// used to abort on a stack overflow).
#[test]
fn deeply_nested_urdf_is_one_error_line() {
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("deep.urdf");
    let depth = 20_000;
    let xml = format!(
        "<robot name=\"deep\">\n<link name=\"a\">\n{}{}</link>\n</robot>\n",
        "<x>".repeat(depth),
        "</x>".repeat(depth)
    );
    std::fs::write(&path, xml).unwrap();
    let out = run(&["model", "--urdf", path.to_str().unwrap(), "--json"], "");
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    let expected = format!("{}:3: elements nested deeper than", path.display());
    assert!(err.contains(&expected), "{err}");
}
