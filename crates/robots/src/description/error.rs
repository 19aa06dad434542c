//! Errors of robot description files: every one names the file, the 1-based line and the
//! field (line 0 when the whole file is at fault, e.g. unreadable).

use biped_dynamics::urdf::srdf::SrdfError;
use biped_dynamics::urdf::{ResolveError, UrdfError};
use biped_ssv::format::FormatError;
use std::ops::Range;
use thiserror::Error;

/// A file the description refers to that could not be found or loaded.
#[derive(Debug, Error)]
pub enum ReferencedError {
    /// The path or `package://` URI does not lead to a file.
    #[error("{source}{hint}")]
    Resolve {
        /// Why.
        source: ResolveError,
        /// What to install or set (empty if nothing to add).
        hint: String,
    },
    /// The URDF does not load.
    #[error(transparent)]
    Urdf(#[from] UrdfError),
    /// The SRDF does not load.
    #[error(transparent)]
    Srdf(#[from] SrdfError),
    /// The SSV collision model does not load.
    #[error(transparent)]
    Collision(#[from] FormatError),
}

/// Errors of [`super::Robot::load`].
#[derive(Debug, Error)]
pub enum DescriptionError {
    /// The file could not be read.
    #[error("{file}: cannot read robot description: {source}")]
    Io {
        /// File name.
        file: String,
        /// I/O error.
        source: std::io::Error,
    },
    /// TOML syntax, a missing, unknown or mistyped field.
    #[error("{file}:{line}: `{field}`: {message}")]
    Syntax {
        /// File name.
        file: String,
        /// 1-based line.
        line: usize,
        /// Field (dotted path or the key on the line).
        field: String,
        /// Parser message.
        message: String,
    },
    /// A value the robot cannot use (unknown joint or link, bad size, ...).
    #[error("{file}:{line}: `{field}`: {reason}")]
    Invalid {
        /// File name.
        file: String,
        /// 1-based line.
        line: usize,
        /// Field.
        field: String,
        /// What is wrong.
        reason: String,
    },
    /// A referenced file (URDF, SRDF, SSV model) is missing or broken.
    #[error("{file}:{line}: `{field}`: {source}")]
    Referenced {
        /// File name.
        file: String,
        /// 1-based line of the reference.
        line: usize,
        /// Field holding the reference.
        field: String,
        /// The referenced file's error (itself located in that file).
        source: Box<ReferencedError>,
    },
}

impl DescriptionError {
    /// 1-based line of the error (0 for I/O errors).
    pub fn line(&self) -> usize {
        match self {
            DescriptionError::Io { .. } => 0,
            DescriptionError::Syntax { line, .. }
            | DescriptionError::Invalid { line, .. }
            | DescriptionError::Referenced { line, .. } => *line,
        }
    }

    /// The field at fault (empty for I/O errors).
    pub fn field(&self) -> &str {
        match self {
            DescriptionError::Io { .. } => "",
            DescriptionError::Syntax { field, .. }
            | DescriptionError::Invalid { field, .. }
            | DescriptionError::Referenced { field, .. } => field,
        }
    }
}

/// Builds located errors for one description file.
pub(super) struct Locator<'a> {
    pub file: &'a str,
    pub text: &'a str,
}

impl Locator<'_> {
    /// 1-based line of a byte offset.
    pub fn line_of(&self, offset: usize) -> usize {
        biped_ssv::format::line_of(self.text, offset)
    }

    /// An [`DescriptionError::Invalid`] at `span`.
    pub fn invalid(
        &self,
        span: Range<usize>,
        field: impl Into<String>,
        reason: impl Into<String>,
    ) -> DescriptionError {
        DescriptionError::Invalid {
            file: self.file.to_string(),
            line: self.line_of(span.start),
            field: field.into(),
            reason: reason.into(),
        }
    }

    /// A [`DescriptionError::Referenced`] at `span`.
    pub fn referenced(
        &self,
        span: Range<usize>,
        field: &str,
        source: impl Into<ReferencedError>,
    ) -> DescriptionError {
        DescriptionError::Referenced {
            file: self.file.to_string(),
            line: self.line_of(span.start),
            field: field.to_string(),
            source: Box::new(source.into()),
        }
    }

    /// A syntax or type error of the TOML deserializer, with the field it names (or the key on
    /// its line).
    pub fn toml(&self, err: toml::de::Error) -> DescriptionError {
        let line = err.span().map_or(1, |s| self.line_of(s.start));
        let message = err.message().trim().to_string();
        let named = ["missing field `", "unknown field `"]
            .iter()
            .find_map(|p| message.strip_prefix(p))
            .and_then(|rest| rest.split('`').next())
            .map(str::to_string);
        let field = named.unwrap_or_else(|| self.key_on_line(line));
        DescriptionError::Syntax {
            file: self.file.to_string(),
            line,
            field,
            message,
        }
    }

    /// The key assigned on a 1-based line (`key = value`), or the table header, if any.
    fn key_on_line(&self, line: usize) -> String {
        let text = self.text.lines().nth(line.saturating_sub(1)).unwrap_or("");
        let text = text.trim();
        if let Some(header) = text.strip_prefix('[') {
            return header.trim_matches(['[', ']']).trim().to_string();
        }
        text.split_once('=')
            .map_or(String::new(), |(key, _)| key.trim().to_string())
    }
}
