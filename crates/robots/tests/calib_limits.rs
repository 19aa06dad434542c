//! Calibration inputs outside their physical ranges, repeated names and extreme weights: a
//! located error (file, line, field) or a correct, finite result, never a finite-looking
//! report of overflowed numbers.

mod calib_support;

use biped_robots::calibration::{
    calibrate, CalibrationError, CalibrationProblem, Components, JigConstraint, LoadedFile,
    SolveOptions,
};
use biped_test_support::mutate;
use calib_support::*;
use proptest::prelude::*;
use proptest::sample::Index;

const EXAMPLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/calibration_example.json");

/// The example file with its URDF path made absolute (so a copy can live anywhere).
fn example() -> String {
    std::fs::read_to_string(EXAMPLE).unwrap().replace(
        "../../dynamics",
        concat!(env!("CARGO_MANIFEST_DIR"), "/../dynamics"),
    )
}

/// Parses, loads and solves `text`.
fn run(text: String) -> Result<biped_robots::calibration::Calibration, CalibrationError> {
    let f = LoadedFile::parse("cal.json", text)?;
    let urdf = f.load_model()?;
    calibrate(&f.problem(&urdf)?, &SolveOptions::default())
}

/// The located error of `text`: `(line, field, message)`.
fn located(text: String) -> (usize, String, String) {
    match run(text) {
        Err(CalibrationError::File {
            line,
            field,
            message,
            ..
        }) => (line, field, message),
        other => panic!("expected a located error, got {other:?}"),
    }
}

/// 1-based line of the `nth` (0-based) occurrence of `needle`.
fn line_of(text: &str, needle: &str, nth: usize) -> usize {
    let at = text.match_indices(needle).nth(nth).unwrap().0;
    text[..at].matches('\n').count() + 1
}

/// `text` with the `nth` occurrence of `from` replaced by `to`.
fn replace_nth(text: &str, from: &str, to: &str, nth: usize) -> String {
    let at = text.match_indices(from).nth(nth).unwrap().0;
    format!("{}{to}{}", &text[..at], &text[at + from.len()..])
}

#[test]
fn out_of_range_numbers_are_located_errors() {
    let good = example();
    // The first target x of pose 1 (the first "xyz": [ after "poses").
    let poses = good.find("\"poses\"").unwrap();
    let xyz = poses + good[poses..].find("\"xyz\": [").unwrap() + "\"xyz\": [".len();
    let end = xyz + good[xyz..].find(',').unwrap();
    let bad = format!("{}1e300{}", &good[..xyz], &good[end..]);
    let (line, field, msg) = located(bad);
    assert_eq!(line, line_of(&good, "\"pelvis->left_foot\": {", 0));
    assert_eq!(field, "poses[0].targets.pelvis->left_foot.xyz[0]");
    assert!(
        msg.contains("1e300 m") && msg.contains("[-10, 10] m"),
        "{msg}"
    );
    // Degrees instead of radians in a target rotation.
    let rpy = poses + good[poses..].find("\"rpy\": [").unwrap() + "\"rpy\": [".len();
    let end = rpy + good[rpy..].find(',').unwrap();
    let (_, field, msg) = located(format!("{}90{}", &good[..rpy], &good[end..]));
    assert_eq!(field, "poses[0].targets.pelvis->left_foot.rpy[0]");
    assert!(msg.contains("90 rad"), "{msg}");
    // An encoder reading of 1e300 rad (the second pose's knee).
    let knee = "\"left_knee_joint\": ";
    let at = good.match_indices(knee).nth(1).unwrap().0 + knee.len();
    let end = at + good[at..].find(',').unwrap();
    let (line, field, msg) = located(format!("{}1e300{}", &good[..at], &good[end..]));
    assert_eq!(line, line_of(&good, knee, 1));
    assert_eq!(field, "poses[1].encoders.left_knee_joint");
    assert!(msg.contains("encoder reading 1e300 rad"), "{msg}");
    // Weights: beyond 1e9, or negative; the line is the weight's own.
    for (w, nth) in [("1e300", 0), ("-1.0", 1)] {
        let bad = replace_nth(
            &good,
            "\"position_weight\": 10.0",
            &format!("\"position_weight\": {w}"),
            nth,
        );
        let (line, field, msg) = located(bad);
        assert_eq!(line, line_of(&good, "\"position_weight\"", nth));
        assert_eq!(field, format!("constraints[{nth}].position_weight"));
        assert!(msg.contains("[0, 1e9]"), "{msg}");
    }
    // A frame offset in millimetres.
    let bad = good.replacen(
        "\"link\": \"left_ankle_roll_link\"",
        "\"link\": \"left_ankle_roll_link\", \"xyz\": [0, 0, -30]",
        1,
    );
    let (_, field, _) = located(bad);
    assert_eq!(field, "constraints[0].frame_b.xyz[2]");
}

#[test]
fn repeated_names_are_located_duplicates() {
    let good = example();
    // A calibrated joint listed twice: "duplicate", at the repetition, not "rank-deficient".
    let bad = good.replacen(
        "\"right_ankle_roll_joint\"\n  ]",
        "\"right_ankle_roll_joint\",\n    \"left_knee_joint\"\n  ]",
        1,
    );
    let (line, field, msg) = located(bad.clone());
    assert_eq!(line, line_of(&bad, "\"left_knee_joint\"", 1));
    assert_eq!(field, "joints[12]");
    assert_eq!(msg, "duplicate joint `left_knee_joint` (also joints[3])");
    // A constraint name used twice: located at the second constraint.
    let bad = good.replacen("\"pelvis->right_foot\",", "\"pelvis->left_foot\",", 1);
    let (line, field, msg) = located(bad.clone());
    assert_eq!(line, line_of(&bad, "\"pelvis->left_foot\"", 1));
    assert_eq!(field, "constraints[1]");
    assert!(msg.starts_with("duplicate constraint name"), "{msg}");
    // A repeated encoder key (JSON keeps the last silently): located at the repetition.
    let knee = good
        .match_indices("\"left_knee_joint\": ")
        .nth(2)
        .unwrap()
        .0;
    let bad = format!(
        "{}\"left_knee_joint\": 0.5,\n{}",
        &good[..knee],
        &good[knee..]
    );
    let (line, field, msg) = located(bad.clone());
    assert_eq!(line, line_of(&bad, "\"left_knee_joint\": ", 3));
    assert_eq!(field, "left_knee_joint");
    assert!(msg.contains("duplicate key `left_knee_joint`"), "{msg}");
}

#[test]
fn byte_order_mark_is_accepted() {
    let with_bom = format!("\u{feff}{}", example());
    let plain = run(example()).unwrap();
    assert_eq!(run(with_bom).unwrap(), plain);
}

/// The synthetic 3-pose problem with both feet constraints' weights multiplied by `scale`.
fn scaled_problem(scale: f64) -> CalibrationProblem {
    let g1 = load(&g1_xml());
    let s = Synthetic {
        joints: leg_names(),
        offsets: random_offsets(12, 5),
        noise: 1e-4,
        poses: 3,
        seed: 9,
    };
    let p = problem(&g1, &g1, &s, Components::Pose);
    let constraints: Vec<JigConstraint> = (p.constraints().iter().cloned())
        .map(|c| JigConstraint {
            position_weight: c.position_weight * scale,
            orientation_weight: c.orientation_weight * scale,
            ..c
        })
        .collect();
    let (model, joints, poses) = (p.model().clone(), p.joints().to_vec(), p.poses().to_vec());
    CalibrationProblem::new(model, joints, constraints, poses).unwrap()
}

#[test]
fn extreme_weights_give_the_same_offsets() {
    let reference = calibrate(&scaled_problem(1.0), &SolveOptions::default()).unwrap();
    for scale in [1e300, 1e-300] {
        let c = calibrate(&scaled_problem(scale), &SolveOptions::default()).unwrap();
        let err = (&c.offsets - &reference.offsets).amax();
        assert!(err < 1e-10, "scale {scale:e}: offsets differ by {err:e}");
        let rel = (&c.std_errors - &reference.std_errors).amax() / reference.std_errors.amax();
        assert!(rel < 1e-6, "scale {scale:e}: std errors differ by {rel:e}");
        // Residuals are reported in the given weights.
        let rms = c.rms_after / (scale * reference.rms_after);
        assert!((rms - 1.0).abs() < 1e-6, "scale {scale:e}: rms ratio {rms}");
    }
}

#[test]
fn library_rejects_duplicate_joints_and_far_targets() {
    let p = scaled_problem(1.0);
    let mut joints = p.joints().to_vec();
    joints.push(joints[3].clone());
    let (model, cons) = (p.model().clone(), p.constraints().to_vec());
    let r = CalibrationProblem::new(model.clone(), joints, cons.clone(), p.poses().to_vec());
    assert!(matches!(r, Err(CalibrationError::DuplicateJoint(ref j)) if j == "left_knee_joint"));
    let mut poses = p.poses().to_vec();
    poses[1].targets[0].1.translation.vector.x = 1e300;
    let r = CalibrationProblem::new(model, p.joints().to_vec(), cons, poses);
    assert!(
        matches!(r, Err(CalibrationError::Invalid(ref m)) if m.contains("1e300 m")),
        "{r:?}"
    );
}

/// Values the fuzz test puts in place of the file's numbers: beyond every physical range,
/// at and near the ranges' bounds, subnormal, degrees.
const EXTREME: [&str; 12] = [
    "1e300", "-1e300", "1e308", "1e-300", "5e-324", "0", "-0", "90", "6.3", "-10.5", "1e9", "2e9",
];

/// A corruption of the example: number edits with [`EXTREME`] values, a repeated line (a
/// repeated key, element or a syntax error), the generic byte and number corruptions, and an
/// optional byte-order mark.
#[derive(Debug, Clone)]
enum Edit {
    Numbers(Vec<(Index, &'static str)>),
    RepeatLine(Index),
    Generic(mutate::Corruption),
}

/// The [`Edit`] strategy.
fn edits() -> impl Strategy<Value = (Edit, bool)> {
    let numbers = prop::collection::vec((any::<Index>(), prop::sample::select(&EXTREME[..])), 1..4);
    let edit = prop_oneof![
        3 => numbers.prop_map(Edit::Numbers),
        2 => any::<Index>().prop_map(Edit::RepeatLine),
        2 => mutate::corruptions(b"-9e.0[]{}\":,", 3).prop_map(Edit::Generic),
    ];
    (edit, any::<bool>())
}

/// `text` corrupted by `edit`.
fn apply(text: &str, edit: &Edit, bom: bool) -> String {
    let out = match edit {
        Edit::Numbers(n) => mutate::apply_numbers(text, n),
        Edit::RepeatLine(i) => {
            let lines: Vec<&str> = text.lines().collect();
            let k = i.index(lines.len());
            let mut out: Vec<&str> = lines[..=k].to_vec();
            out.extend_from_slice(&lines[k..]);
            out.join("\n")
        }
        Edit::Generic(c) => c.apply(text),
    };
    if bom {
        format!("\u{feff}{out}")
    } else {
        out
    }
}

/// Cases of the fuzz test.
const CASES: u32 = 300;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    /// Mutated calibration files never panic and never report a non-finite number: a one-line
    /// error (file errors naming the file), or finite offsets, standard errors, singular
    /// values and residuals.
    #[test]
    fn mutated_files_give_an_error_or_a_finite_result((edit, bom) in edits()) {
        let text = apply(&example(), &edit, bom);
        match run(text) {
            Ok(c) => {
                let all = c.offsets.iter().chain(c.std_errors.iter()).chain(&c.singular_values);
                prop_assert!(all.clone().all(|x| x.is_finite()), "{c:?}");
                prop_assert!(c.rms_after.is_finite());
                for p in &c.poses {
                    let v = [p.rms_before, p.max_before, p.rms_after, p.max_after];
                    prop_assert!(v.iter().all(|x| x.is_finite()), "{p:?}");
                }
            }
            Err(e) => {
                let msg = e.to_string();
                prop_assert!(!msg.contains('\n'), "{msg}");
                if let CalibrationError::File { file, .. } = &e {
                    prop_assert_eq!(file.as_str(), "cal.json");
                }
            }
        }
    }
}
