//! Errors of model files: every error names the file, the line (1-based) and the field.

use crate::error::SsvError;
use crate::model::ModelError;
use crate::segment::{SegmentError, UnknownPlane};
use std::fmt;
use std::ops::Range;

/// A model-file error located at `file:line` in `field`.
#[derive(Debug, Clone, PartialEq)]
pub struct FormatError {
    /// File name (or a label for in-memory text).
    pub file: String,
    /// 1-based line of the offending entry; 0 when the whole file is at fault (I/O).
    pub line: usize,
    /// Dotted path of the offending field, e.g. `segment[2].ssvs[0].radius`.
    pub field: String,
    /// What is wrong.
    pub kind: FormatErrorKind,
}

/// The kinds of model-file errors.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FormatErrorKind {
    /// The file could not be read.
    #[error("cannot read file: {0}")]
    Io(String),
    /// The model could not be serialised.
    #[error("cannot write TOML: {0}")]
    Write(String),
    /// The bytes are not UTF-8.
    #[error("file is not valid UTF-8")]
    NotUtf8,
    /// TOML syntax error, wrong type, missing or unknown field.
    #[error("{0}")]
    Syntax(String),
    /// Invalid SSV coordinates or radius.
    #[error(transparent)]
    Ssv(#[from] SsvError),
    /// Invalid segment (empty, bad `keep` index).
    #[error(transparent)]
    Segment(#[from] SegmentError),
    /// Invalid model (activation distance, duplicate names, self pair).
    #[error(transparent)]
    Model(#[from] ModelError),
    /// Unknown mirror plane name.
    #[error(transparent)]
    Plane(#[from] UnknownPlane),
    /// A body name not in `bodies`.
    #[error("unknown body `{0}`")]
    UnknownBody(String),
    /// A segment name not defined (segments may only refer to earlier segments).
    #[error("unknown segment `{0}` (segments can only refer to segments defined before them)")]
    UnknownSegment(String),
    /// An SSV entry needs exactly one of `point`, `line`, `triangle`.
    #[error("an SSV needs exactly one of `point`, `line`, `triangle`")]
    SsvShape,
    /// A segment needs exactly one of `ssvs`, `mirror_of`, `version_of`.
    #[error("a segment needs exactly one of `ssvs`, `mirror_of` (with `plane`), `version_of` (with `keep`)")]
    SegmentSource,
    /// A required companion key is missing (e.g. `plane` for `mirror_of`).
    #[error("missing `{0}`")]
    Missing(&'static str),
    /// A negative `keep` index.
    #[error("SSV index must be >= 0, got {0}")]
    NegativeIndex(i64),
    /// A companion key without its geometry source (e.g. `plane` without `mirror_of`).
    #[error("`{0}` is only allowed together with `{1}`")]
    Unexpected(&'static str, &'static str),
    /// A non-finite pose component.
    #[error("pose value is not finite ({0})")]
    NonFinitePose(f64),
    /// A pose that does not list every body.
    #[error("pose lacks body `{0}`")]
    PoseLacksBody(String),
}

impl fmt::Display for FormatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line > 0 {
            write!(f, "{}:{}: ", self.file, self.line)?;
        } else {
            write!(f, "{}: ", self.file)?;
        }
        if !self.field.is_empty() {
            write!(f, "`{}`: ", self.field)?;
        }
        write!(f, "{}", self.kind)
    }
}

impl std::error::Error for FormatError {}

/// The 1-based line of byte `offset` in `text` (clamped to the text): where a TOML span of a
/// model or description file starts, for its located errors.
pub fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    1 + text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
}

/// Builds located errors for one file's text.
pub(super) struct Locator<'a> {
    pub file: &'a str,
    pub text: &'a str,
}

impl Locator<'_> {
    /// 1-based line of a byte offset (clamped to the text).
    pub fn line_of(&self, offset: usize) -> usize {
        line_of(self.text, offset)
    }

    /// An error at `span` in `field`.
    pub fn at(
        &self,
        span: Range<usize>,
        field: impl Into<String>,
        kind: impl Into<FormatErrorKind>,
    ) -> FormatError {
        FormatError {
            file: self.file.to_string(),
            line: self.line_of(span.start),
            field: field.into(),
            kind: kind.into(),
        }
    }

    /// The key assigned on a 1-based line (`key = value`), or the table header, if any.
    fn key_on_line(&self, line: usize) -> String {
        let text = self.text.lines().nth(line.saturating_sub(1)).unwrap_or("");
        let text = text.trim();
        if let Some(header) = text.strip_prefix('[') {
            return header
                .trim_matches(|c| c == '[' || c == ']')
                .trim()
                .to_string();
        }
        match text.split_once('=') {
            Some((key, _)) => key.trim().to_string(),
            None => String::new(),
        }
    }

    /// A syntax or type error reported by the TOML deserializer.
    pub fn toml(&self, err: toml::de::Error) -> FormatError {
        let line = err.span().map_or(1, |s| self.line_of(s.start));
        let message = err.message().trim().to_string();
        let mut field = toml_field(err, &message);
        if field.is_empty() {
            field = self.key_on_line(line);
        }
        FormatError {
            file: self.file.to_string(),
            line,
            field,
            kind: FormatErrorKind::Syntax(message),
        }
    }
}

/// The dotted key path of a TOML error (from its context-free rendering), extended by the
/// field named in "missing field `x`" / "unknown field `x`" messages.
fn toml_field(mut err: toml::de::Error, message: &str) -> String {
    err.set_input(None);
    let rendered = err.to_string();
    let mut path = rendered
        .lines()
        .filter_map(|l| l.strip_prefix("in `"))
        .filter_map(|l| l.strip_suffix('`'))
        .next_back()
        .unwrap_or("")
        .to_string();
    for prefix in ["missing field `", "unknown field `"] {
        if let Some(rest) = message.strip_prefix(prefix) {
            if let Some(name) = rest.split('`').next() {
                if !path.is_empty() {
                    path.push('.');
                }
                path.push_str(name);
            }
        }
    }
    path
}
