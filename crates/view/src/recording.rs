//! Recordings the viewer plays back: the tables `biped walk` (`METHOD_trajectory.csv`) and
//! `biped simulate` (`signals.csv`) write, their `q[NAME]` columns turned into body poses by
//! forward kinematics at about 100 frames per second.

use crate::csv::{self, Table};
use crate::robot::Robot;
use crate::ViewError;
use biped_dynamics::{update_placements, Data, Model};
use nalgebra::{DVector, Isometry3};
use std::path::{Path, PathBuf};

/// Frames per second kept of a recording sampled faster (every k-th row, plus the last).
pub const FRAME_RATE: f64 = 100.0;

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

/// The recordings at `path`: a folder's `signals.csv` or `*_trajectory.csv` files (sorted by
/// name), or one such table.
pub fn open(path: &Path, robot: &Robot) -> Result<Vec<Recording>, ViewError> {
    let shown = path.display();
    let meta = std::fs::metadata(path)
        .map_err(|e| ViewError::Recording(format!("--recording {shown}: {e}")))?;
    if meta.is_file() {
        return Ok(vec![from_table(path, "recording", robot)?]);
    }
    let entries = std::fs::read_dir(path)
        .map_err(|e| ViewError::Recording(format!("--recording {shown}: {e}")))?;
    let mut files: Vec<(String, PathBuf)> = entries
        .filter_map(|e| e.ok())
        .filter_map(|e| {
            let name = e.file_name().to_string_lossy().to_string();
            let method = name.strip_suffix("_trajectory.csv").map(str::to_string);
            let label = method.or_else(|| (name == "signals.csv").then(|| "signals".into()));
            label.map(|l| (l, e.path()))
        })
        .collect();
    files.sort();
    if files.is_empty() {
        return Err(ViewError::Recording(format!(
            "--recording {shown}: no signals.csv (biped simulate) or METHOD_trajectory.csv \
             (biped walk) in this folder"
        )));
    }
    let read = files
        .iter()
        .map(|(name, file)| from_table(file, name, robot));
    read.collect()
}

/// Reads one table and computes the body poses of its kept frames.
pub fn from_table(file: &Path, name: &str, robot: &Robot) -> Result<Recording, ViewError> {
    let mut table = csv::read(file)?;
    let shown = file.display();
    let time = |t: &Table| t.column("time").or_else(|| t.column("t"));
    let Some(t) = time(&table) else {
        return Err(ViewError::Recording(format!("{shown}: no `time` column")));
    };
    // A walk's METHOD.csv beside METHOD_trajectory.csv adds L_z, tau_z, distances, margins.
    let series = file
        .to_str()
        .and_then(|f| f.strip_suffix("_trajectory.csv"))
        .map(|stem| PathBuf::from(format!("{stem}.csv")))
        .filter(|p| p.is_file());
    if let Some(series) = series {
        let other = csv::read(&series)?;
        let other_t = time(&other).ok_or_else(|| {
            ViewError::Recording(format!("{}: no `time` column", series.display()))
        })?;
        table.join(&other, t, other_t);
    }
    let model = &robot.model;
    let map = coordinate_columns(model, &table);
    if map.iter().all(Option::is_none) {
        return Err(ViewError::Recording(format!(
            "{shown}: no q[NAME] column names a coordinate of {}",
            robot.label
        )));
    }
    let rows = kept_rows(&table, t);
    let mut data = Data::new(model);
    let mut rec = Recording {
        name: name.to_string(),
        file: file.to_path_buf(),
        time: Vec::with_capacity(rows.len()),
        poses: Vec::with_capacity(rows.len()),
        columns: table.columns.clone(),
        values: Vec::with_capacity(rows.len()),
    };
    let neutral = model.neutral();
    for r in rows {
        let row = &table.rows[r];
        let mut q = neutral.clone();
        for (k, col) in map.iter().enumerate() {
            if let Some(c) = col {
                q[k] = row[*c];
            }
        }
        normalize_quaternions(model, &mut q);
        update_placements(model, &mut data, &q)
            .map_err(|e| ViewError::Recording(format!("{shown}: row at time {}: {e}", row[t])))?;
        rec.time.push(row[t]);
        rec.poses
            .push((0..model.nbodies()).map(|b| data.body_pose(b)).collect());
        rec.values.push(row.clone());
    }
    Ok(rec)
}

/// For every coordinate of `q`, the table column `q[NAME]` holding it.
fn coordinate_columns(model: &Model, table: &Table) -> Vec<Option<usize>> {
    let names = model.q_names();
    names
        .iter()
        .map(|n| table.column(&format!("q[{n}]")))
        .collect()
}

/// Every k-th row so that about [`FRAME_RATE`] frames per second remain, and the last row.
fn kept_rows(table: &Table, t: usize) -> Vec<usize> {
    let n = table.rows.len();
    if n < 2 {
        return (0..n).collect();
    }
    let span = table.rows[n - 1][t] - table.rows[0][t];
    let dt = span / (n - 1) as f64;
    let stride = if dt > 0.0 && dt.is_finite() {
        ((1.0 / FRAME_RATE) / dt + 1e-6).floor().max(1.0) as usize
    } else {
        1
    };
    let mut rows: Vec<usize> = (0..n).step_by(stride).collect();
    if rows.last() != Some(&(n - 1)) {
        rows.push(n - 1);
    }
    rows
}

/// Scales the quaternion of every free joint to unit length (identity if it is zero or not
/// finite): recorded values are rounded, and forward kinematics needs unit quaternions.
fn normalize_quaternions(model: &Model, q: &mut DVector<f64>) {
    for j in model.joints().iter().filter(|j| j.nq == 7) {
        let mut quat = q.rows_mut(j.q_index + 3, 4);
        let norm = quat.norm();
        if norm > 0.0 && norm.is_finite() {
            quat /= norm;
        } else {
            quat.copy_from_slice(&[0.0, 0.0, 0.0, 1.0]);
        }
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
