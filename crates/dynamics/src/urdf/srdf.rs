//! SRDF import: the parts a simulation of a URDF robot needs from its semantic description,
//! the motor rotors (`<rotor_params>`, as Pinocchio's `loadRotorParameters` reads them: the
//! `mass` attribute is the rotor inertia `J` about its axis, `gear_ratio` the reduction `N`,
//! so the joint's reflected inertia is `N^2 J`) and the named joint configurations
//! (`<group_state>`, e.g. TALOS's `half_sitting`).

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
    let text = std::fs::read_to_string(path).map_err(|source| SrdfError::Io {
        file: file.clone(),
        source,
    })?;
    parse_srdf(&text, &file)
}

/// Parses SRDF `text` (`file` labels the errors): every `<rotor_params>` entry and every
/// `<group_state>` of the root `<robot>`; other elements (groups, disabled collisions, ...)
/// are not read. A missing or non-numeric attribute, a negative inertia or a gear ratio
/// `<= 0` is an error at its line.
pub fn parse_srdf(text: &str, file: &str) -> Result<Srdf, SrdfError> {
    let doc = roxmltree::Document::parse(text).map_err(|e| SrdfError::Parse {
        file: file.to_string(),
        line: e.pos().row,
        message: e.to_string(),
    })?;
    let root = doc.root_element();
    if !root.has_tag_name("robot") {
        let at = locate(file, &root, format!("<{}>", root.tag_name().name()));
        return Err(invalid(at, "root element", "must be <robot>"));
    }
    let mut out = Srdf::default();
    for node in root.children().filter(|n| n.is_element()) {
        match node.tag_name().name() {
            "rotor_params" => {
                for j in joints(&node) {
                    out.rotors.push(rotor(file, &j)?);
                }
            }
            "group_state" => out.states.push(group_state(file, &node)?),
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
fn rotor(file: &str, j: &roxmltree::Node) -> Result<RotorParams, SrdfError> {
    let name = required(file, j, "rotor_params joint", "name")?;
    let at = || locate(file, j, format!("rotor_params joint {name:?}"));
    let inertia = number(at, j, "mass")?;
    let gear_ratio = number(at, j, "gear_ratio")?;
    if inertia < 0.0 {
        return Err(invalid(at(), "mass", "the rotor inertia must be >= 0"));
    }
    if gear_ratio <= 0.0 {
        return Err(invalid(at(), "gear_ratio", "must be > 0"));
    }
    Ok(RotorParams {
        joint: name.to_string(),
        inertia,
        gear_ratio,
        line: line_of(j),
    })
}

/// One `<group_state>` with its joint values.
fn group_state(file: &str, node: &roxmltree::Node) -> Result<GroupState, SrdfError> {
    let name = required(file, node, "group_state", "name")?;
    let mut joints_out = Vec::new();
    for j in joints(node) {
        let joint = required(file, &j, "group_state joint", "name")?;
        let at = || locate(file, &j, format!("group_state {name:?} joint {joint:?}"));
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
        line: line_of(node),
    })
}

/// Attribute `attr` of `node` (an `element` tag), or an error naming the element's line.
fn required<'a>(
    file: &str,
    node: &roxmltree::Node<'a, '_>,
    element: &str,
    attr: &str,
) -> Result<&'a str, SrdfError> {
    node.attribute(attr)
        .ok_or_else(|| invalid(locate(file, node, element.to_string()), attr, "missing"))
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

/// 1-based line of `node`'s start tag.
fn line_of(node: &roxmltree::Node) -> u32 {
    node.document().text_pos_at(node.range().start).row
}

/// The location of `node` in `file`, described as `element`.
fn locate(file: &str, node: &roxmltree::Node, element: String) -> Location {
    Location {
        file: file.to_string(),
        line: Some(line_of(node) as usize),
        element,
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

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A TALOS-like SRDF: groups (not read), a group state with a free-flyer and two joints,
    /// rotor parameters.
    const SRDF: &str = r#"<?xml version="1.0" ?>
<robot name="talos">
    <group name="r_leg">
        <joint name="leg_right_1_joint" />
    </group>
    <!-- <rotor_params><joint name="commented" mass="x"/></rotor_params> -->
    <group_state name="half_sitting" group="all">
        <joint name="root_joint" value="0. 0. 1.01927 0. 0. 0. 1." />
        <joint name="leg_left_4_joint" value="0.6" />
        <joint name="leg_left_3_joint" value="-4e-1" />
    </group_state>
    <rotor_params>
        <joint name="leg_left_3_joint" mass="1e-5" gear_ratio="100." />
        <joint name="leg_left_4_joint" mass="2e-5" gear_ratio="50" />
    </rotor_params>
</robot>
"#;

    #[test]
    fn reads_rotors_and_group_states() {
        let s = parse_srdf(SRDF, "talos.srdf").unwrap();
        assert_eq!(s.rotors.len(), 2);
        let r = &s.rotors[1];
        assert_eq!(
            (r.joint.as_str(), r.inertia, r.gear_ratio, r.line),
            ("leg_left_4_joint", 2e-5, 50.0, 14)
        );
        // N^2 J: 50^2 * 2e-5 = 0.05; 100^2 * 1e-5 = 0.1.
        assert!((r.armature() - 0.05).abs() < 1e-15);
        assert!((s.rotors[0].armature() - 0.1).abs() < 1e-15);
        let h = s.state("half_sitting").unwrap();
        assert_eq!((h.group.as_str(), h.line), ("all", 7));
        assert_eq!(h.joints[0].1, vec![0.0, 0.0, 1.01927, 0.0, 0.0, 0.0, 1.0]);
        assert_eq!(h.joints[1], ("leg_left_4_joint".to_string(), vec![0.6]));
        assert_eq!(h.joints[2].1, vec![-0.4]);
        assert!(s.state("standing").is_none());
    }

    #[test]
    fn bad_entries_are_errors_at_their_line() {
        let cases = [
            (
                "mass=\"2e-5\"",
                "mass=\"-1\"",
                ":14: rotor_params joint \"leg_left_4_joint\": mass",
            ),
            (
                "gear_ratio=\"50\"",
                "gear_ratio=\"0\"",
                ":14: rotor_params joint \"leg_left_4_joint\": gear_ratio: must be > 0",
            ),
            (
                "gear_ratio=\"50\"",
                "",
                ":14: rotor_params joint \"leg_left_4_joint\": gear_ratio: missing",
            ),
            (
                "mass=\"2e-5\"",
                "mass=\"heavy\"",
                ":14: rotor_params joint \"leg_left_4_joint\": mass: \"heavy\"",
            ),
            (
                "value=\"0.6\"",
                "value=\"0.6 x\"",
                ":9: group_state \"half_sitting\" joint \"leg_left_4_joint\": value",
            ),
            (
                "value=\"0.6\"",
                "value=\"\"",
                ":9: group_state \"half_sitting\" joint \"leg_left_4_joint\": value",
            ),
            (
                "<group_state name=\"half_sitting\"",
                "<group_state",
                ":7: group_state: name: missing",
            ),
            (
                "</robot>",
                "</robt>",
                "talos.srdf:16: not a valid SRDF document",
            ),
        ];
        for (from, to, expected) in cases {
            // Replace the last occurrence so the rotor entries, not the state, are changed.
            let at = SRDF.rfind(from).unwrap();
            let text = format!("{}{}{}", &SRDF[..at], to, &SRDF[at + from.len()..]);
            let e = parse_srdf(&text, "talos.srdf").unwrap_err().to_string();
            assert!(e.contains(expected), "{from} -> {to}: {e}");
        }
        let e = parse_srdf("<urdf/>", "x.srdf").unwrap_err().to_string();
        assert!(e.contains("x.srdf:1") && e.contains("<robot>"), "{e}");
        let e = load_srdf_file("/no/such.srdf").unwrap_err().to_string();
        assert!(e.contains("/no/such.srdf: cannot read SRDF file"), "{e}");
    }

    proptest! {
        /// Arbitrary text, and the sample with any one byte range deleted, give a result or
        /// an error, never a panic; what parses has finite values, inertias >= 0, ratios > 0.
        #[test]
        fn never_panics(text in ".{0,200}", cut in 0usize..600, len in 0usize..40) {
            let start = cut.min(SRDF.len());
            let end = (start + len).min(SRDF.len());
            let (start, end) = (floor(SRDF, start), floor(SRDF, end));
            let damaged = format!("{}{}", &SRDF[..start], &SRDF[end..]);
            for t in [text.as_str(), damaged.as_str()] {
                if let Ok(s) = parse_srdf(t, "f.srdf") {
                    prop_assert!(s.rotors.iter().all(|r| r.inertia >= 0.0 && r.gear_ratio > 0.0));
                    let values = s.states.iter().flat_map(|g| g.joints.iter().flat_map(|j| &j.1));
                    prop_assert!(values.clone().all(|x| x.is_finite()));
                }
            }
        }
    }

    /// The largest char boundary of `s` at or below `i`.
    fn floor(s: &str, mut i: usize) -> usize {
        while !s.is_char_boundary(i) {
            i -= 1;
        }
        i
    }
}
