//! Recordings for replay by a viewer or a script (`docs/recording.md`): the rows of a table
//! at about [`FRAME_RATE`] frames per second, every value rounded to [`DIGITS`] significant
//! digits, with the world pose of every body of the model added as `body[NAME].x` .. `.qw`
//! columns, computed by forward kinematics of the table's `q[NAME]` columns.

use super::{write_whole, RecordError, Recorder};
use biped_dynamics::{update_placements, Data, Model};
use flate2::{write::GzEncoder, Compression};
use nalgebra::{DVector, Isometry3};
use std::io::Write;
use std::path::Path;

/// Frames per second of a recording (every k-th row of a table sampled faster, and the last).
pub const FRAME_RATE: f64 = 100.0;

/// Significant digits of a recording's values: of the largest magnitude in each column, or of
/// 1 if that is smaller (a resolution of `1e-6` in SI units).
pub const DIGITS: i32 = 7;

/// Fields of a body pose in a recording: position \[m] and unit quaternion.
pub const POSE_FIELDS: [&str; 7] = ["x", "y", "z", "qx", "qy", "qz", "qw"];

/// Column of field `field` (one of [`POSE_FIELDS`]) of the pose of body `body`.
pub fn pose_column(body: &str, field: &str) -> String {
    format!("body[{body}].{field}")
}

/// `x` rounded to `digits` significant digits; zero and non-finite values stay as they are.
pub fn round_significant(x: f64, digits: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    // Decimal formatting rounds exactly (scaling by a power of ten would not).
    let text = format!("{:.*e}", (digits.max(1) - 1) as usize, x);
    text.parse().unwrap_or(x)
}

/// Time `t` rounded to the microsecond, so that it prints short (`12.34`, not
/// `12.340000000000002`).
fn round_time(t: f64) -> f64 {
    (t * 1e6).round() / 1e6
}

/// Rows of samples at `time` (non-decreasing) kept for `rate` frames per second: every k-th
/// row, k the largest stride whose mean spacing is at most `1 / rate` (at least 1), and the
/// last row.
pub fn frame_rows(time: &[f64], rate: f64) -> Vec<usize> {
    let n = time.len();
    if n < 2 {
        return (0..n).collect();
    }
    let dt = (time[n - 1] - time[0]) / (n - 1) as f64;
    let stride = match dt > 0.0 && dt.is_finite() && rate > 0.0 {
        true => ((1.0 / rate) / dt + 1e-6).floor().max(1.0) as usize,
        false => 1,
    };
    let mut rows: Vec<usize> = (0..n).step_by(stride).collect();
    if rows.last() != Some(&(n - 1)) {
        rows.push(n - 1);
    }
    rows
}

/// Scales the quaternion of every free joint in `q` to unit length (the identity if it is
/// zero or not finite): rounded values are not unit, and forward kinematics needs unit ones.
pub fn normalize_quaternions(model: &Model, q: &mut DVector<f64>) {
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

/// `x, y, z, qx, qy, qz, qw` of a pose (the order of [`POSE_FIELDS`]).
pub fn pose_fields(p: &Isometry3<f64>) -> [f64; 7] {
    let (t, q) = (&p.translation.vector, &p.rotation);
    [t.x, t.y, t.z, q.i, q.j, q.k, q.w]
}

/// For every coordinate of `model`, the column of `table` named `q[NAME]`.
fn coordinate_columns(model: &Model, table: &Recorder) -> Vec<Option<usize>> {
    let names = table.column_names();
    let find = |n: &String| names.iter().position(|c| *c == format!("q[{n}]"));
    model.q_names().iter().map(find).collect()
}

/// The recording of `table` (one row per sample, with `q[NAME]` columns of `model`'s
/// coordinates; the others neutral): its rows at `rate` frames per second ([`frame_rows`]),
/// then the pose of every body of `model`; each column rounded to [`DIGITS`] significant
/// digits of its largest magnitude ([`round_in_column`]), the time to the microsecond.
/// Fails if no column names a coordinate or a row's positions cannot be placed.
pub fn replay(model: &Model, table: &Recorder, rate: f64) -> Result<Recorder, RecordError> {
    let map = coordinate_columns(model, table);
    if map.iter().all(Option::is_none) {
        let some: Vec<String> = model.q_names().into_iter().take(3).collect();
        return Err(RecordError::Replay(format!(
            "no q[NAME] column names a coordinate of the model (q[{}], ...)",
            some.join("], q[")
        )));
    }
    let rows = frame_rows(table.time(), rate);
    let nb = model.nbodies();
    let width = table.column_names().len() + POSE_FIELDS.len() * nb;
    let mut values = Vec::with_capacity(rows.len() * width);
    let mut data = Data::new(model);
    let neutral = model.neutral();
    for &r in &rows {
        let row = table.row(r);
        let mut q = neutral.clone();
        for (k, col) in map.iter().enumerate() {
            if let Some(c) = col {
                q[k] = row[*c];
            }
        }
        normalize_quaternions(model, &mut q);
        update_placements(model, &mut data, &q)
            .map_err(|e| RecordError::Replay(format!("row at t = {} s: {e}", table.time()[r])))?;
        values.extend_from_slice(row);
        for b in 0..nb {
            values.extend(pose_fields(&data.body_pose(b)));
        }
    }
    let exponents = column_exponents(&values, width);
    let mut out = Recorder::with_capacity(rows.len());
    let mut names: Vec<String> = table.column_names().to_vec();
    for b in model.body_names() {
        names.extend(POSE_FIELDS.map(|f| pose_column(b, f)));
    }
    let ids = names
        .iter()
        .map(|n| out.register(n))
        .collect::<Result<Vec<_>, _>>()?;
    let mut line = vec![0.0; width];
    for (k, &r) in rows.iter().enumerate() {
        out.sample(round_time(table.time()[r]))?;
        let row = &values[k * width..(k + 1) * width];
        for ((dst, &x), &e) in line.iter_mut().zip(row).zip(&exponents) {
            *dst = round_in_column(x, e);
        }
        if let Some(&first) = ids.first() {
            out.set_id(first, &line)?;
        }
    }
    Ok(out)
}

/// Decimal exponent of the largest finite magnitude of every column of `values` (`width` per
/// row), at least 0: a column of values below 1 (SI units) keeps the resolution `1e-6` of one
/// of magnitude 1 (a µm, a µrad), not that of its round-off noise.
fn column_exponents(values: &[f64], width: usize) -> Vec<i32> {
    let mut largest = vec![0.0_f64; width];
    for row in values.chunks_exact(width.max(1)) {
        for (m, x) in largest.iter_mut().zip(row) {
            if x.is_finite() {
                *m = m.max(x.abs());
            }
        }
    }
    let exponent = |m: f64| if m > 1.0 { m.log10().floor() as i32 } else { 0 };
    largest.into_iter().map(exponent).collect()
}

/// `x` rounded to [`DIGITS`] significant digits of a column whose largest magnitude has decimal
/// exponent `exp`: a fixed resolution `10^(exp + 1 - DIGITS)` per column, so that round-off
/// noise about zero (`1e-30`) is written as `0`.
pub fn round_in_column(x: f64, exp: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let digits = DIGITS - (exp - x.abs().log10().floor() as i32);
    if digits >= 1 {
        return round_significant(x, digits);
    }
    let quantum = round_significant(10f64.powi(exp + 1 - DIGITS), 1);
    match x.abs() >= 0.5 * quantum {
        true => quantum.copysign(x),
        false => 0.0,
    }
}

/// Writes `rec` to `path` as gzip-compressed CSV (`time,<columns>`, then one line per sample);
/// the file appears complete or not at all ([`write_whole`]).
pub fn write_csv_gz(rec: &Recorder, path: &Path) -> Result<(), RecordError> {
    if rec.is_empty() {
        return Err(RecordError::Empty);
    }
    write_whole(path, |tmp| {
        let file = std::fs::File::create(tmp)?;
        let mut gz = GzEncoder::new(std::io::BufWriter::new(file), Compression::default());
        rec.csv_to(&mut gz)?;
        gz.finish()?.flush()
    })
    .map_err(|source| RecordError::Io {
        path: path.to_path_buf(),
        source,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_keeps_seven_significant_digits() {
        assert_eq!(round_significant(0.123456789, 7), 0.1234568);
        assert_eq!(round_significant(-12345.678, 7), -12345.68);
        assert_eq!(round_significant(1.5e-9, 7), 1.5e-9);
        assert_eq!(round_significant(0.0, 7), 0.0);
        assert!(round_significant(f64::NAN, 7).is_nan());
        assert_eq!(round_time(12.340000000000002), 12.34);
    }

    #[test]
    fn column_rounding_has_one_resolution_per_column() {
        // Largest magnitude 1.2 (exponent 0): resolution 1e-6.
        assert_eq!(round_in_column(1.23456789, 0), 1.234568);
        assert_eq!(round_in_column(0.0123456789, 0), 0.012346);
        assert_eq!(round_in_column(-7.5e-30, 0), 0.0);
        assert_eq!(round_in_column(6e-7, 0), 1e-6);
        assert_eq!(round_in_column(-4e-7, 0), 0.0);
        // Largest magnitude 2500 (exponent 3): resolution 1e-3.
        assert_eq!(round_in_column(0.1234567, 3), 0.123);
        assert_eq!(
            column_exponents(&[1.2, -2500.0, 1e-9, 0.5, 30.0, 0.0], 3),
            [0, 3, 0]
        );
    }

    #[test]
    fn frame_rows_keep_a_hundred_per_second_and_the_last() {
        let t: Vec<f64> = (0..=1005).map(|k| k as f64 * 1e-3).collect();
        let rows = frame_rows(&t, 100.0);
        assert_eq!(&rows[..3], &[0, 10, 20]);
        assert_eq!(rows.last(), Some(&1005));
        assert_eq!(rows.len(), 102);
        let slow: Vec<f64> = (0..5).map(|k| k as f64 * 0.05).collect();
        assert_eq!(frame_rows(&slow, 100.0), vec![0, 1, 2, 3, 4]);
    }
}
