//! `--robot`: a robot description's URDF and SSV model in the scene, the model shown and
//! checked but not saved; the `[[pair]]` tables and the mirrored segments' lines the page edits.

mod support;

use biped_robots::description::Robot as Described;
use biped_view::{RobotSource, ViewConfig};
use serde_json::Value;
use std::path::PathBuf;
use support::{lola_ssv, temp_dir, Running};

fn config(robot: RobotSource, ssv: Option<PathBuf>) -> ViewConfig {
    ViewConfig {
        robot,
        ssv,
        recording: None,
        web_dir: temp_dir("described_web"),
    }
}

fn g1() -> RobotSource {
    RobotSource::Description {
        file: Described::bundled("g1").unwrap(),
        package_path: Vec::new(),
    }
}

fn names(list: &Value, key: &str) -> Vec<String> {
    let items = list.as_array().unwrap().iter();
    items
        .map(|v| v[key].as_str().unwrap().to_string())
        .collect()
}

#[test]
fn g1_scene_has_its_bodies_and_ssv_segments_and_save_is_refused() {
    let server = Running::start(&config(g1(), None));
    let (status, scene) = server.json("GET", "/api/scene", b"");
    assert_eq!(status, 200);
    let described = Described::load(Described::bundled("g1").unwrap()).unwrap();
    let model = &described.urdf.model;
    let bodies = names(&scene["bodies"], "name");
    let expected: Vec<String> = model.body_names().iter().map(|n| n.to_string()).collect();
    assert_eq!(bodies, expected);
    assert!(bodies.iter().any(|b| b == "left_knee_link"), "{bodies:?}");
    assert!(scene["robot"].as_str().unwrap().starts_with("g1 ("));
    let ssv = &scene["ssv"];
    let collision = described.collision.as_ref().unwrap();
    let segments = names(&ssv["segments"], "name");
    let own: Vec<&str> = collision
        .model
        .segments()
        .iter()
        .map(|s| s.name())
        .collect();
    assert_eq!(segments, own);
    assert!(ssv["file"].as_str().unwrap().ends_with("g1_ssv.toml"));
    let why = ssv["read_only"].as_str().unwrap();
    assert!(why.contains("--ssv"), "{why}");
    // `biped ssv fit` writes the entries as [[segment.ssvs]] tables: their lines are located.
    let path = described.description.collision_model.clone().unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let knee = ssv["segments"].as_array().unwrap().iter();
    let knee = knee
        .clone()
        .find(|s| s["name"] == "left_knee_link")
        .unwrap();
    assert_eq!(knee["source"]["tables"], true);
    let lines = at(&text, &knee["source"]["span"]);
    assert!(lines.starts_with("[[segment.ssvs]]\nline = [["), "{lines}");
    assert!(lines.ends_with("radius = 0.05760761397928504\n"), "{lines}");
    assert_eq!(lines.matches("[[segment.ssvs]]").count(), 1);

    // Edits are checked, a save is refused and the bundled file stays as it is.
    let (status, _) = server.json("POST", "/api/ssv/check", text.as_bytes());
    assert_eq!(status, 200);
    let (status, answer) = server.json("PUT", "/api/ssv", text.as_bytes());
    assert_eq!(status, 403, "{answer}");
    assert!(
        answer["error"].as_str().unwrap().contains("--ssv"),
        "{answer}"
    );
}

#[test]
fn g1_with_its_own_ssv_file_saves_it() {
    let dir = temp_dir("g1_own");
    let own = dir.join("g1_ssv.toml");
    let bundled = Described::bundled("g1")
        .unwrap()
        .with_file_name("g1_ssv.toml");
    std::fs::copy(&bundled, &own).unwrap();
    let server = Running::start(&config(g1(), Some(own.clone())));
    let text = std::fs::read_to_string(&own).unwrap() + "\n# edited\n";
    let (status, answer) = server.json("PUT", "/api/ssv", text.as_bytes());
    assert_eq!(status, 200, "{answer}");
    assert!(answer["ssv"]["read_only"].is_null());
    assert_eq!(std::fs::read_to_string(&own).unwrap(), text);
}

#[test]
fn a_bad_description_is_the_loaders_located_error() {
    let dir = temp_dir("bad_description");
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "name = \"x\"\nurdf = 3\n").unwrap();
    let config = config(
        RobotSource::Description {
            file: bad.clone(),
            package_path: Vec::new(),
        },
        None,
    );
    let err = biped_view::AppState::load(&config).unwrap_err().to_string();
    assert!(err.starts_with(&format!("{}:2: ", bad.display())), "{err}");
}

/// UTF-16 span `[start, end)` of `text` as a `&str` (the texts here are ASCII).
fn at<'a>(text: &'a str, span: &Value) -> &'a str {
    let [a, b] = [0, 1].map(|i| span[i].as_u64().unwrap() as usize);
    &text[a..b]
}

#[test]
fn pair_tables_and_mirror_lines_are_located() {
    let dir = temp_dir("tables");
    let file = dir.join("model.toml");
    let lola = std::fs::read_to_string(lola_ssv()).unwrap();
    let start = lola.find("pairs = [").unwrap();
    let end = start + lola[start..].find("\n]\n").unwrap() + 3;
    let tables = "# as tables\n[[pair]]\na = \"r_foot\" # right\nb = \"l_foot\"\n\n[[pair]]\n  b = \"r_toe\"\n  a = \"l_toe\"\n";
    let text = format!("{}{}\n{tables}", &lola[..start], &lola[end..]);
    std::fs::write(&file, &text).unwrap();
    let lola_robot = RobotSource::Lola(biped_robots::lola::LolaType::Type2);
    let server = Running::start(&config(lola_robot, Some(file)));
    let (_, scene) = server.json("GET", "/api/scene", b"");
    let ssv = &scene["ssv"];
    assert!(ssv["pair_list"].is_null());
    let tables = ssv["pair_tables"].as_array().unwrap();
    assert_eq!(names(&ssv["pair_tables"], "a"), ["r_foot", "l_toe"]);
    assert_eq!(
        at(&text, &tables[0]["span"]),
        "[[pair]]\na = \"r_foot\" # right\nb = \"l_foot\"\n"
    );
    assert_eq!(
        at(&text, &tables[1]["span"]),
        "[[pair]]\n  b = \"r_toe\"\n  a = \"l_toe\"\n"
    );
    let segments = ssv["segments"].as_array().unwrap();
    let l_toe = segments.iter().find(|s| s["name"] == "l_toe").unwrap();
    assert_eq!(l_toe["source"]["kind"], "mirror_of");
    let lines = &l_toe["source"]["lines"];
    assert_eq!(at(&text, &lines[0]), "mirror_of = \"r_toe\"\n");
    assert_eq!(at(&text, &lines[1]), "plane = \"xz\"\n");
}
