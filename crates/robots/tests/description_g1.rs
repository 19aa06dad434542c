//! The robot description files: the bundled G1 (and TALOS where example-robot-data is
//! installed) load and agree with their URDF, the G1's fitted SSV model is free of contact at
//! the comfort pose, the documented example loads, and broken files give errors that name the
//! file, the line and the field.

use biped_dynamics::update_placements;
use biped_dynamics::urdf::PackagePath;
use biped_dynamics::Data;
use biped_robots::description::{search_path, DescriptionError, Robot};
use std::path::{Path, PathBuf};

fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("data")
}

fn g1_text() -> String {
    std::fs::read_to_string(data_dir().join("g1.toml")).unwrap()
}

/// Loads `text` as if it were `data/g1.toml` (same folder), without any package folders.
fn parse(text: &str) -> Result<Robot, DescriptionError> {
    Robot::parse(
        text,
        "g1.toml",
        &data_dir(),
        &PackagePath::new(vec![], None),
    )
}

/// 1-based line of the first line of `text` containing `needle`.
fn line_of(text: &str, needle: &str) -> usize {
    1 + text.lines().position(|l| l.contains(needle)).expect(needle)
}

#[test]
fn g1_loads_with_its_urdf() {
    let g1 = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
    let d = &g1.description;
    assert_eq!(d.name, "g1");
    assert_eq!((g1.urdf.model.nq(), g1.urdf.model.nv()), (7 + 29, 6 + 29));
    assert_eq!(d.feet[1].frame, "right_ankle_roll_link");
    assert_eq!(d.feet[0].sole_size, [0.17, 0.055]);
    assert_eq!(d.legs[0].len(), 6);
    assert_eq!(d.arms[1].len(), 7);
    assert_eq!(d.reducing.len(), 4);
    // producing = every other joint: 29 - 4
    assert_eq!(d.producing.len(), 25);
    assert!(d.producing.iter().all(|p| !d.reducing.contains(p)));
    // the first matching armature pattern wins
    assert_eq!(g1.armature("left_knee_joint"), 0.0251);
    assert_eq!(g1.armature("right_ankle_roll_joint"), 0.00722);
    assert_eq!(g1.armature("left_elbow_joint"), 0.00361);
    // comfort pose: listed values, others 0, all inside the ranges
    let (qi, _) = g1.joint_index("left_knee_joint").unwrap();
    assert_eq!(g1.comfort[qi], 0.6);
    let (qi, _) = g1.joint_index("waist_yaw_joint").unwrap();
    assert_eq!(g1.comfort[qi], 0.0);
    for j in &g1.urdf.joints {
        let [lo, hi] = j.range.unwrap();
        let (qi, _) = g1.joint_index(&j.name).unwrap();
        assert!(g1.comfort[qi] >= lo && g1.comfort[qi] <= hi, "{}", j.name);
    }
}

#[test]
fn g1_collision_model_is_free_of_contact_at_the_comfort_pose() {
    let g1 = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
    let mut collision = g1.collision.unwrap();
    assert_eq!(collision.model.segments().len(), 30);
    // the fitted file's 348 pairs less the two excluded ones
    assert_eq!(collision.model.pairs().len(), 348 - 2);
    // every body but the pelvis (the root) is a model body of the same name
    for (name, body) in collision.model.bodies().iter().zip(&collision.model_bodies) {
        let b = body.expect(name);
        assert_eq!(g1.urdf.model.bodies()[b].name(), name);
    }
    let model = &g1.urdf.model;
    let mut data = Data::new(model);
    update_placements(model, &mut data, &g1.comfort).unwrap();
    let poses: Vec<_> = collision
        .model_bodies
        .iter()
        .map(|b| data.body_pose(b.unwrap()))
        .collect();
    collision.model.update(&poses).unwrap();
    if let Some((k, closest)) = collision.model.min_distance() {
        let pair = &collision.model.pairs()[k];
        assert!(
            closest.result.distance > 0.0,
            "pair {pair:?} at {}",
            closest.result.distance
        );
    }
}

#[test]
fn documented_example_loads() {
    let doc = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/robot_description.md"),
    )
    .unwrap();
    let start = doc.find("```toml\n").expect("a toml block") + 8;
    let len = doc[start..].find("```").unwrap();
    let example = &doc[start..start + len];
    let robot = parse(example).unwrap();
    assert_eq!(robot.description.name, "my_g1");
    assert_eq!(robot.description.feet[0].toe_joint, None);
    assert_eq!(robot.description.comfort_joints.len(), 2);
    let pairs = robot.description.collision_pairs.as_ref().unwrap();
    assert_eq!(robot.description.collision_exclude.len(), 1);
    assert_eq!(
        robot.collision.unwrap().model.pairs().len(),
        pairs.len() - 1
    );
}

#[test]
fn talos_is_found_through_robots_or_names_what_to_install() {
    let talos = Robot::bundled("talos").unwrap();
    let err = Robot::load_with(&talos, &PackagePath::new(vec![], None))
        .err()
        .expect("no package folders: TALOS cannot be found");
    let text = std::fs::read_to_string(&talos).unwrap();
    assert_eq!(err.line(), line_of(&text, "urdf = "));
    assert_eq!(err.field(), "urdf");
    let message = err.to_string();
    assert!(message.contains("talos_data"), "{message}");
    assert!(message.contains("example-robot-data"), "{message}");
    assert!(message.contains("fetch_robots.sh"), "{message}");
    // with example-robot-data installed (ROBOTS set), TALOS loads
    let installed = std::env::var_os("ROBOTS").map(PathBuf::from);
    if installed.is_some_and(|r| r.join("talos_data").is_dir()) {
        let robot = Robot::load_with(&talos, &search_path(vec![])).unwrap();
        assert_eq!(robot.urdf.model.nv(), 6 + 32);
        assert!(robot.srdf.is_some());
        let (qi, _) = robot.joint_index("leg_left_4_joint").unwrap();
        assert!(robot.comfort[qi] > 0.5); // half sitting: bent knees
    }
}

/// `g1.toml` with the first occurrence of `from` replaced by `to`; the error must be on the
/// line of `to` (or of `at`, if given) and name `field`.
fn assert_located(from: &str, to: &str, at: Option<&str>, field: &str, says: &str) {
    let text = g1_text().replacen(from, to, 1);
    assert_ne!(text, g1_text(), "{from} not in g1.toml");
    let err = parse(&text)
        .err()
        .unwrap_or_else(|| panic!("{to}: accepted"));
    let message = err.to_string();
    let line = line_of(&text, at.unwrap_or(to));
    assert!(
        message.starts_with(&format!("g1.toml:{line}: ")),
        "{to}: {message}"
    );
    assert_eq!(err.line(), line, "{message}");
    assert_eq!(err.field(), field, "{message}");
    assert!(message.contains(says), "{to}: {message}");
}

#[test]
fn bad_files_give_located_errors() {
    assert_located(
        "\"left_knee_joint\",",
        "\"left_kne_joint\",",
        None,
        "groups.left_leg",
        "`left_kne_joint` is not a movable joint",
    );
    assert_located(
        "frame = \"right_ankle_roll_link\"",
        "frame = \"right_foot\"",
        None,
        "feet.right.frame",
        "not a link of the URDF",
    );
    assert_located(
        "sole_size = [0.17, 0.055]",
        "sole_size = [0.17, -0.055]",
        None,
        "feet.left.sole_size",
        "must be > 0",
    );
    assert_located(
        "left_knee_joint = 0.6",
        "left_knee_joint = -0.6",
        None,
        "comfort.joints.left_knee_joint",
        "outside the joint range",
    );
    assert_located(
        "urdf = \"../../dynamics/data/g1_29dof_rev_1_0.urdf\"",
        "urdf = \"../../dynamics/data/g2.urdf\"",
        None,
        "urdf",
        "does not exist",
    );
    assert_located(
        "model = \"g1_ssv.toml\"",
        "model = \"g1_ssv.toml\"\npairs = [[\"torso_link\", \"left_hand\"]]",
        Some("pairs = "),
        "collision.pairs",
        "`left_hand` is not a segment",
    );
    assert_located(
        "[\"torso_link\", \"left_shoulder_roll_link\"]",
        "[\"torso_link\", \"logo_link\"]",
        None,
        "collision.exclude",
        "not a pair of the collision model",
    );
    assert_located(
        "{ joints = \"*_knee_joint\", inertia = 0.0251 },",
        "{ joints = \"*_knees_joint\", inertia = 0.0251 },",
        None,
        "drives.armature[4]",
        "matches no movable joint",
    );
    assert_located(
        "[comfort.joints]",
        "[comfort]\nsrdf_state = \"half_sitting\"\n[comfort.joints]",
        Some("srdf_state"),
        "comfort.srdf_state",
        "no SRDF group_state",
    );
    assert_located(
        "reducing = [",
        "producing = [\"left_elbow_joint\"]\nreducing = [",
        Some("producing = "),
        "momentum.producing",
        "also in momentum.reducing",
    );
}

#[test]
fn syntax_and_field_errors_are_located() {
    // unknown field
    assert_located(
        "sole_size = [0.17, 0.055]",
        "sole_size = [0.17, 0.055]\nsole_width = 0.05",
        Some("sole_width"),
        "sole_width",
        "unknown field",
    );
    // wrong type
    assert_located(
        "floating = true",
        "floating = \"yes\"",
        None,
        "floating",
        "invalid type",
    );
    // missing field: reported at the table that lacks it
    assert_located(
        "frame = \"left_ankle_roll_link\"\n",
        "",
        Some("[feet.left]"),
        "frame",
        "missing field `frame`",
    );
    // broken TOML
    assert_located("name = \"g1\"", "name = \"g1", None, "name", "");
}
