//! `biped walk --robot`: the bundled G1 walks a few steps with every arm method; the outputs and
//! verdicts are those of the Lola walk, and a replay of the trajectory's q through the G1's
//! forward kinematics confirms the feet (planned sole frames, no sliding of a stance foot,
//! the footsteps' advance), the CoM (the model's, and the pattern's LIPM CoM regenerated from
//! the robot) and the joint ranges. Bad robots fail with one line.

use biped_control::pattern::WalkingPattern;
use biped_control::walk::WalkRobot;
use biped_dynamics::{center_of_mass, Data};
use biped_robots::description::Robot;
use nalgebra::{DVector, Vector3};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const STEPS: usize = 3;

fn biped() -> Command {
    Command::new(env!("CARGO_BIN_EXE_biped"))
}

fn temp(tag: &str) -> PathBuf {
    std::env::temp_dir().join(format!("biped_walk_robot_{tag}_{}", std::process::id()))
}

/// Rows of a CSV file as (header, numbers).
fn csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let head = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    (head, rows)
}

fn column(head: &[String], name: &str) -> usize {
    head.iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name}"))
}

#[test]
fn g1_walks_with_every_method_and_its_replay_keeps_the_plan() {
    let dir = temp("g1");
    let out = biped()
        .args([
            "walk",
            "--robot",
            "g1",
            "--steps",
            &STEPS.to_string(),
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}{stdout}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.starts_with("walked g1 ("), "{stdout}");
    for line in [
        "tracking: kept",
        "joint limits: kept",
        "self-collision: none",
        "friction: kept",
    ] {
        assert!(stdout.contains(line), "{line}: {stdout}");
    }
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["violations"].as_array().map(Vec::len), Some(0));
    for m in ["none", "reference", "compensation", "minimization"] {
        let s = &summary[m];
        assert!(s["min_distance"].as_f64().unwrap() > 0.0, "{m}");
        assert!(s["min_joint_margin"].as_f64().unwrap() >= 0.0, "{m}");
        for file in [format!("{m}.csv"), format!("{m}_recording.csv.gz")] {
            assert!(dir.join(&file).is_file(), "{file}");
        }
        replay(&dir.join(format!("{m}_trajectory.csv")), m);
    }
    // the free arms reduce the vertical angular momentum of the held ones
    let peak = |m: &str| summary[m]["peak_abs_Lz"].as_f64().unwrap();
    assert!(peak("minimization") < 0.5 * peak("none"));
    assert!(peak("compensation") < 0.5 * peak("none"));
    assert!(std::fs::read_to_string(dir.join("lz.svg"))
        .unwrap()
        .contains("<svg"));
    std::fs::remove_dir_all(&dir).ok();
}

/// Replays the q of a trajectory file through the G1's kinematics (see the module docs).
fn replay(path: &Path, method: &str) {
    let g1 = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
    let model = &g1.urdf.model;
    let (head, rows) = csv(path);
    let names = model.q_names();
    let q_cols: Vec<usize> = names
        .iter()
        .map(|n| column(&head, &format!("q[{n}]")))
        .collect();
    let feet = &g1.description.feet; // [left, right]
    let bodies = feet.each_ref().map(|f| model.body_id(&f.frame).unwrap());
    let sole_cols = ["l_sole", "r_sole"].map(|s| column(&head, &format!("{s}.x")));
    let com_col = column(&head, "com.x");
    let step = summary_step(path);
    let robot = WalkRobot::from_description(&g1).unwrap();
    let pattern = WalkingPattern::generate(&robot.pattern_params(STEPS, step, 0.8)).unwrap();
    assert_eq!(
        pattern.len(),
        rows.len(),
        "{method}: one row per pattern sample"
    );
    let mut com_offset: Option<Vector3<f64>> = None;
    let mut data = Data::new(model);
    let mut contact: [Vec<Vector3<f64>>; 2] = Default::default();
    let mut first = None;
    let mut last = [Vector3::zeros(); 2];
    for (k, row) in rows.iter().enumerate() {
        let q = DVector::from_iterator(names.len(), q_cols.iter().map(|&c| row[c]));
        for j in &g1.urdf.joints {
            let [lo, hi] = j.range.unwrap();
            let i = model.body(j.body).unwrap().q_index();
            assert!(
                q[i] >= lo - 1e-9 && q[i] <= hi + 1e-9,
                "{method}: {} = {}",
                j.name,
                q[i]
            );
        }
        let com = center_of_mass(model, &mut data, &q, None).unwrap().position;
        let planned = Vector3::new(row[com_col], row[com_col + 1], row[com_col + 2]);
        assert!(
            (com - planned).norm() < 1e-9,
            "{method}: CoM {com} vs {planned}"
        );
        // the CoM follows the pattern's LIPM CoM (shifted by the start pose's offset)
        let lipm = pattern.sample(k).unwrap().com;
        let offset = *com_offset.get_or_insert(com - lipm);
        let off = (com - lipm - offset).norm();
        assert!(
            off < 5e-3,
            "{method}: CoM {off} m off the pattern at row {k}"
        );
        for s in 0..2 {
            let b = bodies[s];
            let down = Vector3::new(0.0, 0.0, feet[s].sole_center.z);
            let p = data.world_pos[b] + data.world_rot[b] * down;
            let c = sole_cols[s];
            let file = Vector3::new(row[c], row[c + 1], row[c + 2]);
            assert!((p - file).norm() < 1e-9, "{method}: sole {p} vs {file}");
            // flat on the ground: at rest within one contact
            if p.z.abs() < 2e-4 && data.world_rot[b][(2, 2)] > 1.0 - 1e-6 {
                contact[s].push(p);
            } else if !contact[s].is_empty() {
                check_contact(&contact[s], method);
                contact[s].clear();
            }
            last[s] = p;
        }
        first.get_or_insert(last);
        let mid = 0.5 * (last[0] + last[1]);
        assert!(
            (com.xy() - mid.xy()).norm() < 0.25,
            "{method}: CoM far from the feet"
        );
    }
    contact.iter().for_each(|c| check_contact(c, method));
    let first = first.unwrap();
    for s in 0..2 {
        let moved = last[s] - first[s];
        let planned = (STEPS - 1) as f64 * step;
        assert!(
            (moved.x - planned).abs() < 3e-3,
            "{method}: foot moved {moved}, planned {planned}"
        );
        assert!(
            moved.y.abs() < 3e-3 && moved.z.abs() < 1e-3,
            "{method}: {moved}"
        );
    }
}

/// A stance foot does not slide: its positions within one contact stay within 1 mm.
fn check_contact(points: &[Vector3<f64>], method: &str) {
    let Some(p0) = points.first() else { return };
    for p in points {
        assert!(
            (p - p0).xy().norm() < 1e-3,
            "{method}: stance foot slid {}",
            (p - p0).norm()
        );
    }
}

/// The step length walked, from the report's first line in the output folder's summary.
fn summary_step(trajectory: &Path) -> f64 {
    let dir = trajectory.parent().unwrap();
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    s["robot"]["step_length"].as_f64().unwrap()
}

fn one_line_error(args: &[&str]) -> String {
    let out: Output = biped().args(args).output().unwrap();
    assert!(!out.status.success(), "{args:?}");
    let err = String::from_utf8_lossy(&out.stderr).trim().to_string();
    assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    err
}

#[test]
fn bad_robots_fail_with_one_located_line() {
    let err = one_line_error(&["walk", "--robot", "nosuch"]);
    assert!(err.contains("--robot") && err.contains("nosuch"), "{err}");

    let dir = temp("bad");
    std::fs::create_dir_all(&dir).unwrap();
    let g1 = Robot::bundled("g1").unwrap();
    let data = g1.parent().unwrap();
    let text = std::fs::read_to_string(&g1).unwrap().replace(
        "urdf = \"../../dynamics/data/",
        &format!("urdf = \"{}/../../dynamics/data/", data.display()),
    );
    let model = format!("model = \"{}/g1_ssv.toml\"", data.display());
    let text = text.replace("model = \"g1_ssv.toml\"", &model);
    let typo = dir.join("typo.toml");
    std::fs::write(
        &typo,
        text.replace("\"left_knee_joint\",", "\"left_kne_joint\","),
    )
    .unwrap();
    let err = one_line_error(&["walk", "--robot", typo.to_str().unwrap()]);
    assert!(
        err.contains("typo.toml:") && err.contains("left_kne_joint"),
        "{err}"
    );
    let short = dir.join("short_leg.toml");
    let leg = "\"left_ankle_pitch_joint\", \"left_ankle_roll_joint\"]";
    assert!(text.contains(leg));
    std::fs::write(&short, text.replace(leg, "\"left_ankle_pitch_joint\"]")).unwrap();
    let err = one_line_error(&["walk", "--robot", short.to_str().unwrap(), "--dynamic"]);
    assert!(
        err.contains("--robot") && err.contains("short_leg.toml") && err.contains("5 joints"),
        "{err}"
    );
    let start = text.find("[collision]").unwrap();
    let end = text.find("[drives]").unwrap();
    let bare = dir.join("bare.toml");
    std::fs::write(&bare, format!("{}{}", &text[..start], &text[end..])).unwrap();
    let err = one_line_error(&["walk", "--robot", bare.to_str().unwrap()]);
    assert!(
        err.contains("bare.toml") && err.contains("[collision]"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// `biped walk --robot g1 --dynamic`: the G1 walks 10 steps of its natural step length in the
/// contact simulation (end stops on), every verdict kept, and writes the dynamic walk's files;
/// the summary's distance is the recorded base's travel and no recorded joint angle leaves
/// the URDF's range.
#[test]
fn g1_walks_dynamically_with_every_verdict_kept() {
    let dir = temp("dynamic");
    let out = biped()
        .args([
            "walk",
            "--robot",
            "g1",
            "--dynamic",
            "--method",
            "minimization",
        ])
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout.contains("dynamic (minimization): walked"),
        "{stdout}"
    );
    assert!(
        stdout.contains("dynamic limits and self-collision: kept"),
        "{stdout}"
    );
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let d = &s["dynamic"];
    for key in [
        "walked",
        "contact_kept",
        "friction_kept",
        "limits_kept",
        "collision_free",
    ] {
        assert_eq!(d[key], true, "{key}: {d}");
    }
    assert_eq!(d["end_stops"], true);
    assert!(d["fell_at"].is_null(), "{d}");
    assert!(s["violations"].as_array().unwrap().is_empty(), "{s}");
    let step = s["robot"]["step_length"].as_f64().unwrap();
    let planned = d["planned_distance"].as_f64().unwrap();
    assert!(
        (planned - 9.0 * step).abs() < 0.05 * planned,
        "{planned} vs {step}"
    );
    let (head, rows) = csv(&dir.join("dynamic.csv"));
    let x = column(&head, "base_x");
    let travel = rows.last().unwrap()[x] - rows[0][x];
    assert!((travel - d["distance"].as_f64().unwrap()).abs() < 1e-6);
    assert!(travel > 0.95 * planned, "{travel} of {planned}");
    let recording = std::fs::File::open(dir.join("dynamic_recording.csv.gz")).unwrap();
    let mut text = String::new();
    std::io::Read::read_to_string(&mut flate2::read::GzDecoder::new(recording), &mut text).unwrap();
    let g1 = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
    let mut lines = text.lines();
    let names: Vec<&str> = lines.next().unwrap().split(',').collect();
    let ranges: Vec<(usize, [f64; 2])> = g1
        .urdf
        .joints
        .iter()
        .filter_map(|j| {
            let col = names.iter().position(|n| *n == format!("q[{}]", j.name))?;
            Some((col, j.range?))
        })
        .collect();
    assert_eq!(ranges.len(), 29);
    let mut rows = 0;
    for line in lines {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        for &(col, [lo, hi]) in &ranges {
            assert!(v[col] >= lo && v[col] <= hi, "{} = {}", names[col], v[col]);
        }
        rows += 1;
    }
    assert!(rows > 100, "{rows} recorded rows");
    std::fs::remove_dir_all(&dir).ok();
}
