//! Errors of the Lola parameter file name the file, the line and the field; random and
//! edge-value edits of the shipped file never panic.

use biped_robots::lola::{self, LolaError, LolaType, LOLA_TOML};
use biped_test_support::mutate;

fn build(text: &str) -> Result<lola::LolaModel, LolaError> {
    lola::build_from_str(text, "test.toml", LolaType::Type2)
}

/// 1-based line of the first occurrence of `needle` in the shipped file.
fn line_of(text: &str, needle: &str) -> usize {
    text[..text.find(needle).expect(needle)]
        .matches('\n')
        .count()
        + 1
}

/// 1-based line of the `name` of the body table holding the first `needle`.
fn body_line(text: &str, needle: &str) -> usize {
    let at = text.find(needle).expect(needle);
    let name = text[..at].rfind("name = ").expect("a body name before it");
    text[..name].matches('\n').count() + 1
}

#[test]
fn shipped_file_builds_both_types() {
    for t in [LolaType::Type2, LolaType::Type3] {
        let lm = lola::build(t).unwrap();
        assert_eq!(lm.limits.len(), 25);
    }
}

#[test]
fn unknown_field_names_line_and_field() {
    let text = LOLA_TOML.replacen("ratio = 160.0", "ratoi = 160.0", 1);
    let line = line_of(&text, "ratoi");
    match build(&text) {
        Err(LolaError::Parse {
            file,
            line: l,
            message,
            ..
        }) => {
            assert_eq!(file, "test.toml");
            assert_eq!(l, line);
            assert!(message.contains("ratoi"), "{message}");
        }
        other => panic!("expected a parse error, got {other:?}"),
    }
}

#[test]
fn wrong_type_names_line() {
    let text = LOLA_TOML.replacen("mass = 7.0", "mass = \"heavy\"", 1);
    let line = line_of(&text, "\"heavy\"");
    let e = build(&text).unwrap_err();
    assert!(
        matches!(e, LolaError::Parse { line: l, .. } if l == line),
        "{e}"
    );
    assert!(
        e.to_string().starts_with(&format!("test.toml:{line}:")),
        "{e}"
    );
}

#[test]
fn unknown_parent_and_bad_axis_name_the_field() {
    let text = LOLA_TOML.replacen("parent = \"l_thigh\"", "parent = \"l_thig\"", 1);
    let line = line_of(&text, "l_thig\"");
    let e = build(&text).unwrap_err();
    assert!(
        matches!(&e, LolaError::Invalid { field: "parent", line: l, .. } if *l == line),
        "{e}"
    );
    let text = LOLA_TOML.replacen("axis = \"x\"", "axis = \"w\"", 1);
    let line = line_of(&text, "\"w\"");
    let e = build(&text).unwrap_err();
    assert!(
        matches!(&e, LolaError::Invalid { field: "axis", line: l, .. } if *l == line),
        "{e}"
    );
}

#[test]
fn bad_values_are_errors_not_panics() {
    let knee_range = LOLA_TOML.replacen("limits = [0.0, 1.9]", "limits = [0.0, 3.1]", 1);
    let knee_line = body_line(&knee_range, "limits = [0.0, 3.1]");
    let e = build(&knee_range).unwrap_err();
    assert!(
        matches!(&e, LolaError::Mechanism { file, line, .. } if file == "test.toml" && *line == knee_line),
        "{e}"
    );
    let inverted = LOLA_TOML.replacen("limits = [-0.6, 0.6]", "limits = [0.6, -0.6]", 1);
    assert!(matches!(
        build(&inverted),
        Err(LolaError::Invalid {
            field: "limits",
            ..
        })
    ));
    let negative = LOLA_TOML.replacen("mass = 7.0", "mass = -7.0", 1);
    let mass_line = body_line(&negative, "mass = -7.0");
    let e = build(&negative).unwrap_err();
    assert!(
        matches!(&e, LolaError::Model { file, line, .. } if file == "test.toml" && *line == mass_line),
        "{e}"
    );
    let missing = std::path::Path::new("/nonexistent/lola.toml");
    assert!(matches!(
        lola::load_file(missing, LolaType::Type3),
        Err(LolaError::Io { .. })
    ));
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(150))]

    /// Random edits of the shipped parameter file never panic: a located error (file and a
    /// line inside it), or a model whose dynamics at its neutral configuration are finite or
    /// a typed error.
    #[test]
    fn mutated_parameter_file_never_panics(c in mutate::corruptions(b"-9e.0[]\"=\n#", 4)) {
        let text = c.apply(LOLA_TOML);
        match build(&text) {
            Err(e) => {
                let msg = e.to_string();
                proptest::prop_assert!(msg.starts_with("test.toml") && !msg.contains('\n'), "{msg}");
            }
            Ok(lm) => {
                let m = &lm.model;
                let mut data = biped_dynamics::Data::new(m);
                let zero = nalgebra::DVector::zeros(m.nv());
                let on = biped_dynamics::Algorithm::On;
                let r = biped_dynamics::forward_dynamics(m, &mut data, &m.neutral(), &zero, &zero, None, on);
                if let Ok(ddq) = r {
                    proptest::prop_assert!(ddq.iter().all(|x| x.is_finite()), "{ddq:?}");
                }
            }
        }
    }
}
