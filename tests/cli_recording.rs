//! The recordings for replay (docs/recording.md) that `biped walk` and `biped simulate` write:
//! 100 frames per second of the full tables, every body's pose, and a fraction of their size.
//! The poses are checked against quantities the runs compute on other paths: the sole frames
//! of the walk's IK and the centre of mass (of the IK's centroidal task, of the simulation's
//! signals), recomputed here from the recorded body poses and the model's body inertias.

use biped_dynamics::Model;
use biped_robots::lola::{self, LolaType};
use biped_robots::plant::lola_plant;
use biped_sim::plant::PlantConfig;
use flate2::read::GzDecoder;
use nalgebra::{Point3, Quaternion, UnitQuaternion, Vector3};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Column names and rows of a CSV table (gzip-compressed if its name ends in `.gz`).
struct Table(Vec<String>, Vec<Vec<f64>>);

impl Table {
    fn read(path: &Path) -> Table {
        let mut text = String::new();
        let file = std::fs::File::open(path).unwrap_or_else(|e| panic!("{path:?}: {e}"));
        match path.extension().is_some_and(|e| e == "gz") {
            true => GzDecoder::new(file).read_to_string(&mut text),
            false => std::io::BufReader::new(file).read_to_string(&mut text),
        }
        .unwrap();
        let mut lines = text.lines();
        let header = lines.next().unwrap().split(',').map(String::from).collect();
        let rows = lines
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect();
        Table(header, rows)
    }

    fn col(&self, name: &str) -> usize {
        self.0
            .iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("no column {name}"))
    }

    /// The row whose time is `t` (to 1 µs).
    fn at(&self, t: f64) -> &[f64] {
        let k = self.1.iter().position(|r| (r[0] - t).abs() < 1e-6);
        &self.1[k.unwrap_or_else(|| panic!("no row at t = {t}"))]
    }
}

fn run(args: &[&str], dir: &Path) {
    let _ = std::fs::remove_dir_all(dir);
    let out = Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(args)
        .arg("--out")
        .arg(dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{args:?}: {err}");
}

fn temp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("biped_recording_{name}_{}", std::process::id()))
}

/// The pose of body `b` in row `row` of `rec`.
fn pose(rec: &Table, row: &[f64], b: &str) -> (Vector3<f64>, UnitQuaternion<f64>) {
    let f = |k: &str| row[rec.col(&format!("body[{b}].{k}"))];
    let q = Quaternion::new(f("qw"), f("qx"), f("qy"), f("qz"));
    (
        Vector3::new(f("x"), f("y"), f("z")),
        UnitQuaternion::from_quaternion(q),
    )
}

/// The centre of mass of `model` from the body poses of `row`.
fn com(model: &Model, rec: &Table, row: &[f64]) -> Vector3<f64> {
    let (mut sum, mut mass) = (Vector3::zeros(), 0.0);
    for (b, name) in model.bodies().iter().zip(model.body_names()) {
        let (p, r) = pose(rec, row, name);
        let i = b.inertia();
        sum += i.mass() * (p + r * i.com());
        mass += i.mass();
    }
    sum / mass
}

/// Every recorded frame is 10 ms after the previous one but the last, which ends the table.
fn check_frames(rec: &Table, full: &Table) {
    let t: Vec<f64> = rec.1.iter().map(|r| r[0]).collect();
    let last = full.1.last().unwrap()[0];
    assert!((t[t.len() - 1] - last).abs() < 1e-6, "last frame at {last}");
    for w in t[..t.len() - 1].windows(2) {
        assert!((w[1] - w[0] - 0.01).abs() < 1e-6, "frames {w:?}");
    }
}

/// Every column of `full` the recording has equals it at the frame's time, to the rounding:
/// half a unit of the 7th significant digit of the column's largest magnitude, or of 1.
fn check_values(rec: &Table, full: &Table) {
    for (k, name) in full.0.iter().enumerate().skip(1) {
        let Some(c) = rec.0.iter().position(|n| n == name) else {
            continue;
        };
        let largest = full.1.iter().map(|r| r[k].abs()).fold(1.0, f64::max);
        let tol = 0.5e-6 * 10f64.powf(largest.log10().floor()) * (1.0 + 1e-9);
        for row in &rec.1 {
            let src = full.at(row[0]);
            assert!((row[c] - src[k]).abs() <= tol, "{name} at {}", row[0]);
        }
    }
}

fn size(path: &Path) -> u64 {
    std::fs::metadata(path).unwrap().len()
}

#[test]
fn walk_recordings_hold_every_body_pose_at_100_hz() {
    let dir = temp("walk");
    run(&["walk", "--steps", "2", "--method", "compensation"], &dir);
    let rec = Table::read(&dir.join("compensation_recording.csv.gz"));
    let full = Table::read(&dir.join("compensation_trajectory.csv"));
    let series = Table::read(&dir.join("compensation.csv"));
    check_frames(&rec, &full);
    check_values(&rec, &full);
    check_values(&rec, &series);
    let model = lola::build(LolaType::Type2).unwrap().model;
    let bodies = rec.0.iter().filter(|c| c.starts_with("body[")).count();
    assert_eq!(bodies, 7 * model.nbodies());
    for row in &rec.1 {
        let src = full.at(row[0]);
        // The sole frames of the IK's kinematics.
        for (side, body) in [("l_sole", "l_sole"), ("r_sole", "r_sole")] {
            let (p, r) = pose(&rec, row, body);
            let s = |k: &str| src[full.col(&format!("{side}.{k}"))];
            let want = Vector3::new(s("x"), s("y"), s("z"));
            assert!((p - want).norm() < 1e-5, "{body} at {}", row[0]);
            let q = Quaternion::new(s("qw"), s("qx"), s("qy"), s("qz"));
            let angle = r.angle_to(&UnitQuaternion::from_quaternion(q));
            assert!(angle < 1e-5, "{body} at {}: {angle}", row[0]);
        }
        // The centre of mass of the IK's centroidal task.
        let want = Vector3::new(
            src[full.col("com.x")],
            src[full.col("com.y")],
            src[full.col("com.z")],
        );
        let got = com(&model, &rec, row);
        assert!((got - want).norm() < 1e-5, "CoM at {}", row[0]);
    }
    let tables =
        size(&dir.join("compensation_trajectory.csv")) + size(&dir.join("compensation.csv"));
    let recording = size(&dir.join("compensation_recording.csv.gz"));
    assert!(
        10 * recording < tables,
        "{recording} bytes against {tables}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn simulate_recording_matches_its_signals() {
    let dir = temp("simulate");
    run(&["simulate", "--duration", "0.3"], &dir);
    let rec = Table::read(&dir.join("recording.csv.gz"));
    let full = Table::read(&dir.join("signals.csv"));
    assert_eq!(rec.1.len(), 31);
    check_frames(&rec, &full);
    check_values(&rec, &full);
    let plant = lola_plant(LolaType::Type2, PlantConfig::default())
        .unwrap()
        .plant;
    let model = plant.model();
    for row in &rec.1 {
        let src = full.at(row[0]);
        let want = Vector3::new(
            src[full.col("com.x")],
            src[full.col("com.y")],
            src[full.col("com.z")],
        );
        let got = com(model, &rec, row);
        assert!(
            (got - want).norm() < 1e-5,
            "CoM at {}: {got} {want}",
            row[0]
        );
    }
    // The pelvis is the floating base: its pose is the recorded q[root.*].
    let row = rec.1.last().unwrap();
    let (p, _) = pose(&rec, row, "pelvis");
    let root = Point3::new(
        row[rec.col("q[root.x]")],
        row[rec.col("q[root.y]")],
        row[rec.col("q[root.z]")],
    );
    assert!((p - root.coords).norm() < 1e-5);
    assert!(8 * size(&dir.join("recording.csv.gz")) < size(&dir.join("signals.csv")));
    let _ = std::fs::remove_dir_all(&dir);
}
