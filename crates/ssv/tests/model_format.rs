//! Model files: the documented example, the humanoid example, round trips, located errors
//! for every kind of bad input, and robustness against random byte mutations.

mod model_support;

use biped_ssv::format::{self, FormatErrorKind};
use biped_ssv::segment::MirrorPlane;
use biped_ssv::{FormatError, Ssv};
use biped_test_support::mutate;
use model_support::data_path;
use proptest::prelude::*;

/// The TOML example from the module documentation of `src/format/mod.rs`.
fn doc_example() -> String {
    let src = include_str!("../src/format/mod.rs");
    let mut out = String::new();
    let mut inside = false;
    for line in src.lines() {
        let Some(doc) = line.strip_prefix("//!") else {
            continue;
        };
        let doc = doc.strip_prefix(' ').unwrap_or(doc);
        match (inside, doc.trim()) {
            (false, "```toml") => inside = true,
            (true, "```") => break,
            (true, _) => {
                out.push_str(doc);
                out.push('\n');
            }
            _ => {}
        }
    }
    assert!(out.len() > 200, "example not found");
    out
}

#[test]
fn documented_example_loads() {
    let loaded = format::parse_str(&doc_example(), "doc-example.toml").unwrap();
    let m = &loaded.model;
    assert_eq!(m.bodies().len(), 4);
    assert_eq!(m.segments().len(), 6);
    assert_eq!(m.pairs().len(), 3);
    assert_eq!(m.activation_distance(), 0.05);
    let seg = |n: &str| &m.segments()[m.segment_index(n).unwrap()];
    // mirror_copy expands the list: 2 entries -> 3 SSVs.
    let thigh = seg("thigh_r");
    assert_eq!(thigh.len(), 3);
    assert_eq!(
        thigh.ssvs()[2],
        MirrorPlane::Xz.reflect_ssv(&thigh.ssvs()[1])
    );
    // Versions keep the listed SSVs, mirrors reflect every vertex (y negated).
    assert_eq!(
        seg("thigh_r_inner").ssvs(),
        &[thigh.ssvs()[0], thigh.ssvs()[1]]
    );
    assert_eq!(
        seg("thigh_r_outer").ssvs(),
        &[thigh.ssvs()[0], thigh.ssvs()[2]]
    );
    for (l, r) in seg("thigh_l_inner")
        .ssvs()
        .iter()
        .zip(seg("thigh_r_inner").ssvs())
    {
        assert_eq!(l.radius(), r.radius());
        for (p, q) in l.vertices().iter().zip(r.vertices()) {
            assert_eq!([p.x, p.y, p.z], [q.x, -q.y, q.z]);
        }
    }
    let body = m.segment_bodies()[m.segment_index("thigh_l_inner").unwrap()];
    assert_eq!(m.bodies()[body], "thigh_l");
    let standing = &loaded.poses["standing"];
    assert_eq!(standing.len(), 4);
    assert_eq!(standing[3].translation.vector.y, -0.25);
    let (roll, pitch, yaw) = standing[3].rotation.euler_angles();
    assert!((roll - 0.1).abs() < 1e-15 && pitch.abs() < 1e-15 && yaw.abs() < 1e-15);
}

#[test]
fn humanoid_model_meets_size_requirements() {
    let loaded = format::load(data_path("humanoid.toml")).unwrap();
    let m = &loaded.model;
    assert!(m.segments().len() >= 15, "{} segments", m.segments().len());
    assert!(m.ssv_count() >= 100, "{} SSVs", m.ssv_count());
    assert!(m.pairs().len() >= 40, "{} pairs", m.pairs().len());
    for posture in ["standing", "arms_close"] {
        assert_eq!(loaded.poses[posture].len(), m.bodies().len());
    }
    // Left segments are exact mirror images of the right ones.
    for side in ["upper_arm", "forearm", "hand", "thigh", "shank", "foot"] {
        let r = &m.segments()[m.segment_index(&format!("{side}_r")).unwrap()];
        let l = &m.segments()[m.segment_index(&format!("{side}_l")).unwrap()];
        let mirrored: Vec<Ssv> = r
            .ssvs()
            .iter()
            .map(|s| MirrorPlane::Xz.reflect_ssv(s))
            .collect();
        assert_eq!(l.ssvs(), mirrored.as_slice());
    }
}

#[test]
fn round_trip_preserves_model_and_poses() {
    let loaded = format::load(data_path("humanoid.toml")).unwrap();
    let text = format::to_toml_string(&loaded.model, &loaded.poses).unwrap();
    let back = format::parse_str(&text, "round-trip.toml").unwrap();
    let (a, b) = (&loaded.model, &back.model);
    assert_eq!(a.bodies(), b.bodies());
    assert_eq!(a.pairs(), b.pairs());
    assert_eq!(a.segment_bodies(), b.segment_bodies());
    assert_eq!(a.activation_distance(), b.activation_distance());
    for (x, y) in a.segments().iter().zip(b.segments()) {
        assert_eq!(x.name(), y.name());
        assert_eq!(x.ssvs(), y.ssvs(), "segment {}", x.name());
    }
    assert_eq!(
        loaded.poses.keys().collect::<Vec<_>>(),
        back.poses.keys().collect::<Vec<_>>()
    );
    for (name, poses) in &loaded.poses {
        for (p, q) in poses.iter().zip(&back.poses[name]) {
            assert!((p.translation.vector - q.translation.vector).norm() == 0.0);
            assert!(p.rotation.angle_to(&q.rotation) < 1e-12, "pose {name}");
        }
    }
    // A second round trip is textually stable.
    let again = format::to_toml_string(&back.model, &back.poses).unwrap();
    let third = format::parse_str(&again, "again.toml").unwrap();
    for (x, y) in b.segments().iter().zip(third.model.segments()) {
        assert_eq!(x.ssvs(), y.ssvs());
    }
}

#[test]
fn save_and_load_file() {
    let loaded = format::parse_str(&doc_example(), "doc-example.toml").unwrap();
    let dir = std::env::temp_dir().join(format!("biped_ssv_model_format_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("model.toml");
    format::save(&path, &loaded.model, &loaded.poses).unwrap();
    let back = format::load(&path).unwrap();
    assert_eq!(back.model.pairs(), loaded.model.pairs());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A small valid file; each bad-file test replaces one line of it.
const BASE: &str = r#"activation_distance = 0.05
bodies = ["b0", "b1"]
pairs = [["s0", "s1"], ["s0", "s2"]]

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
mirror_of = "s0"
plane = "xz"

[[segment]]
name = "s2"
body = "b1"
version_of = "s0"
keep = [1]

[pose.zero]
b0 = { position = [0.0, 0.0, 0.0] }
b1 = { position = [0.0, 0.2, 0.0], rpy = [0.1, 0.2, 0.3] }
"#;

/// Replaces 1-based line `n` of `BASE`.
fn with_line(n: usize, text: &str) -> String {
    let mut lines: Vec<&str> = BASE.lines().collect();
    lines[n - 1] = text;
    lines.join("\n") + "\n"
}

/// Parses `BASE` with line `n` replaced and checks file, line and field of the error.
fn bad(n: usize, text: &str, field: &str) -> FormatError {
    bad_at(n, text, n, field)
}

/// Like [`bad`], for an error expected on line `line` rather than the replaced one.
fn bad_at(replaced: usize, text: &str, n: usize, field: &str) -> FormatError {
    let src = with_line(replaced, text);
    let err = format::parse_str(&src, "bad.toml").expect_err(text);
    let shown = err.to_string();
    assert_eq!(err.file, "bad.toml");
    assert_eq!(err.line, n, "line of `{text}`: {shown}");
    assert!(
        err.field.contains(field),
        "field `{}` lacks `{field}`: {shown}",
        err.field
    );
    assert!(shown.starts_with(&format!("bad.toml:{n}: ")), "{shown}");
    err
}

#[test]
fn base_file_is_valid() {
    let loaded = format::parse_str(BASE, "base.toml").unwrap();
    assert_eq!(loaded.model.segments().len(), 3);
}

#[test]
fn syntax_and_type_errors_are_located() {
    bad(1, "activation_distance = ", "activation_distance");
    bad(1, "activation_distance = \"far\"", "activation_distance");
    bad(
        9,
        "  { point = [0.0, 0.0, 0.0], radius = \"big\" },",
        "radius",
    );
    bad(9, "  { point = [0.0, 0.0], radius = 0.1 },", "point");
    bad(9, "  { point = [0.0, 0.0, 0.0] },", "radius");
    bad(7, "colour = \"red\"", "colour");
    bad(
        26,
        "b0 = { position = [0.0, 0.0, 0.0], scale = 2 }",
        "scale",
    );
}

#[test]
fn semantic_errors_are_located() {
    let e = bad(
        9,
        "  { point = [0.0, 0.0, 0.0], radius = -0.1 },",
        "segment[0].ssvs[0].radius",
    );
    assert!(matches!(e.kind, FormatErrorKind::Ssv(_)));
    let e = bad(
        10,
        "  { line = [[0.0, nan, 0.0], [0.0, 0.0, 0.3]], radius = 0.05 },",
        "segment[0].ssvs[1].line",
    );
    assert!(matches!(e.kind, FormatErrorKind::Ssv(_)));
    bad(
        9,
        "  { point = [0.0, 0.0, inf], radius = 0.1 },",
        "segment[0].ssvs[0].point",
    );
    bad(
        9,
        "  { point = [0.0, 0.0, 0.0], radius = inf },",
        "segment[0].ssvs[0].radius",
    );
    let e = bad(3, r#"pairs = [["s0", "s1"], ["s0", "s9"]]"#, "pairs[1][1]");
    assert_eq!(e.kind, FormatErrorKind::UnknownSegment("s9".into()));
    bad(3, r#"pairs = [["s0", "s1"], ["s2", "s2"]]"#, "pairs[1]");
    let e = bad(7, r#"body = "b7""#, "segment[0].body");
    assert_eq!(e.kind, FormatErrorKind::UnknownBody("b7".into()));
    bad(16, r#"mirror_of = "s2""#, "segment[1].mirror_of");
    let e = bad(17, r#"plane = "xw""#, "segment[1].plane");
    assert!(matches!(e.kind, FormatErrorKind::Plane(_)));
    bad(23, "keep = [1, 2]", "segment[2].keep");
    bad(23, "keep = [-1]", "segment[2].keep[0]");
    bad(23, "keep = []", "segment[2].keep");
    bad(1, "activation_distance = -0.05", "activation_distance");
    bad(1, "activation_distance = nan", "activation_distance");
    let e = bad(14, r#"name = "s0""#, "segment[1].name");
    assert!(matches!(e.kind, FormatErrorKind::Model(_)));
    bad(2, r#"bodies = ["b0", "b0"]"#, "bodies");
    let e = bad(
        9,
        "  { point = [0.0, 0.0, 0.0], line = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]], radius = 0.1 },",
        "segment[0].ssvs[0]",
    );
    assert_eq!(e.kind, FormatErrorKind::SsvShape);
    let e = bad(
        17,
        r#"ssvs = [{ point = [0.0, 0.0, 0.0], radius = 0.1 }]"#,
        "segment[1].ssvs",
    );
    assert_eq!(e.kind, FormatErrorKind::SegmentSource);
    let e = bad_at(
        16,
        r#"ssvs = [{ point = [0.0, 0.0, 0.0], radius = 0.1 }]"#,
        17,
        "segment[1].plane",
    );
    assert_eq!(e.kind, FormatErrorKind::Unexpected("plane", "mirror_of"));
    // No geometry source at all: reported at the segment's header.
    let e = bad_at(16, "", 13, "segment[1]");
    assert_eq!(e.kind, FormatErrorKind::SegmentSource);
    bad(
        9,
        r#"  { point = [0.0, 0.0, 0.0], radius = 0.1, mirror_copy = "ab" },"#,
        "segment[0].ssvs[0].mirror_copy",
    );
    bad(27, "b7 = { position = [0.0, 0.2, 0.0] }", "pose.zero.b7");
    bad(
        27,
        "b1 = { position = [0.0, 0.2, nan] }",
        "pose.zero.b1.position",
    );
    // A posture without some body is reported at its table header.
    let e = bad_at(27, "", 25, "pose.zero");
    assert_eq!(e.kind, FormatErrorKind::PoseLacksBody("b1".into()));
}

#[test]
fn missing_companion_keys_are_located() {
    let src = BASE.replace("plane = \"xz\"\n", "");
    let err = format::parse_str(&src, "bad.toml").unwrap_err();
    assert_eq!((err.line, err.field.as_str()), (16, "segment[1].plane"));
    let src = BASE.replace("keep = [1]\n", "");
    let err = format::parse_str(&src, "bad.toml").unwrap_err();
    assert_eq!((err.line, err.field.as_str()), (22, "segment[2].keep"));
}

#[test]
fn io_and_encoding_errors_name_the_file() {
    let err = format::load("/nonexistent/biped/model.toml").unwrap_err();
    assert!(matches!(err.kind, FormatErrorKind::Io(_)));
    assert!(err
        .to_string()
        .starts_with("/nonexistent/biped/model.toml: "));
    let mut bytes = BASE.as_bytes().to_vec();
    let at = BASE.find("name = \"s1\"").unwrap();
    bytes[at] = 0xff;
    let err = format::parse_bytes(&bytes, "latin.toml").unwrap_err();
    assert_eq!((err.kind, err.line), (FormatErrorKind::NotUtf8, 14));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    /// Random byte edits (replace, insert, delete) of the humanoid file never panic; every
    /// error carries the file name and a line inside the file.
    #[test]
    fn random_mutations_never_panic(edits in mutate::byte_edits(7)) {
        let bytes = mutate::apply(&std::fs::read(data_path("humanoid.toml")).unwrap(), &edits);
        let lines = 1 + mutate::line_count(&bytes);
        if let Err(e) = format::parse_bytes(&bytes, "mutated.toml") {
            prop_assert_eq!(e.file.as_str(), "mutated.toml");
            prop_assert!(e.line >= 1 && e.line <= lines, "{}", e);
        }
    }

    /// Numbers replaced by edge values (zero, +-1e308, subnormal, negative): a located
    /// error, or a model whose distances and closest points at the file's first posture are
    /// finite (or whose update is a typed error).
    #[test]
    fn edge_numbers_never_panic_or_give_nan(edits in mutate::number_edits(3)) {
        let good = std::fs::read_to_string(data_path("humanoid.toml")).unwrap();
        let text = mutate::apply_numbers(&good, &edits);
        let Ok(mut loaded) = format::parse_str(&text, "edge.toml") else {
            return Ok(());
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

    /// Mutations biased to the characters that matter in TOML numbers and structure.
    #[test]
    fn structural_mutations_never_panic(edits in mutate::structural_edits(b"-9e.[]{},\"=\n#n", 5)) {
        let bytes = mutate::apply(&std::fs::read(data_path("humanoid.toml")).unwrap(), &edits);
        let _ = format::parse_bytes(&bytes, "mutated.toml");
    }
}
