//! Model files with arrays of the wrong length, a byte-order mark, and corruptions of the
//! humanoid example: a located error or a model with finite values, never a silent change.

mod model_support;

use biped_ssv::format;
use biped_test_support::mutate;
use model_support::data_path;
use proptest::prelude::*;

/// A small valid file with every kind of fixed-length array: pair, point, line, triangle,
/// position and rpy.
const BASE: &str = r#"activation_distance = 0.05
bodies = ["b0", "b1"]
pairs = [["s0", "s1"]]

[[segment]]
name = "s0"
body = "b0"
ssvs = [
  { point = [0.0, 0.0, 0.0], radius = 0.1 },
  { line = [[0.0, 0.0, 0.0], [0.0, 0.0, 0.3]], radius = 0.05 },
]

[[segment]]
name = "s1"
body = "b1"
ssvs = [{ triangle = [[0.0, 0.0, 0.0], [0.1, 0.0, 0.0], [0.0, 0.1, 0.0]], radius = 0.02 }]

[pose.zero]
b0 = { position = [0.0, 0.0, 0.0] }
b1 = { position = [0.0, 0.2, 0.0], rpy = [0.1, 0.2, 0.3] }
"#;

/// `BASE` with the first `from` replaced by `to`: the error's line and message.
fn error_with(from: &str, to: &str) -> (usize, String) {
    assert!(BASE.contains(from), "{from}");
    let text = BASE.replacen(from, to, 1);
    let e = format::parse_str(&text, "bad.toml").expect_err(to);
    (e.line, e.to_string())
}

/// An extra entry in a fixed-length array is an error at its line (a pair of three names
/// used to drop the third silently, a point of four coordinates the fourth); so is a
/// missing one.
#[test]
fn arrays_of_the_wrong_length_are_located_errors() {
    let cases = [
        (
            r#"["s0", "s1"]"#,
            r#"["s0", "s1", "s2"]"#,
            3,
            "length 3, expected an array of length 2",
        ),
        (
            "[0.0, 0.0, 0.0], radius = 0.1",
            "[0.0, 0.0, 0.0, 0.5], radius = 0.1",
            9,
            "length 4",
        ),
        (
            "[0.0, 0.0, 0.3]]",
            "[0.0, 0.0, 0.3], [1.0, 0.0, 0.0]]",
            10,
            "length 3",
        ),
        (
            "[0.0, 0.1, 0.0]]",
            "[0.0, 0.1, 0.0], [0.0, 0.0, 1.0]]",
            16,
            "length 4",
        ),
        ("[0.0, 0.2, 0.0]", "[0.0, 0.2, 0.0, 9.0]", 20, "length 4"),
        (
            "[0.1, 0.2, 0.3]",
            "[0.1, 0.2, 0.3, 0.4, 0.5]",
            20,
            "length 5",
        ),
        (
            "[0.1, 0.2, 0.3]",
            "[0.1, 0.2]",
            20,
            "length 2, expected an array of length 3",
        ),
        (
            r#"["s0", "s1"]"#,
            r#"["s0"]"#,
            3,
            "length 1, expected an array of length 2",
        ),
    ];
    for (from, to, line, message) in cases {
        let (at, shown) = error_with(from, to);
        assert_eq!(at, line, "{to}: {shown}");
        assert!(shown.starts_with(&format!("bad.toml:{line}: ")), "{shown}");
        assert!(shown.contains(message), "{to}: {shown}");
    }
}

/// The file writer still writes what the reader takes back (fixed arrays as TOML arrays).
#[test]
fn written_files_read_back() {
    let loaded = format::parse_str(BASE, "base.toml").unwrap();
    let text = format::to_toml_string(&loaded.model, &loaded.poses).unwrap();
    let back = format::parse_str(&text, "written.toml").unwrap();
    assert_eq!(back.model.pairs(), loaded.model.pairs());
    assert_eq!(back.model.segments(), loaded.model.segments());
}

/// A UTF-8 byte-order mark before the first key is accepted.
#[test]
fn byte_order_mark_is_accepted() {
    let bom = format::parse_bytes(format!("\u{feff}{BASE}").as_bytes(), "bom.toml").unwrap();
    assert_eq!(bom, format::parse_str(BASE, "base.toml").unwrap());
}

/// Offsets of the `]` that close an array outside comments.
fn array_ends(text: &str) -> Vec<usize> {
    let mut ends = Vec::new();
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let code = line.split('#').next().unwrap_or("");
        ends.extend(code.match_indices(']').map(|(i, _)| offset + i));
        offset += line.len();
    }
    ends
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// An extra number inserted as the last entry of any array of the humanoid file makes it
    /// an error: no array of the format takes a number beyond its length (names, tables and
    /// indices reject it by type, points and pairs by length).
    #[test]
    fn an_extra_array_entry_is_never_ignored(at in any::<prop::sample::Index>()) {
        let good = std::fs::read_to_string(data_path("humanoid.toml")).unwrap();
        let ends = array_ends(&good);
        let end = ends[at.index(ends.len())];
        let text = format!("{}, 0.0{}", &good[..end], &good[end..]);
        prop_assert!(format::parse_str(&text, "extra.toml").is_err(), "accepted at {}", end);
    }

    /// Corruptions of the humanoid file (byte edits, TOML-structure edits, edge numbers,
    /// both): a located error, or a model whose distances and closest points at its first
    /// posture are finite (or whose update is a typed error).
    #[test]
    fn corrupted_humanoid_is_an_error_or_finite(c in mutate::corruptions(b"-9e.[]{},\"=\n#n", 6)) {
        let good = std::fs::read_to_string(data_path("humanoid.toml")).unwrap();
        let text = c.apply(&good);
        let mut loaded = match format::parse_str(&text, "bad.toml") {
            Err(e) => {
                let shown = e.to_string();
                prop_assert!(shown.starts_with("bad.toml:") && !shown.contains('\n'), "{}", shown);
                prop_assert!(e.line >= 1 && e.line <= mutate::line_count(text.as_bytes()), "{}", shown);
                return Ok(());
            }
            Ok(loaded) => loaded,
        };
        let poses = loaded.poses.values().next().cloned().unwrap_or_default();
        if loaded.model.update(&poses).is_ok() {
            for (_, d) in loaded.model.distances() {
                let finite = d.computed().is_none_or(|c| {
                    let r = &c.result;
                    r.distance.is_finite() && r.point_a.iter().chain(r.point_b.iter()).all(|x| x.is_finite())
                });
                prop_assert!(finite, "{:?}", d);
            }
        }
    }
}
