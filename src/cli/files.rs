//! File-system access of the sub-commands: every error names the file or folder it is about
//! (`std::io::Error` alone says "No such file or directory" without saying which). Any file
//! operation gets the path with [`WithPath::with_path`], e.g.
//! `std::fs::write(&path, text).with_path(&path)?`.

use std::error::Error;
use std::fmt;
use std::path::{Path, PathBuf};

/// An error about a file or folder: its path and what went wrong.
#[derive(Debug)]
pub struct PathError {
    path: PathBuf,
    source: Box<dyn Error + Send + Sync>,
}

impl fmt::Display for PathError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.source)
    }
}

impl Error for PathError {
    fn source(&self) -> Option<&(dyn Error + 'static)> {
        Some(&*self.source)
    }
}

/// Attaches a path to the error of a file operation.
pub trait WithPath<T> {
    /// The result, its error naming `path`.
    fn with_path(self, path: &Path) -> Result<T, PathError>;
}

impl<T, E: Into<Box<dyn Error + Send + Sync>>> WithPath<T> for Result<T, E> {
    fn with_path(self, path: &Path) -> Result<T, PathError> {
        self.map_err(|e| PathError {
            path: path.to_path_buf(),
            source: e.into(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_name_the_path() {
        let missing = Path::new("/no/such/folder/file.txt");
        let e = std::fs::read_to_string(missing).with_path(missing);
        let e = e.unwrap_err().to_string();
        assert!(e.starts_with("/no/such/folder/file.txt: "), "{e}");
        let proc_x = Path::new("/proc/x");
        let e = std::fs::create_dir_all(proc_x)
            .with_path(proc_x)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("/proc/x: "), "{e}");
        let e = Err::<(), _>("bad plot").with_path(missing).unwrap_err();
        assert_eq!(e.to_string(), "/no/such/folder/file.txt: bad plot");
    }
}
