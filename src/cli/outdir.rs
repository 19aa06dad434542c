//! Output directories written as a whole.
//!
//! A run writes into a hidden sibling of its `--out` directory (`.NAME.partial-PID`) and swaps
//! it into place when it ends, so the directory always holds one run's complete files: the
//! previous run's until the swap, then the new run's. A run that fails or is interrupted
//! (SIGINT / SIGTERM) still swaps its files in, with a `summary.json` whose `"status"` is
//! `"failed"` or `"interrupted"` and whose `"reason"` says why; a finished run's summary says
//! `"status": "completed"`. A lock on the sibling file `.NAME.lock` keeps a second run out of
//! a directory that one is writing. A run killed outright (SIGKILL, a second Ctrl-C) leaves
//! the previous files untouched; the next run into the directory removes its leftovers.

use super::files::WithPath;
use super::interrupt;
use serde_json::{json, Map, Value};
use std::fs::{self, File, TryLockError};
use std::path::{Path, PathBuf};

/// Result of this module: errors are one line that names the directory.
pub type DirResult<T> = Result<T, Box<dyn std::error::Error>>;

/// File that marks a directory as a biped result (so that `--out` never replaces other data).
const MARKER: &str = ".biped-output";

/// How a run ended, as written to `summary.json`'s `"status"`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Every step ran (the verdicts in the summary say whether the run passed its checks).
    Completed,
    /// An error stopped the run; `"reason"` names it.
    Failed,
    /// SIGINT or SIGTERM stopped the run.
    Interrupted,
}

impl Status {
    /// The `"status"` value.
    pub fn name(self) -> &'static str {
        match self {
            Status::Completed => "completed",
            Status::Failed => "failed",
            Status::Interrupted => "interrupted",
        }
    }
}

/// An output directory being written: files go to [`OutputDir::path`] until
/// [`OutputDir::commit`] swaps them into place.
#[derive(Debug)]
pub struct OutputDir {
    /// The directory the user named.
    target: PathBuf,
    /// Where this run writes.
    staging: PathBuf,
    /// Held (flock) for the life of the run.
    _lock: File,
}

impl OutputDir {
    /// Locks `target` for this run and creates its staging sibling; `option` names the
    /// command-line option for errors (e.g. `--out`). Installs the SIGINT/SIGTERM handler.
    pub fn create(target: &Path, option: &str) -> DirResult<Self> {
        let name = target
            .file_name()
            .and_then(|n| n.to_str())
            .filter(|n| !n.is_empty() && *n != "." && *n != "..")
            .ok_or_else(|| format!("{option} {}: name a directory", target.display()))?;
        let parent = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        fs::create_dir_all(&parent).map_err(|e| format!("{option} {}: {e}", target.display()))?;
        let lock_path = parent.join(format!(".{name}.lock"));
        let lock = File::create(&lock_path).map_err(|e| {
            let lock = lock_path.display();
            format!(
                "{option} {}: cannot create its lock file {lock}: {e}",
                target.display()
            )
        })?;
        match lock.try_lock() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => {
                return Err(format!(
                    "{option} {}: another biped run is writing into this directory (lock {})",
                    target.display(),
                    lock_path.display()
                )
                .into())
            }
            Err(TryLockError::Error(e)) => {
                return Err(format!("{option} {}: {e}", lock_path.display()).into())
            }
        }
        let dir = OutputDir {
            target: target.to_path_buf(),
            staging: parent.join(format!(".{name}.partial-{}", std::process::id())),
            _lock: lock,
        };
        dir.recover(&parent, name)?;
        dir.check_replaceable(option)?;
        fs::create_dir(&dir.staging)
            .map_err(|e| format!("{option} {}: {e}", dir.staging.display()))?;
        fs::write(dir.staging.join(MARKER), "").with_path(&dir.staging)?;
        interrupt::install();
        Ok(dir)
    }

    /// Where this run writes its files.
    pub fn path(&self) -> &Path {
        &self.staging
    }

    /// The directory the user named (where the files are after [`OutputDir::commit`]).
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Removes a killed run's leftovers (under the lock, so no live run owns them) and puts
    /// back a previous result that a kill between the two renames of a swap left aside.
    fn recover(&self, parent: &Path, name: &str) -> DirResult<()> {
        let partial = format!(".{name}.partial-");
        let old = format!(".{name}.old-");
        let entries = fs::read_dir(parent).with_path(parent)?;
        for entry in entries.flatten() {
            let file = entry.file_name();
            let file = file.to_string_lossy();
            let path = entry.path();
            if file.starts_with(&old) && !self.target.exists() {
                fs::rename(&path, &self.target).with_path(&path)?;
            } else if file.starts_with(&partial) || file.starts_with(&old) {
                fs::remove_dir_all(&path).with_path(&path)?;
            }
        }
        Ok(())
    }

    /// An existing target must be a biped result or empty: a swap replaces all of it.
    fn check_replaceable(&self, option: &str) -> DirResult<()> {
        let t = &self.target;
        if !t.exists() {
            return Ok(());
        }
        if !t.is_dir() {
            return Err(format!("{option} {}: exists and is not a directory", t.display()).into());
        }
        let mut entries = fs::read_dir(t).map_err(|e| format!("{option} {}: {e}", t.display()))?;
        let ours = t.join(MARKER).exists() || t.join("summary.json").exists();
        if ours || entries.next().is_none() {
            return Ok(());
        }
        Err(format!(
            "{option} {}: the directory holds files that are not a biped result; name a new or empty directory",
            t.display()
        )
        .into())
    }

    /// Swaps the staging directory into place (the previous result is removed).
    pub fn commit(self) -> DirResult<()> {
        let t = &self.target;
        if t.exists() {
            let name = t
                .file_name()
                .map(|n| n.to_string_lossy())
                .unwrap_or_default();
            let aside = self
                .staging
                .with_file_name(format!(".{name}.old-{}", std::process::id()));
            fs::rename(t, &aside).with_path(t)?;
            fs::rename(&self.staging, t).with_path(t)?;
            fs::remove_dir_all(&aside).with_path(&aside)?;
        } else {
            fs::rename(&self.staging, t).with_path(t)?;
        }
        Ok(())
    }

    /// Ends a run that did not complete: writes `summary.json` (`base`'s fields, if any, with
    /// `"status"` and `"reason"`) beside what was written so far and swaps it all into place.
    /// Returns a note for the error line.
    pub fn abandon(self, status: Status, reason: &str, base: Option<Value>) -> String {
        let mut map = match base {
            Some(Value::Object(m)) => m,
            _ => Map::new(),
        };
        stamp(&mut map, status);
        map.insert("reason".into(), json!(reason));
        let target = self.target.clone();
        let written = write_json(&self.staging.join("summary.json"), &Value::Object(map))
            .and_then(|()| self.commit());
        match written {
            Ok(()) => format!(
                " ({} marked {} in its summary.json)",
                target.display(),
                status.name()
            ),
            Err(e) => format!(" (could not write the failed result: {e})"),
        }
    }
}

/// Sets `"status"` of a summary object.
pub fn stamp(summary: &mut Map<String, Value>, status: Status) {
    summary.insert("status".into(), json!(status.name()));
}

/// Writes `value` as pretty JSON (one trailing newline) to `path`.
pub fn write_json(path: &Path, value: &Value) -> DirResult<()> {
    let text = serde_json::to_string_pretty(value).with_path(path)?;
    Ok(fs::write(path, text + "\n").with_path(path)?)
}

/// The error of an interrupted run, once [`interrupt::requested`] says so.
pub fn interrupted_reason() -> &'static str {
    "interrupted by a signal (SIGINT or SIGTERM)"
}
