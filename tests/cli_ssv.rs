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

mod jsonl;

/// Valid queries of the three shapes, the start of every corrupted query below.
const QUERIES: [&str; 3] = [
    r#"{"a": {"point": [0,0,0], "radius": 1}, "b": {"point": [5,0,0], "radius": 1.5}}"#,
    r#"{"a": {"line": [[0.1,0.1,2],[0.2,0.1,2]], "radius": 0.5}, "b": {"triangle": [[0,0,0],[1,0,0],[0,1,0]], "radius": 0.5}}"#,
    r#"{"a": {"triangle": [[0,0,1],[1,0,1],[0,1,1.5]], "radius": 0.1}, "b": {"triangle": [[0,0,0],[1,0,0],[0,1,0]], "radius": 0}}"#,
];

/// A line that is not UTF-8 is answered with an error for that line and the queries after
/// it are answered (`biped ssv query` used to stop there and drop them).
#[test]
fn non_utf8_line_is_an_error_and_the_rest_is_answered() {
    let input = [
        QUERIES[0].as_bytes(),
        b"\n\xff\xfe{}\n",
        QUERIES[1].as_bytes(),
        b"\n",
    ]
    .concat();
    let out = common::run_bytes(&["ssv", "query"], &input);
    assert_eq!(out.status.code(), Some(1));
    let lines = json_lines(&out);
    assert_eq!(lines.len(), 3);
    let msg = lines[1]["error"].as_str().unwrap();
    assert!(msg.starts_with("line 2: not UTF-8 text"), "{msg}");
    assert!(close(lines[0]["distance"].as_f64().unwrap(), 2.5));
    assert!(close(lines[2]["distance"].as_f64().unwrap(), 1.0));
}

/// A UTF-8 byte-order mark before the first query is ignored (it was a JSON syntax error).
#[test]
fn byte_order_mark_is_ignored() {
    let (code, out) = query(&format!("\u{feff}{}\n", QUERIES[0]));
    assert_eq!(code, 0, "{out:?}");
    assert!(close(out[0]["distance"].as_f64().unwrap(), 2.5));
}

/// Characters of JSON structure and numbers, for the corruptions below.
const JSON_ALPHABET: &[u8] = b"{}[],:\"-+.eE09 \nrpl";

/// One corrupted query: text corruptions (byte edits read back as UTF-8, structural edits,
/// edge numbers) or raw byte edits that may leave invalid UTF-8.
fn corrupted_query() -> impl proptest::strategy::Strategy<Value = Vec<u8>> {
    use biped_test_support::mutate;
    use proptest::prelude::*;
    let base = prop::sample::select(&QUERIES[..]);
    prop_oneof![
        (base.clone(), mutate::corruptions(JSON_ALPHABET, 4))
            .prop_map(|(q, c)| c.apply(q).into_bytes()),
        (base, mutate::byte_edits(3)).prop_map(|(q, e)| mutate::apply(q.as_bytes(), &e)),
    ]
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(150))]

    /// Batches of 1 to 40 corrupted queries (150 runs, about 3 000 lines): every non-blank
    /// line gets one answer with finite numbers or one error naming it, in order, and the
    /// exit code says whether any line was bad.
    #[test]
    fn corrupted_queries_get_one_finite_answer_or_error_each(
        batch in proptest::collection::vec(corrupted_query(), 1..40),
    ) {
        let input: Vec<u8> = batch.iter().flat_map(|q| q.iter().chain(b"\n")).copied().collect();
        let out = common::run_bytes(&["ssv", "query"], &input);
        let checked = jsonl::check_answers(&input, &out, "distance");
        proptest::prop_assert!(checked.is_ok(), "{:?}", checked);
    }
}
