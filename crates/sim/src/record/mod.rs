//! Time-series recorder of named signals, written as CSV and SVG plots (thesis 2.1: the
//! simulation outputs of Fig. 2.1).
//!
//! A [`Recorder`] holds one time column and any number of `f64` columns. A sample row is
//! started with [`Recorder::sample`]; values are then set by name ([`Recorder::set`],
//! [`Recorder::set_vector`]) or by pre-registered id ([`Recorder::set_id`]). Signals may be
//! registered up front or on first set; a vector signal `q` of length `n` expands to columns
//! `q[0]`..`q[n-1]`. A column registered after earlier rows, or not set in a row, holds NaN
//! there (written as `NaN` in the CSV), so missing data stays visible. Storage is one
//! row-major buffer with amortised growth (a sample writes one contiguous row rather than one
//! value into each of a simulation's 135 column streams, which misses the cache); setting by id
//! or by an existing name does not allocate, and registering a column after rows exist re-lays
//! the buffer once.

mod csv;
mod error;
pub mod plot;
pub mod replay;

pub use csv::{push_f64, write_whole};
pub use error::RecordError;

use std::collections::HashMap;

/// Index of a column of a [`Recorder`], from [`Recorder::register`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct SignalId(usize);

impl SignalId {
    /// Position of the signal's (first) column in [`Recorder::column_names`].
    pub fn column(self) -> usize {
        self.0
    }
}

/// A registered signal: a scalar column or a block of vector columns.
#[derive(Debug, Clone, Copy)]
struct Signal {
    first: usize,
    len: usize,
}

/// Grows `v`'s allocation to at least `total` entries and writes them once, keeping its length.
fn touch(v: &mut Vec<f64>, total: usize) {
    let len = v.len();
    if total > len {
        v.resize(total, f64::NAN);
        v.truncate(len);
    }
}

/// Named scalar signals sampled at common times.
#[derive(Debug, Clone, Default)]
pub struct Recorder {
    time: Vec<f64>,
    names: Vec<String>,
    /// Row-major values: row `r` is `rows[r * width..(r + 1) * width]`, `width = names.len()`.
    rows: Vec<f64>,
    columns_by_name: HashMap<String, usize>,
    signals: HashMap<String, Signal>,
    capacity: usize,
}

impl Recorder {
    /// Empty recorder.
    pub fn new() -> Self {
        Self::default()
    }

    /// Empty recorder reserving `rows` samples per column.
    pub fn with_capacity(rows: usize) -> Self {
        Recorder {
            time: Vec::with_capacity(rows),
            capacity: rows,
            ..Self::default()
        }
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.time.len()
    }

    /// Whether no sample was taken.
    pub fn is_empty(&self) -> bool {
        self.time.is_empty()
    }

    /// Sample times.
    pub fn time(&self) -> &[f64] {
        &self.time
    }

    /// Column names in order (without `time`).
    pub fn column_names(&self) -> &[String] {
        &self.names
    }

    /// Registers scalar signal `name` (idempotent for an existing scalar).
    pub fn register(&mut self, name: &str) -> Result<SignalId, RecordError> {
        self.register_vector(name, 1)
    }

    /// Registers vector signal `name` of length `len`, columns `name[0]`.. (length 1 with a
    /// plain name is a scalar); returns the id of its first column.
    pub fn register_vector(&mut self, name: &str, len: usize) -> Result<SignalId, RecordError> {
        self.signal(name, len).map(|s| SignalId(s.first))
    }

    /// Looks up or creates the signal `name` with `len` columns.
    fn signal(&mut self, name: &str, len: usize) -> Result<Signal, RecordError> {
        if let Some(&s) = self.signals.get(name) {
            return if s.len == len {
                Ok(s)
            } else {
                Err(RecordError::LengthMismatch {
                    name: name.into(),
                    expected: s.len,
                    got: len,
                })
            };
        }
        let bad = name.is_empty() || name == "time" || name.contains([',', '"', '\n', '\r']);
        let col_names: Vec<String> = match len {
            1 => vec![name.to_string()],
            _ => (0..len).map(|i| format!("{name}[{i}]")).collect(),
        };
        if bad
            || col_names
                .iter()
                .any(|c| self.columns_by_name.contains_key(c))
        {
            return Err(RecordError::InvalidName(name.into()));
        }
        let s = Signal {
            first: self.names.len(),
            len,
        };
        let old = self.names.len();
        for c in col_names {
            self.columns_by_name.insert(c.clone(), self.names.len());
            self.names.push(c);
        }
        self.widen(old);
        self.signals.insert(name.to_string(), s);
        Ok(s)
    }

    /// Allocates the rows reserved by [`Self::with_capacity`] for the columns registered so far
    /// and writes them once, so that the operating system maps the memory now rather than on
    /// first use inside a timed or real-time loop (one page fault per 4 KiB otherwise).
    /// Recorded values are unaffected; call it after registering the signals.
    pub fn prefault(&mut self) {
        touch(&mut self.rows, self.capacity * self.names.len());
        touch(&mut self.time, self.capacity);
    }

    /// Starts a new sample row at time `t` (non-decreasing); its values default to NaN.
    pub fn sample(&mut self, t: f64) -> Result<(), RecordError> {
        let prev = self.time.last().copied().unwrap_or(f64::NEG_INFINITY);
        if !t.is_finite() || t < prev {
            return Err(RecordError::InvalidTime { t, prev });
        }
        if self.rows.capacity() == 0 {
            self.rows.reserve(self.capacity * self.names.len());
        }
        self.time.push(t);
        let width = self.names.len();
        self.rows.resize(self.rows.len() + width, f64::NAN);
        Ok(())
    }

    /// Sets scalar `name` in the current row (registering it on first use).
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), RecordError> {
        self.set_vector(name, &[value])
    }

    /// Sets vector `name` (columns `name[i]`) in the current row, registering it on first use.
    pub fn set_vector(&mut self, name: &str, values: &[f64]) -> Result<(), RecordError> {
        if self.time.is_empty() {
            return Err(RecordError::Empty);
        }
        let s = self.signal(name, values.len())?;
        self.write(s.first, values);
        Ok(())
    }

    /// Sets the columns starting at `id` in the current row (no lookup, no allocation).
    pub fn set_id(&mut self, id: SignalId, values: &[f64]) -> Result<(), RecordError> {
        if self.time.is_empty() {
            return Err(RecordError::Empty);
        }
        if id.0 + values.len() > self.names.len() {
            let name = self.names.get(id.0).cloned().unwrap_or_default();
            let expected = self.names.len().saturating_sub(id.0);
            return Err(RecordError::LengthMismatch {
                name,
                expected,
                got: values.len(),
            });
        }
        self.write(id.0, values);
        Ok(())
    }

    /// Writes `values` into the last row of columns `first..`.
    fn write(&mut self, first: usize, values: &[f64]) {
        let width = self.names.len();
        let Some(start) = self.rows.len().checked_sub(width) else {
            return;
        };
        let row = &mut self.rows[start..];
        let n = values.len().min(width.saturating_sub(first));
        row[first..first + n].copy_from_slice(&values[..n]);
    }

    /// Re-lays the rows for columns `old..` added after the first `old` (NaN in earlier rows).
    fn widen(&mut self, old: usize) {
        let (width, n) = (self.names.len(), self.time.len());
        if n == 0 || width == old {
            return;
        }
        let mut rows = Vec::with_capacity(self.capacity.max(n) * width);
        for r in self.rows.chunks_exact(old.max(1)).take(n) {
            rows.extend_from_slice(&r[..old]);
            rows.resize(rows.len() + width - old, f64::NAN);
        }
        if old == 0 {
            rows.resize(n * width, f64::NAN);
        }
        self.rows = rows;
    }

    /// Values of column `c`, one per sample.
    fn gather(&self, c: usize) -> Vec<f64> {
        let width = self.names.len();
        self.rows.iter().skip(c).step_by(width).copied().collect()
    }

    /// The values of sample `r` in column order (empty past the last sample).
    pub fn row(&self, r: usize) -> &[f64] {
        let width = self.names.len();
        self.rows.get(r * width..(r + 1) * width).unwrap_or(&[])
    }

    /// Column `name` (a scalar name or `q[i]`), one value per sample.
    pub fn column(&self, name: &str) -> Result<Vec<f64>, RecordError> {
        self.columns_by_name
            .get(name)
            .map(|&i| self.gather(i))
            .ok_or_else(|| RecordError::UnknownSignal(name.into()))
    }

    /// Columns of signal `name`: one for a scalar, `n` for a vector signal.
    pub fn signal_columns(&self, name: &str) -> Result<Vec<Vec<f64>>, RecordError> {
        let s = self
            .signals
            .get(name)
            .ok_or_else(|| RecordError::UnknownSignal(name.into()))?;
        Ok((s.first..s.first + s.len).map(|c| self.gather(c)).collect())
    }
}
