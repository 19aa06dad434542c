//! Typed errors of the URDF importer, each naming the file and the element at fault.

use crate::ModelError;
use std::fmt;

/// Where in a URDF document a problem is: file, line (when found in the text) and element.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// File name (or a caller-chosen source label for in-memory text).
    pub file: String,
    /// 1-based line of the element's start tag, if it could be found in the text.
    pub line: Option<usize>,
    /// The element, e.g. `joint "knee"` or `link "foot"`.
    pub element: String,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "{}:{}: {}", self.file, line, self.element),
            None => write!(f, "{}: {}", self.file, self.element),
        }
    }
}

/// `file:line`, or `file` without a line.
fn place(file: &str, line: Option<usize>) -> String {
    match line {
        Some(line) => format!("{file}:{line}"),
        None => file.to_string(),
    }
}

/// A well-formed element of a URDF or SRDF document whose content is unusable.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{at}: {field}: {problem}")]
pub struct InvalidElement {
    /// The element at fault.
    pub at: Location,
    /// The attribute or child element at fault, e.g. `axis xyz`.
    pub field: String,
    /// What is wrong with it.
    pub problem: String,
}

/// Errors of [`load_file`](super::load_file) and [`load_str`](super::load_str).
#[derive(Debug, thiserror::Error)]
pub enum UrdfError {
    /// The file could not be read.
    #[error("{file}: cannot read URDF file: {source}")]
    Io {
        /// File name.
        file: String,
        /// Underlying I/O error.
        source: std::io::Error,
    },
    /// The bytes are not UTF-8.
    #[error("{file}:{line}: not UTF-8 text")]
    NotUtf8 {
        /// File name.
        file: String,
        /// 1-based line of the first invalid byte.
        line: usize,
    },
    /// The text is not well-formed URDF XML (the importer's or urdf-rs' message).
    #[error("{}: not a valid URDF document: {message}", place(file, *line))]
    Parse {
        /// File name.
        file: String,
        /// 1-based line of the fault, when known (urdf-rs' messages have none).
        line: Option<usize>,
        /// Parser message.
        message: String,
    },
    /// Elements nested deeper than the importer reads ([`MAX_DEPTH`](super::MAX_DEPTH)).
    #[error("{file}:{line}: elements nested deeper than {limit} levels")]
    TooDeep {
        /// File name.
        file: String,
        /// 1-based line of the first element beyond the limit.
        line: usize,
        /// The nesting limit.
        limit: usize,
    },
    /// An element is well-formed but its content is unusable.
    #[error(transparent)]
    Invalid(#[from] InvalidElement),
    /// The model builder rejected a body built from this element (e.g. a non-physical inertia).
    #[error("{at}: {source}")]
    Model {
        /// The element at fault.
        at: Location,
        /// The builder's error.
        source: ModelError,
    },
}
