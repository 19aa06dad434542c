//! CSV output of a [`Recorder`] and the file helpers it shares with the other writers: whole-file
//! writes through a hidden sibling, shortest round-trip `f64` text.

use super::{RecordError, Recorder};
use std::io::Write;
use std::path::Path;

impl Recorder {
    /// Writes `time,<columns>` and one line per sample with shortest round-trip `f64` text
    /// ([`push_f64`]); the file appears complete or not at all ([`write_whole`]).
    pub fn write_csv(&self, path: &Path) -> Result<(), RecordError> {
        if self.is_empty() {
            return Err(RecordError::Empty);
        }
        write_whole(path, |tmp| {
            let file = std::fs::File::create(tmp)?;
            let mut w = std::io::BufWriter::new(file);
            self.csv_to(&mut w).and_then(|_| w.flush())
        })
        .map_err(|source| RecordError::Io {
            path: path.to_path_buf(),
            source,
        })
    }

    /// Writes the CSV text to `w`, one row buffer per line.
    pub(crate) fn csv_to(&self, w: &mut impl Write) -> std::io::Result<()> {
        write!(w, "time")?;
        for n in &self.names {
            write!(w, ",{n}")?;
        }
        writeln!(w)?;
        let width = self.names.len();
        let mut row = Vec::with_capacity(32 * (width + 1));
        for (r, &t) in self.time.iter().enumerate() {
            row.clear();
            push_f64(&mut row, t)?;
            for &x in &self.rows[r * width..(r + 1) * width] {
                row.push(b',');
                push_f64(&mut row, x)?;
            }
            row.push(b'\n');
            w.write_all(&row)?;
        }
        Ok(())
    }
}

/// Writes a file as a whole: `write` fills a hidden sibling (`.NAME.partial-PID`, parent
/// folders created), which is renamed to `path` on success and removed on failure, so `path`
/// holds either its previous content or the complete new one.
pub fn write_whole<E>(path: &Path, write: impl FnOnce(&Path) -> Result<(), E>) -> Result<(), E>
where
    E: From<std::io::Error>,
{
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .map_err(|e| std::io::Error::new(e.kind(), format!("folder {}: {e}", dir.display())))?;
    }
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy())
        .unwrap_or_default();
    let tmp = path.with_file_name(format!(".{name}.partial-{}", std::process::id()));
    let result = write(&tmp).and_then(|()| Ok(std::fs::rename(&tmp, path)?));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
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
