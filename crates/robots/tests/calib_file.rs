//! The calibration file format: the bundled example parses and calibrates to its reference
//! offsets; malformed files give errors naming file, line and field.

mod calib_support;

use biped_robots::calibration::{
    calibrate, CalibrationError, Components, LoadedFile, SolveOptions,
};
use biped_test_support::mutate;
use calib_support::*;
use std::path::Path;

const EXAMPLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/calibration_example.json");
/// Encoder noise used to generate the example \[rad].
const EXAMPLE_NOISE: f64 = 1e-4;

/// Regenerates `data/calibration_example.json` (run with `--ignored`).
#[test]
#[ignore]
fn regenerate_example() {
    let g1 = load(&g1_xml());
    let s = Synthetic {
        joints: leg_names(),
        offsets: random_offsets(12, 2014),
        noise: EXAMPLE_NOISE,
        poses: 3,
        seed: 35,
    };
    let p = problem(&g1, &g1, &s, Components::Pose);
    let cons: Vec<_> = ["left", "right"]
        .iter()
        .zip(p.constraints())
        .map(|(side, c)| {
            serde_json::json!({
                "name": c.name,
                "frame_a": {"link": "pelvis"},
                "frame_b": {"link": format!("{side}_ankle_roll_link")},
                "components": "pose",
                "position_weight": c.position_weight,
                "orientation_weight": c.orientation_weight,
            })
        })
        .collect();
    let poses: Vec<_> = p
        .poses()
        .iter()
        .map(|pose| {
            let enc: serde_json::Map<_, _> = p
                .joints()
                .iter()
                .map(|j| (j.name.clone(), pose.q_measured[j.q_index].into()))
                .collect();
            let targets: serde_json::Map<_, _> = pose
                .targets
                .iter()
                .map(|(c, t)| {
                    let (r, pi, y) = t.rotation.euler_angles();
                    let v = t.translation.vector;
                    (
                        p.constraints()[*c].name.clone(),
                        serde_json::json!({"xyz": [v.x, v.y, v.z], "rpy": [r, pi, y]}),
                    )
                })
                .collect();
            serde_json::json!({"name": pose.name, "encoders": enc, "targets": targets})
        })
        .collect();
    let reference: serde_json::Map<_, _> = s
        .joints
        .iter()
        .zip(s.offsets.iter())
        .map(|(n, x)| (n.clone(), (*x).into()))
        .collect();
    let doc = serde_json::json!({
        "model": {"urdf": "../../dynamics/data/g1_29dof_rev_1_0.urdf", "floating": false},
        "joints": s.joints,
        "constraints": cons,
        "poses": poses,
        "reference_offsets": reference,
    });
    std::fs::write(EXAMPLE, serde_json::to_string_pretty(&doc).unwrap() + "\n").unwrap();
}

#[test]
fn example_file_calibrates_to_its_reference_offsets() {
    let f = LoadedFile::read(Path::new(EXAMPLE)).unwrap();
    let urdf = f.load_model().unwrap();
    let p = f.problem(&urdf).unwrap();
    let c = calibrate(&p, &SolveOptions::default()).unwrap();
    assert_eq!(c.joints.len(), 12);
    for (name, x) in c.joints.iter().zip(c.offsets.iter()) {
        let truth = f.spec.reference_offsets[name];
        // 3 poses, uniform noise of std 1e-4: the error std is below the noise std (see
        // calib_offsets::noisy_offsets_within_noise_derived_tolerance); allow 5 sigma.
        assert!(
            (x - truth).abs() < 5.0 * EXAMPLE_NOISE,
            "{name}: {x} vs {truth}"
        );
    }
    for r in &c.poses {
        assert!(r.rms_after < r.rms_before * 1e-2, "{r:?}");
    }
}

/// The error of parsing `text` (written to a temp file so the path appears in the message).
fn error_of(text: &str, tag: &str) -> String {
    let dir = std::env::temp_dir().join(format!("biped_calib_{}_{tag}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad.json");
    std::fs::write(&path, text).unwrap();
    let r = LoadedFile::read(&path).and_then(|f| {
        let urdf = f.load_model()?;
        f.problem(&urdf).map(|_| ())
    });
    match r {
        Err(e @ CalibrationError::File { .. }) => e.to_string(),
        other => panic!("expected a located file error, got {other:?}"),
    }
}

#[test]
fn bad_files_name_file_line_and_field() {
    let good = std::fs::read_to_string(EXAMPLE).unwrap();
    let fix = |s: &str| {
        s.replace(
            "../../dynamics",
            concat!(env!("CARGO_MANIFEST_DIR"), "/../dynamics"),
        )
    };
    // Type error: a string where a weight is expected.
    let bad = good.replacen(
        "\"position_weight\": 10.0",
        "\"position_weight\": \"ten\"",
        1,
    );
    let e = error_of(&fix(&bad), "type");
    assert!(
        e.contains("bad.json:") && e.contains("position_weight"),
        "{e}"
    );
    let line = good
        .lines()
        .position(|l| l.contains("position_weight"))
        .unwrap()
        + 1;
    assert!(e.contains(&format!(":{line}:")), "{e} (line {line})");
    // Unknown field.
    let bad = good.replacen("\"components\"", "\"component\"", 1);
    let e = error_of(&fix(&bad), "unknown");
    assert!(e.contains("component"), "{e}");
    // A damaged key whose quotes no longer delimit a field name: one line, no stray text.
    let bad = good.replacen("\"orientation_weight\"", "\":rientation_weight\"", 1);
    let e = error_of(&fix(&bad), "damaged");
    assert!(!e.contains('\n') && e.contains(":rientation_weight"), "{e}");
    // Unknown joint in the calibrated list.
    let bad = good.replacen("\"left_knee_joint\"", "\"left_kneee_joint\"", 1);
    let e = error_of(&fix(&bad), "joint");
    assert!(
        e.contains("joints[3]") && e.contains("left_kneee_joint"),
        "{e}"
    );
    // Unknown link.
    let bad = good.replacen("\"pelvis\"", "\"pelvic\"", 1);
    let e = error_of(&fix(&bad), "link");
    assert!(e.contains("frame_a.link") && e.contains("pelvic"), "{e}");
    // Missing URDF.
    let bad = good.replacen("g1_29dof_rev_1_0.urdf", "nope.urdf", 1);
    let e = error_of(&bad, "urdf");
    assert!(e.contains("model.urdf"), "{e}");
    // Syntax error.
    let e = error_of(
        "{\n  \"model\": {\"urdf\": \"x\"},\n  \"joints\": [\n",
        "syntax",
    );
    assert!(
        e.contains("bad.json:4:") || e.contains("bad.json:3:"),
        "{e}"
    );
}

#[test]
fn pose_and_constraint_errors_point_into_their_own_element() {
    let good = std::fs::read_to_string(EXAMPLE).unwrap();
    let fix = |s: &str| {
        s.replace(
            "../../dynamics",
            concat!(env!("CARGO_MANIFEST_DIR"), "/../dynamics"),
        )
    };
    // Rename the knee encoder of the third pose only (the 4th occurrence after `joints`).
    let third = good.match_indices("\"left_knee_joint\":").nth(2).unwrap().0;
    let bad = format!("{}\"left_knees\":{}", &good[..third], &good[third + 18..]);
    let line = bad[..third].matches('\n').count() + 1;
    let e = error_of(&fix(&bad), "pose3");
    assert!(
        e.contains(&format!(":{line}: poses[2].encoders.left_knees")),
        "{e} (line {line})"
    );
    // Unknown link in the second constraint's frame_b.
    let second = good
        .match_indices("\"right_ankle_roll_link\"")
        .next()
        .unwrap()
        .0;
    let bad = format!(
        "{}\"right_foot_x\"{}",
        &good[..second],
        &good[second + 23..]
    );
    let line = bad[..second].matches('\n').count() + 1;
    let e = error_of(&fix(&bad), "link2");
    assert!(
        e.contains(&format!(":{line}: constraints[1].frame_b.link")),
        "{e} (line {line})"
    );
}

#[test]
fn non_finite_or_inconsistent_input_is_a_typed_error() {
    use biped_robots::calibration::CalibrationProblem;
    let g1 = load(&g1_xml());
    let s = Synthetic {
        joints: leg_names(),
        offsets: random_offsets(12, 1),
        noise: 0.0,
        poses: 1,
        seed: 1,
    };
    let p = problem(&g1, &g1, &s, Components::Pose);
    let mut poses = p.poses().to_vec();
    poses[0].q_measured[3] = f64::NAN;
    let r = CalibrationProblem::new(
        p.model().clone(),
        p.joints().to_vec(),
        p.constraints().to_vec(),
        poses,
    );
    assert!(matches!(r, Err(CalibrationError::NonFinite(_))));
    let r = CalibrationProblem::new(
        p.model().clone(),
        vec![],
        p.constraints().to_vec(),
        p.poses().to_vec(),
    );
    assert!(matches!(r, Err(CalibrationError::Invalid(_))));
    let x = nalgebra::DVector::from_element(12, f64::INFINITY);
    assert!(matches!(
        p.residual(&x),
        Err(CalibrationError::NonFinite(_))
    ));
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(120))]

    /// Random edits of the example file never panic: parsing, the model, the problem and the
    /// solve end in a one-line error (file errors naming the file) or offsets that are all
    /// finite.
    #[test]
    fn mutated_calibration_file_never_panics(c in mutate::corruptions(b"-9e.0[]{}\":,", 3)) {
        let text = c.apply(&std::fs::read_to_string(EXAMPLE).unwrap());
        let r = LoadedFile::parse(EXAMPLE, text).and_then(|f| {
            let urdf = f.load_model()?;
            calibrate(&f.problem(&urdf)?, &SolveOptions::default())
        });
        match r {
            Ok(c) => proptest::prop_assert!(c.offsets.iter().all(|x| x.is_finite()), "{c:?}"),
            Err(e) => {
                let msg = e.to_string();
                proptest::prop_assert!(!msg.contains('\n'), "{msg}");
                if let CalibrationError::File { file, .. } = &e {
                    proptest::prop_assert_eq!(file.as_str(), EXAMPLE);
                }
            }
        }
    }
}
