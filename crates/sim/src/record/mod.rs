//! Time-series recorder of named signals, written as CSV and SVG plots (thesis 2.1: the
//! simulation outputs of Fig. 2.1).
//!
//! A [`Recorder`] holds one time column and any number of `f64` columns. A sample row is
//! started with [`Recorder::sample`]; values are then set by name ([`Recorder::set`],
//! [`Recorder::set_vector`]) or by pre-registered id ([`Recorder::set_id`]). Signals may be
//! registered up front or on first set; a vector signal `q` of length `n` expands to columns
//! `q[0]`..`q[n-1]`. A column registered after earlier rows, or not set in a row, holds NaN
//! there (written as `NaN` in the CSV), so missing data stays visible. Storage is
//! column-major `Vec`s with amortised growth; setting by id or by an existing name does not
//! allocate.

mod error;
mod plot;

pub use error::RecordError;

use std::collections::HashMap;
use std::io::Write;
use std::path::Path;

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

/// Named scalar signals sampled at common times.
#[derive(Debug, Clone, Default)]
pub struct Recorder {
    time: Vec<f64>,
    names: Vec<String>,
    columns: Vec<Vec<f64>>,
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
        for c in col_names {
            self.columns_by_name.insert(c.clone(), self.names.len());
            self.names.push(c);
            let mut col = Vec::with_capacity(self.capacity.max(self.time.len()));
            col.resize(self.time.len(), f64::NAN);
            self.columns.push(col);
        }
        self.signals.insert(name.to_string(), s);
        Ok(s)
    }

    /// Starts a new sample row at time `t` (non-decreasing); its values default to NaN.
    pub fn sample(&mut self, t: f64) -> Result<(), RecordError> {
        let prev = self.time.last().copied().unwrap_or(f64::NEG_INFINITY);
        if !t.is_finite() || t < prev {
            return Err(RecordError::InvalidTime { t, prev });
        }
        self.time.push(t);
        self.columns.iter_mut().for_each(|c| c.push(f64::NAN));
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
        if id.0 + values.len() > self.columns.len() {
            let name = self.names.get(id.0).cloned().unwrap_or_default();
            let expected = self.columns.len().saturating_sub(id.0);
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
        for (col, &v) in self.columns[first..].iter_mut().zip(values) {
            if let Some(last) = col.last_mut() {
                *last = v;
            }
        }
    }

    /// Column `name` (a scalar name or `q[i]`), one value per sample.
    pub fn column(&self, name: &str) -> Result<&[f64], RecordError> {
        self.columns_by_name
            .get(name)
            .map(|&i| self.columns[i].as_slice())
            .ok_or_else(|| RecordError::UnknownSignal(name.into()))
    }

    /// Columns of signal `name`: one for a scalar, `n` for a vector signal.
    pub fn signal_columns(&self, name: &str) -> Result<&[Vec<f64>], RecordError> {
        let s = self
            .signals
            .get(name)
            .ok_or_else(|| RecordError::UnknownSignal(name.into()))?;
        Ok(&self.columns[s.first..s.first + s.len])
    }

    /// Writes `time,<columns>` and one line per sample with shortest round-trip `f64` text
    /// ([`push_f64`]).
    pub fn write_csv(&self, path: &Path) -> Result<(), RecordError> {
        if self.is_empty() {
            return Err(RecordError::Empty);
        }
        let io = |source| RecordError::Io {
            path: path.to_path_buf(),
            source,
        };
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(io)?;
        }
        let file = std::fs::File::create(path).map_err(io)?;
        let mut w = std::io::BufWriter::new(file);
        self.csv_to(&mut w).and_then(|_| w.flush()).map_err(io)
    }

    /// Writes the CSV text to `w`, one row buffer per line.
    fn csv_to(&self, w: &mut impl Write) -> std::io::Result<()> {
        write!(w, "time")?;
        for n in &self.names {
            write!(w, ",{n}")?;
        }
        writeln!(w)?;
        let mut row = Vec::with_capacity(32 * (self.columns.len() + 1));
        for (r, &t) in self.time.iter().enumerate() {
            row.clear();
            push_f64(&mut row, t)?;
            for c in &self.columns {
                row.push(b',');
                push_f64(&mut row, c[r])?;
            }
            row.push(b'\n');
            w.write_all(&row)?;
        }
        Ok(())
    }
}

/// Appends the shortest text that parses back to exactly `x` (serde_json's float formatter;
/// `NaN`, `inf`, `-inf` as Rust prints them, which JSON cannot represent).
pub fn push_f64(out: &mut Vec<u8>, x: f64) -> std::io::Result<()> {
    if x.is_finite() {
        serde_json::to_writer(out, &x).map_err(std::io::Error::other)
    } else {
        let text: &[u8] = match (x.is_nan(), x > 0.0) {
            (true, _) => b"NaN",
            (false, true) => b"inf",
            (false, false) => b"-inf",
        };
        out.extend_from_slice(text);
        Ok(())
    }
}
