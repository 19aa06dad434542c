//! Recordings the viewer plays back: the recordings for replay that `biped walk`
//! (`METHOD_recording.csv.gz`) and `biped simulate` (`recording.csv.gz`) write, with every
//! body's pose (docs/recording.md), or their full tables (`METHOD_trajectory.csv`,
//! `signals.csv`), whose `q[NAME]` columns are turned into body poses by forward kinematics;
//! at about 100 frames per second.

use crate::csv::{self, Table};
use crate::robot::Robot;
use crate::ViewError;
use biped_dynamics::{update_placements, Data, Model};
use biped_sim::record::replay::{frame_rows, normalize_quaternions, pose_column, POSE_FIELDS};
use nalgebra::{DVector, Isometry3, Quaternion, Translation3, UnitQuaternion};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

pub use biped_sim::record::replay::FRAME_RATE;

/// The recording `biped simulate` writes (docs/recording.md).
pub const RECORDING_FILE: &str = "recording.csv.gz";

/// One recording: per kept frame its time, the world pose of every robot body and the values
/// of every column of the table.
#[derive(Debug, Clone)]
pub struct Recording {
    /// Name: the walk's arm method, or `signals` for a simulation.
    pub name: String,
    /// The table it was read from.
    pub file: PathBuf,
    /// Time of each frame in s.
    pub time: Vec<f64>,
    /// Per frame, the world pose of every robot body.
    pub poses: Vec<Vec<Isometry3<f64>>>,
    /// Column names of the table.
    pub columns: Vec<String>,
    /// Per frame, the table's row.
    pub values: Vec<Vec<f64>>,
}

impl Recording {
    /// A column's values over the frames.
    pub fn series(&self, name: &str) -> Option<Vec<f64>> {
        let k = self.columns.iter().position(|c| c == name)?;
        Some(self.values.iter().map(|row| row[k]).collect())
    }
}

/// What a file of a recording folder holds, by its name: the label it is shown under and
/// whether it is a recording for replay (preferred over a table of the same label).
fn classify(name: &str) -> Option<(String, bool)> {
    if name == RECORDING_FILE {
        return Some(("signals".into(), true));
    }
    if let Some(stem) = name.strip_suffix("_recording.csv.gz") {
        return Some((stem.into(), true));
    }
    if name == "signals.csv" {
        return Some(("signals".into(), false));
    }
    let stem = name.strip_suffix("_trajectory.csv")?;
    Some((stem.into(), false))
}

/// The recordings at `path`: a folder's recordings for replay (`recording.csv.gz`,
/// `STEM_recording.csv.gz`), or where a label has none its table (`signals.csv`,
/// `METHOD_trajectory.csv`), sorted by label; or one such file.
pub fn open(path: &Path, robot: &Robot) -> Result<Vec<Recording>, ViewError> {
    let shown = path.display();
    let meta = std::fs::metadata(path)
        .map_err(|e| ViewError::Recording(format!("--recording {shown}: {e}")))?;
    if meta.is_file() {
        return Ok(vec![from_table(path, "recording", robot)?]);
    }
    let entries = std::fs::read_dir(path)
        .map_err(|e| ViewError::Recording(format!("--recording {shown}: {e}")))?;
    let mut files: BTreeMap<String, (bool, PathBuf)> = BTreeMap::new();
    for e in entries.filter_map(|e| e.ok()) {
        let name = e.file_name().to_string_lossy().to_string();
        let Some((label, replay)) = classify(&name) else {
            continue;
        };
        if files.get(&label).is_none_or(|(r, _)| replay && !r) {
            files.insert(label, (replay, e.path()));
        }
    }
    if files.is_empty() {
        return Err(ViewError::Recording(format!(
            "--recording {shown}: no recording ({RECORDING_FILE} of biped simulate, \
             METHOD_recording.csv.gz of biped walk) or table (signals.csv, \
             METHOD_trajectory.csv) in this folder"
        )));
    }
    let read = files
        .iter()
        .map(|(name, (_, file))| from_table(file, name, robot));
    read.collect()
}

/// Reads one recording or table (`.csv` or `.csv.gz`): the body poses of its kept frames
/// from its `body[NAME]` columns when it has them for every body of the robot, or else by
/// forward kinematics of its `q[NAME]` columns.
pub fn from_table(file: &Path, name: &str, robot: &Robot) -> Result<Recording, ViewError> {
    let mut table = csv::read(file)?;
    let shown = file.display();
    let time = |t: &Table| t.column("time").or_else(|| t.column("t"));
    let Some(t) = time(&table) else {
        return Err(ViewError::Recording(format!("{shown}: no `time` column")));
    };
    join_series(file, &mut table, t)?;
    let model = &robot.model;
    let bodies = body_columns(model, &table);
    let map = coordinate_columns(model, &table);
    if bodies.is_none() && map.iter().all(Option::is_none) {
        return Err(ViewError::Recording(format!(
            "{shown}: no q[NAME] column names a coordinate of {}",
            robot.label
        )));
    }
    let times: Vec<f64> = table.rows.iter().map(|r| r[t]).collect();
    let rows = frame_rows(&times, FRAME_RATE);
    let mut data = Data::new(model);
    let kept: Vec<usize> = (0..table.columns.len())
        .filter(|&c| !table.columns[c].starts_with("body["))
        .collect();
    let mut rec = Recording {
        name: name.to_string(),
        file: file.to_path_buf(),
        time: Vec::with_capacity(rows.len()),
        poses: Vec::with_capacity(rows.len()),
        columns: kept.iter().map(|&c| table.columns[c].clone()).collect(),
        values: Vec::with_capacity(rows.len()),
    };
    let neutral = model.neutral();
    for r in rows {
        let row = &table.rows[r];
        let poses = match &bodies {
            Some(cols) => cols.iter().map(|c| pose_of(row, c)).collect(),
            None => {
                let q = coordinates(model, &map, row, &neutral);
                update_placements(model, &mut data, &q).map_err(|e| {
                    ViewError::Recording(format!("{shown}: row at time {}: {e}", row[t]))
                })?;
                (0..model.nbodies()).map(|b| data.body_pose(b)).collect()
            }
        };
        rec.time.push(row[t]);
        rec.poses.push(poses);
        rec.values.push(kept.iter().map(|&c| row[c]).collect());
    }
    Ok(rec)
}

/// Joins a walk's `METHOD.csv` (`L_z`, `tau_z`, distances, margins) to the table of
/// `METHOD_trajectory.csv` beside it.
fn join_series(file: &Path, table: &mut Table, t: usize) -> Result<(), ViewError> {
    let series = file
        .to_str()
        .and_then(|f| f.strip_suffix("_trajectory.csv"))
        .map(|stem| PathBuf::from(format!("{stem}.csv")))
        .filter(|p| p.is_file());
    let Some(series) = series else {
        return Ok(());
    };
    let other = csv::read(&series)?;
    let other_t = other.column("time").or_else(|| other.column("t"));
    let other_t = other_t
        .ok_or_else(|| ViewError::Recording(format!("{}: no `time` column", series.display())))?;
    table.join(&other, t, other_t);
    Ok(())
}

/// For every coordinate of `q`, the table column `q[NAME]` holding it.
fn coordinate_columns(model: &Model, table: &Table) -> Vec<Option<usize>> {
    let names = model.q_names();
    names
        .iter()
        .map(|n| table.column(&format!("q[{n}]")))
        .collect()
}

/// The positions of `row` (`neutral` where no column holds a coordinate), quaternions unit.
fn coordinates(
    model: &Model,
    map: &[Option<usize>],
    row: &[f64],
    neutral: &DVector<f64>,
) -> DVector<f64> {
    let mut q = neutral.clone();
    for (k, col) in map.iter().enumerate() {
        if let Some(c) = col {
            q[k] = row[*c];
        }
    }
    normalize_quaternions(model, &mut q);
    q
}

/// The `body[NAME].x` .. `.qw` columns of every body of `model`, if the table has them all.
fn body_columns(model: &Model, table: &Table) -> Option<Vec<[usize; 7]>> {
    let find = |b: &str| -> Option<[usize; 7]> {
        let mut cols = [0; 7];
        for (c, f) in cols.iter_mut().zip(POSE_FIELDS) {
            *c = table.column(&pose_column(b, f))?;
        }
        Some(cols)
    };
    model.body_names().into_iter().map(find).collect()
}

/// The pose in columns `c` (`x, y, z, qx, qy, qz, qw`) of `row`, its quaternion scaled to
/// unit length (the identity if it is zero or not finite).
fn pose_of(row: &[f64], c: &[usize; 7]) -> Isometry3<f64> {
    let v = c.map(|k| row[k]);
    let quat = Quaternion::new(v[6], v[3], v[4], v[5]);
    let n = quat.norm();
    let rot = match n > 0.0 && n.is_finite() {
        true => UnitQuaternion::new_unchecked(quat / n),
        false => UnitQuaternion::identity(),
    };
    let pos = Translation3::new(v[0], v[1], v[2]);
    match v.iter().all(|x| x.is_finite()) {
        true => Isometry3::from_parts(pos, rot),
        false => Isometry3::identity(),
    }
}

/// The world poses of every body at `q = neutral`; a floating robot is lifted so that its
/// lowest point (of its drawn geometry and its body frames) is at the ground, `z = 0`.
pub fn neutral_poses(robot: &Robot) -> Result<Vec<Isometry3<f64>>, ViewError> {
    let model = &robot.model;
    let mut data = Data::new(model);
    let mut q = model.neutral();
    let floating: Vec<usize> = model
        .joints()
        .iter()
        .filter(|j| j.nq == 7)
        .map(|j| j.q_index)
        .collect();
    let place = |data: &mut Data, q: &DVector<f64>| {
        update_placements(model, data, q).map_err(|e| ViewError::Robot(e.to_string()))
    };
    place(&mut data, &q)?;
    if let Some(&root) = floating.first() {
        let poses: Vec<_> = (0..model.nbodies()).map(|b| data.body_pose(b)).collect();
        let low = crate::ground::lowest_point(robot, &poses);
        if low.is_finite() {
            q[root + 2] -= low;
            place(&mut data, &q)?;
        }
    }
    Ok((0..model.nbodies()).map(|b| data.body_pose(b)).collect())
}
