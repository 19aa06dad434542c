//! SRDF import: the parts a simulation of a URDF robot needs from its semantic description,
//! the motor rotors (`<rotor_params>`, as Pinocchio's `loadRotorParameters` reads them: the
//! `mass` attribute is the rotor inertia `J` about its axis, `gear_ratio` the reduction `N`,
//! so the joint's reflected inertia is `N^2 J`) and the named joint configurations
//! (`<group_state>`, e.g. TALOS's `half_sitting`).

use super::lines::{one_line, read_text, LineIndex, ReadError};
use super::{InvalidElement, Location};
use std::path::Path;

/// Errors of [`load_srdf_file`] and [`parse_srdf`].
#[derive(Debug, thiserror::Error)]
pub enum SrdfError {
    /// The file could not be read.
    #[error("{file}: cannot read SRDF file: {source}")]
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
    /// The text is not well-formed XML.
    #[error("{file}:{line}: not a valid SRDF document: {message}")]
    Parse {
        /// File name.
        file: String,
        /// 1-based line of the fault.
        line: u32,
        /// Parser message.
        message: String,
    },
    /// An element is well-formed but its content is unusable (the attribute at fault, e.g.
    /// `gear_ratio`).
    #[error(transparent)]
    Invalid(#[from] InvalidElement),
}

/// The motor rotor of one joint (`<rotor_params><joint name mass gear_ratio/>`).
#[derive(Debug, Clone, PartialEq)]
pub struct RotorParams {
    /// Joint name.
    pub joint: String,
    /// Rotor inertia `J` about its axis \[kg m^2] (the SRDF's `mass` attribute).
    pub inertia: f64,
    /// Gear ratio `N` (> 0).
    pub gear_ratio: f64,
    /// 1-based line of the entry.
    pub line: u32,
}

impl RotorParams {
    /// Reflected rotor inertia `N^2 J` at the joint (Pinocchio's armature).
    pub fn armature(&self) -> f64 {
        self.gear_ratio * self.gear_ratio * self.inertia
    }
}

/// A named joint configuration (`<group_state name group>` with `<joint name value>`).
#[derive(Debug, Clone, PartialEq)]
pub struct GroupState {
    /// State name, e.g. `half_sitting`.
    pub name: String,
    /// Group it is defined for.
    pub group: String,
    /// Joint values in file order: one number for a one-DoF joint, several for e.g. a
    /// free-flyer (`x y z qx qy qz qw`).
    pub joints: Vec<(String, Vec<f64>)>,
    /// 1-based line of the `group_state` tag.
    pub line: u32,
}

/// What [`parse_srdf`] reads from an SRDF document.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Srdf {
    /// Rotor parameters in file order.
    pub rotors: Vec<RotorParams>,
    /// Named configurations in file order.
    pub states: Vec<GroupState>,
}

impl Srdf {
    /// The group state called `name`.
    pub fn state(&self, name: &str) -> Option<&GroupState> {
        self.states.iter().find(|s| s.name == name)
    }
}

/// Reads and parses the SRDF file at `path` ([`parse_srdf`]).
pub fn load_srdf_file(path: impl AsRef<Path>) -> Result<Srdf, SrdfError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    let text = read_text(path).map_err(|e| match e {
        ReadError::Io(source) => SrdfError::Io {
            file: file.clone(),
            source,
        },
        ReadError::NotUtf8 { line } => SrdfError::NotUtf8 {
            file: file.clone(),
            line,
        },
    })?;
    parse_srdf(&text, &file)
}

/// The file label and line index of the text being parsed.
struct Doc<'f> {
    file: &'f str,
    lines: LineIndex,
}

/// Parses SRDF `text` (`file` labels the errors): every `<rotor_params>` entry and every
/// `<group_state>` of the root `<robot>`; other elements (groups, disabled collisions, ...)
/// are not read. A missing or non-numeric attribute, a negative inertia, a gear ratio `<= 0`
/// or a reflected inertia `N^2 J` beyond f64 is an error at its line, and so is a URDF passed for an SRDF (its root `<robot>`
/// has `<link>` or `<joint>` children). The XML reader (roxmltree) and this parser do not
/// recurse on the element nesting, and locating lines is a binary search, so parsing is
/// linear in the text.
pub fn parse_srdf(text: &str, file: &str) -> Result<Srdf, SrdfError> {
    let xml = roxmltree::Document::parse(text).map_err(|e| SrdfError::Parse {
        file: file.to_string(),
        line: e.pos().row,
        message: one_line(&e.to_string()),
    })?;
    let doc = Doc {
        file,
        lines: LineIndex::new(text),
    };
    let root = xml.root_element();
    if !root.has_tag_name("robot") {
        let at = doc.locate(&root, format!("<{}>", root.tag_name().name()));
        return Err(invalid(at, "root element", "must be <robot>"));
    }
    let mut out = Srdf::default();
    for node in root.children().filter(|n| n.is_element()) {
        match node.tag_name().name() {
            "rotor_params" => {
                for j in joints(&node) {
                    out.rotors.push(rotor(&doc, &j)?);
                }
            }
            "group_state" => out.states.push(group_state(&doc, &node)?),
            tag @ ("link" | "joint") => {
                let at = doc.locate(&node, format!("<{tag}>"));
                let problem = "an SRDF has no such child of <robot>: this file looks like a URDF";
                return Err(invalid(at, "element", problem));
            }
            _ => {}
        }
    }
    Ok(out)
}

/// The `<joint>` children of `node`.
fn joints<'a, 'i>(node: &roxmltree::Node<'a, 'i>) -> impl Iterator<Item = roxmltree::Node<'a, 'i>> {
    node.children().filter(|n| n.has_tag_name("joint"))
}

/// One `<rotor_params>` joint entry.
fn rotor(doc: &Doc, j: &roxmltree::Node) -> Result<RotorParams, SrdfError> {
    let name = doc.required(j, "rotor_params joint", "name")?;
    let at = || doc.locate(j, format!("rotor_params joint {name:?}"));
    let inertia = number(at, j, "mass")?;
    let gear_ratio = number(at, j, "gear_ratio")?;
    if inertia < 0.0 {
        return Err(invalid(at(), "mass", "the rotor inertia must be >= 0"));
    }
    if gear_ratio <= 0.0 {
        return Err(invalid(at(), "gear_ratio", "must be > 0"));
    }
    if !(gear_ratio * gear_ratio * inertia).is_finite() {
        let problem = "the reflected inertia gear_ratio^2 * mass is too large for f64";
        return Err(invalid(at(), "gear_ratio", problem));
    }
    Ok(RotorParams {
        joint: name.to_string(),
        inertia,
        gear_ratio,
        line: doc.line_of(j),
    })
}

/// One `<group_state>` with its joint values.
fn group_state(doc: &Doc, node: &roxmltree::Node) -> Result<GroupState, SrdfError> {
    let name = doc.required(node, "group_state", "name")?;
    let mut joints_out = Vec::new();
    for j in joints(node) {
        let joint = doc.required(&j, "group_state joint", "name")?;
        let at = || doc.locate(&j, format!("group_state {name:?} joint {joint:?}"));
        let text = j
            .attribute("value")
            .ok_or_else(|| invalid(at(), "value", "missing"))?;
        let values: Result<Vec<f64>, _> = text.split_whitespace().map(str::parse).collect();
        match values {
            Ok(v) if !v.is_empty() && v.iter().all(|x| x.is_finite()) => {
                joints_out.push((joint.to_string(), v))
            }
            _ => {
                let problem = format!("{text:?} is not a list of finite numbers");
                return Err(invalid(at(), "value", &problem));
            }
        }
    }
    Ok(GroupState {
        name: name.to_string(),
        group: node.attribute("group").unwrap_or_default().to_string(),
        joints: joints_out,
        line: doc.line_of(node),
    })
}

impl Doc<'_> {
    /// Attribute `attr` of `node` (an `element` tag), or an error naming the element's line.
    fn required<'a>(
        &self,
        node: &roxmltree::Node<'a, '_>,
        element: &str,
        attr: &str,
    ) -> Result<&'a str, SrdfError> {
        node.attribute(attr)
            .ok_or_else(|| invalid(self.locate(node, element.to_string()), attr, "missing"))
    }

    /// 1-based line of `node`'s start tag.
    fn line_of(&self, node: &roxmltree::Node) -> u32 {
        let line = self.lines.line_of(node.range().start);
        u32::try_from(line).unwrap_or(u32::MAX)
    }

    /// The location of `node`, described as `element`.
    fn locate(&self, node: &roxmltree::Node, element: String) -> Location {
        Location {
            file: self.file.to_string(),
            line: Some(self.lines.line_of(node.range().start)),
            element,
        }
    }
}

/// The finite number in attribute `attr` of `node`.
fn number(at: impl Fn() -> Location, node: &roxmltree::Node, attr: &str) -> Result<f64, SrdfError> {
    let text = node
        .attribute(attr)
        .ok_or_else(|| invalid(at(), attr, "missing"))?;
    match text.trim().parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err(invalid(
            at(),
            attr,
            &format!("{text:?} is not a finite number"),
        )),
    }
}

/// An [`SrdfError::Invalid`].
fn invalid(at: Location, field: &str, problem: &str) -> SrdfError {
    SrdfError::Invalid(InvalidElement {
        at,
        field: field.to_string(),
        problem: problem.to_string(),
    })
}
