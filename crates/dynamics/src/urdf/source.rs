//! The URDF text's label and one-pass index, for locating elements in error messages.

use super::error::{InvalidElement, Location, UrdfError};
use super::lines::one_line;
use super::scan::Scanned;

/// The scanned URDF text and its label.
pub(super) struct Source<'a> {
    /// What the scan found (root element, lines of links and joints).
    pub scanned: &'a Scanned,
    /// File name or label.
    pub file: &'a str,
}

impl Source<'_> {
    /// Location of the element `<tag name="name">` (`robot` is the root element).
    pub(super) fn at(&self, tag: &str, name: &str) -> Location {
        let s = self.scanned;
        let line = match tag {
            "robot" => s.root.as_ref().map(|r| r.1),
            "link" => s.links.get(name).copied(),
            "joint" => s.joints.get(name).copied(),
            _ => None,
        };
        Location {
            file: self.file.to_string(),
            line,
            element: format!("{tag} {name:?}"),
        }
    }

    /// An [`UrdfError::Invalid`] at `<tag name="name">`.
    pub(super) fn invalid(&self, tag: &str, name: &str, field: &str, problem: String) -> UrdfError {
        UrdfError::Invalid(InvalidElement {
            at: self.at(tag, name),
            field: field.to_string(),
            problem,
        })
    }

    /// The root element must be `<robot>` (urdf-rs reads any root element as one).
    pub(super) fn check_root(&self) -> Result<(), UrdfError> {
        match &self.scanned.root {
            Some((tag, _)) if tag == "robot" => Ok(()),
            Some((tag, line)) => Err(UrdfError::Invalid(InvalidElement {
                at: Location {
                    file: self.file.to_string(),
                    line: Some(*line),
                    element: format!("<{}>", one_line(tag)),
                },
                field: "root element".into(),
                problem: "must be <robot>".into(),
            })),
            None => Err(UrdfError::Parse {
                file: self.file.to_string(),
                line: None,
                message: "no <robot> element".into(),
            }),
        }
    }
}
