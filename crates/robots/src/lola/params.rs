//! The Lola-like parameter file (`data/lola.toml`): typed serde structures and error locations.

use serde::Deserialize;
use std::ops::Range;
use thiserror::Error;
use toml::Spanned;

/// Mass, centre of mass and box size of one rigid part (inertia of a solid box).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PartParams {
    /// Mass \[kg].
    pub mass: f64,
    /// Centre of mass in the part frame \[m].
    pub com: [f64; 3],
    /// Edge lengths of the solid box centred at the CoM \[m].
    pub size: [f64; 3],
}

/// Knee roller-screw drive parts (thesis 3.2); geometry from the mechanism defaults.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KneeParams {
    /// Roller-screw lead \[m/rev].
    pub lead: f64,
    /// Screw housing hinged to the thigh.
    pub housing: PartParams,
    /// Roller-screw nut.
    pub nut: PartParams,
    /// Motor rotor and screw.
    pub rotor: PartParams,
}

/// Ankle drive parts, one set per slider-crank (thesis 3.3); geometry from the defaults.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnkleParams {
    /// Roller-screw lead \[m/rev].
    pub lead: f64,
    /// Roller-screw nut.
    pub nut: PartParams,
    /// Motor rotor and screw.
    pub rotor: PartParams,
    /// Coupler rod.
    pub rod: PartParams,
}

/// One body of the file and the joint to its parent.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyParams {
    /// Unique body name (the joint gets the same name).
    pub name: Spanned<String>,
    /// Parent body name (none for the floating base).
    pub parent: Option<Spanned<String>>,
    /// "revolute" (default), "free" or "fixed".
    #[serde(default)]
    pub joint: Option<Spanned<String>>,
    /// Joint origin in the parent frame \[m].
    #[serde(default)]
    pub origin: [f64; 3],
    /// Joint axis "x", "y" or "z" (revolute only).
    pub axis: Option<Spanned<String>>,
    /// Joint range \[rad] (revolute only).
    pub limits: Option<Spanned<[f64; 2]>>,
    /// "harmonic", "knee", "ankle_flexion", "ankle_adduction" or "none".
    pub drive: Option<Spanned<String>>,
    /// Harmonic Drive gear ratio.
    pub ratio: Option<Spanned<f64>>,
    /// Whether Type 3 models the gear elastically (own motor coordinate).
    #[serde(default)]
    pub elastic: bool,
    /// Body mass \[kg].
    pub mass: f64,
    /// Centre of mass \[m].
    pub com: [f64; 3],
    /// Box size for the inertia \[m].
    pub size: [f64; 3],
}

/// The whole parameter file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LolaParams {
    /// Harmonic Drive motor rotor (all HD joints).
    pub harmonic_rotor: PartParams,
    /// Knee drive.
    pub knee: KneeParams,
    /// Ankle drive.
    pub ankle: AnkleParams,
    /// Bodies, parents first.
    pub body: Vec<BodyParams>,
}

/// Errors of the Lola model: file syntax/fields, semantics, model or mechanism validation.
#[derive(Debug, Error)]
pub enum LolaError {
    /// The file could not be read.
    #[error("{file}: {source}")]
    Io {
        /// File name.
        file: String,
        /// I/O error.
        source: std::io::Error,
    },
    /// Syntax error or a missing/unknown/mistyped field (from the TOML deserializer).
    #[error("{file}:{line}:{column}: {message}")]
    Parse {
        /// File name.
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// Deserializer message (names the field).
        message: String,
    },
    /// A field has a value the model cannot use.
    #[error("{file}:{line}: field `{field}`: {reason}")]
    Invalid {
        /// File name.
        file: String,
        /// 1-based line.
        line: usize,
        /// Field name.
        field: &'static str,
        /// What is wrong.
        reason: String,
    },
    /// The multibody model rejected a body or one of its drive parts (located at the body's
    /// `name`; line 0 if no body is to blame).
    #[error("{file}:{line}: model: {source}")]
    Model {
        /// File name.
        file: String,
        /// 1-based line of the body's `name`.
        line: usize,
        /// The model builder's error.
        source: biped_dynamics::ModelError,
    },
    /// A drive mechanism rejected its parameters (located at the body it drives).
    #[error("{file}:{line}: mechanism: {source}")]
    Mechanism {
        /// File name.
        file: String,
        /// 1-based line of the body's `name`.
        line: usize,
        /// The mechanism's error.
        source: biped_dynamics::mechanism::MechanismError,
    },
}

/// Not yet located: [`Locator::locate`] fills in file and line.
impl From<biped_dynamics::ModelError> for LolaError {
    fn from(source: biped_dynamics::ModelError) -> Self {
        let (file, line) = (String::new(), 0);
        LolaError::Model { file, line, source }
    }
}

/// Not yet located: [`Locator::locate`] fills in file and line.
impl From<biped_dynamics::mechanism::MechanismError> for LolaError {
    fn from(source: biped_dynamics::mechanism::MechanismError) -> Self {
        let (file, line) = (String::new(), 0);
        LolaError::Mechanism { file, line, source }
    }
}

/// Maps byte offsets of one file to 1-based lines and columns.
pub struct Locator<'a> {
    /// File name for messages.
    pub file: &'a str,
    /// File text.
    pub text: &'a str,
}

impl Locator<'_> {
    /// 1-based (line, column) of a byte offset.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let head = &self.text[..offset.min(self.text.len())];
        let line = head.matches('\n').count() + 1;
        let column = head.len() - head.rfind('\n').map_or(0, |p| p + 1) + 1;
        (line, column)
    }

    /// An [`LolaError::Invalid`] at `span`.
    pub fn invalid(&self, span: Range<usize>, field: &'static str, reason: String) -> LolaError {
        LolaError::Invalid {
            file: self.file.to_string(),
            line: self.line_col(span.start).0,
            field,
            reason,
        }
    }

    /// `e` with the file and, from `span` (the body at fault), the line filled in if it is a
    /// model or mechanism error not located yet; other errors unchanged.
    pub fn locate(&self, mut e: LolaError, span: Option<Range<usize>>) -> LolaError {
        if let LolaError::Model { file, line, .. } | LolaError::Mechanism { file, line, .. } =
            &mut e
        {
            if file.is_empty() {
                *file = self.file.to_string();
                *line = span.map_or(0, |s| self.line_col(s.start).0);
            }
        }
        e
    }

    /// Parses the file text.
    pub fn parse(&self) -> Result<LolaParams, LolaError> {
        toml::from_str(self.text).map_err(|e| {
            let (line, column) = e.span().map_or((0, 0), |s| self.line_col(s.start));
            LolaError::Parse {
                file: self.file.to_string(),
                line,
                column,
                message: e.message().to_string(),
            }
        })
    }
}
