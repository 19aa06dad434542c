//! The geometry of a URDF's links: every `<collision>` and `<visual>` element with its origin
//! and shape (box, cylinder, sphere, capsule, mesh), read with roxmltree after the same
//! linear pre-scan as the dynamics import (which bounds the nesting, see `scan`), so the read
//! is linear in the text and never recurses on its depth. Mesh file names are kept as written;
//! [`PackagePath::resolve`](super::PackagePath::resolve) finds the files.

use super::lines::{one_line, read_text, LineIndex, ReadError};
use super::scan::{scan, ScanError};
use super::{InvalidElement, Location, UrdfError, MAX_DEPTH};
use nalgebra::{Isometry3, Translation3, UnitQuaternion};
use roxmltree::Node;
use std::path::Path;

/// The shape of one geometry element (URDF `<geometry>` child), lengths in metres.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// `<box size="x y z">`: full edge lengths, centred at the origin.
    Box {
        /// Edge lengths along x, y, z.
        size: [f64; 3],
    },
    /// `<cylinder radius length>`: axis along z, centred at the origin.
    Cylinder {
        /// Radius.
        radius: f64,
        /// Length along z.
        length: f64,
    },
    /// `<sphere radius>` about the origin.
    Sphere {
        /// Radius.
        radius: f64,
    },
    /// `<capsule radius length>`: a cylinder of this length along z with hemispherical caps.
    Capsule {
        /// Radius.
        radius: f64,
        /// Length of the cylindrical part along z.
        length: f64,
    },
    /// `<mesh filename scale>`: a mesh file, its vertices scaled per axis.
    Mesh {
        /// The file name as written (`package://...`, `file://...` or a path).
        filename: String,
        /// Scale per axis (default 1 1 1).
        scale: [f64; 3],
    },
}

/// One `<collision>` or `<visual>` element: its shape placed by its origin in the link frame.
#[derive(Debug, Clone, PartialEq)]
pub struct GeometryElement {
    /// Pose of the shape in the link frame (`<origin xyz rpy>`).
    pub origin: Isometry3<f64>,
    /// The shape.
    pub shape: Shape,
    /// Where the element is (file, line, `link "name" collision`).
    pub at: Location,
}

impl GeometryElement {
    /// An [`UrdfError::Invalid`] about `field` of this element.
    pub fn invalid(&self, field: &str, problem: String) -> UrdfError {
        UrdfError::Invalid(InvalidElement {
            at: self.at.clone(),
            field: field.to_string(),
            problem,
        })
    }
}

/// The geometry of one `<link>`, in file order.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkGeometry {
    /// Link name.
    pub link: String,
    /// The `<collision>` elements.
    pub collisions: Vec<GeometryElement>,
    /// The `<visual>` elements.
    pub visuals: Vec<GeometryElement>,
}

/// Reads the geometry of every link of the URDF file at `path` (see [`read_geometry_str`]).
pub fn read_geometry_file(path: impl AsRef<Path>) -> Result<Vec<LinkGeometry>, UrdfError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    let text = read_text(path).map_err(|e| match e {
        ReadError::Io(source) => UrdfError::Io {
            file: file.clone(),
            source,
        },
        ReadError::NotUtf8 { line } => UrdfError::NotUtf8 {
            file: file.clone(),
            line,
        },
    })?;
    read_geometry_str(&text, &file)
}

/// Reads the geometry of every `<link>` child of the root `<robot>` of URDF text (`file`
/// labels errors), links in file order; links without geometry are listed with none. A
/// missing or bad attribute (non-finite number, size `<= 0`, zero scale, unknown shape) is an
/// error naming file, line and field.
pub fn read_geometry_str(xml: &str, file: &str) -> Result<Vec<LinkGeometry>, UrdfError> {
    scan(xml).map_err(|e| match e {
        ScanError::Malformed { line, problem } => UrdfError::Parse {
            file: file.to_string(),
            line: Some(line),
            message: one_line(&problem),
        },
        ScanError::TooDeep { line } => UrdfError::TooDeep {
            file: file.to_string(),
            line,
            limit: MAX_DEPTH,
        },
    })?;
    let doc = roxmltree::Document::parse(xml).map_err(|e| UrdfError::Parse {
        file: file.to_string(),
        line: Some(e.pos().row as usize),
        message: one_line(&e.to_string()),
    })?;
    let reader = Reader {
        file,
        lines: LineIndex::new(xml),
    };
    let root = doc.root_element();
    if !root.has_tag_name("robot") {
        let at = reader.locate(&root, format!("<{}>", one_line(root.tag_name().name())));
        return Err(invalid(at, "root element", "must be <robot>".into()));
    }
    let mut out = Vec::new();
    for link in root.children().filter(|n| n.has_tag_name("link")) {
        out.push(reader.link(&link)?);
    }
    Ok(out)
}

/// The file label and line index of the text being read.
struct Reader<'f> {
    file: &'f str,
    lines: LineIndex,
}

impl Reader<'_> {
    /// The location of `node`, described as `element`.
    fn locate(&self, node: &Node, element: String) -> Location {
        Location {
            file: self.file.to_string(),
            line: Some(self.lines.line_of(node.range().start)),
            element,
        }
    }

    /// One `<link>` and its geometry elements.
    fn link(&self, link: &Node) -> Result<LinkGeometry, UrdfError> {
        let Some(name) = link.attribute("name") else {
            let at = self.locate(link, "<link>".into());
            return Err(invalid(at, "name", "missing".into()));
        };
        let mut out = LinkGeometry {
            link: name.to_string(),
            collisions: Vec::new(),
            visuals: Vec::new(),
        };
        for child in link.children().filter(Node::is_element) {
            let kind = child.tag_name().name();
            let list = match kind {
                "collision" => &mut out.collisions,
                "visual" => &mut out.visuals,
                _ => continue,
            };
            let at = self.locate(&child, format!("link {name:?} {kind}"));
            list.push(element(&child, at)?);
        }
        Ok(out)
    }
}

/// One `<collision>` or `<visual>` element located at `at`.
fn element(node: &Node, at: Location) -> Result<GeometryElement, UrdfError> {
    let child = |tag: &str| node.children().find(|n| n.has_tag_name(tag));
    let origin = match child("origin") {
        Some(o) => {
            let xyz = numbers(&at, &o, "origin", "xyz")?.unwrap_or([0.0; 3]);
            let rpy = numbers(&at, &o, "origin", "rpy")?.unwrap_or([0.0; 3]);
            Isometry3::from_parts(
                Translation3::new(xyz[0], xyz[1], xyz[2]),
                UnitQuaternion::from_euler_angles(rpy[0], rpy[1], rpy[2]),
            )
        }
        None => Isometry3::identity(),
    };
    let geometry =
        child("geometry").ok_or_else(|| invalid(at.clone(), "geometry", "missing".into()))?;
    let Some(shape) = geometry.children().find(Node::is_element) else {
        return Err(invalid(at, "geometry", "has no shape element".into()));
    };
    let shape = read_shape(&at, &shape)?;
    Ok(GeometryElement { origin, shape, at })
}

/// The shape element `node` (`box`, `cylinder`, `sphere`, `capsule` or `mesh`).
fn read_shape(at: &Location, node: &Node) -> Result<Shape, UrdfError> {
    let tag = node.tag_name().name();
    let length = |attr: &str| -> Result<f64, UrdfError> {
        let [x] = positive(at, node, tag, attr)?;
        Ok(x)
    };
    Ok(match tag {
        "box" => Shape::Box {
            size: positive(at, node, tag, "size")?,
        },
        "cylinder" => Shape::Cylinder {
            radius: length("radius")?,
            length: length("length")?,
        },
        "capsule" => Shape::Capsule {
            radius: length("radius")?,
            length: length("length")?,
        },
        "sphere" => Shape::Sphere {
            radius: length("radius")?,
        },
        "mesh" => {
            let filename = match node.attribute("filename") {
                Some(f) if !f.trim().is_empty() => f.trim().to_string(),
                _ => return Err(invalid(at.clone(), "mesh filename", "missing".into())),
            };
            let scale = numbers(at, node, tag, "scale")?.unwrap_or([1.0; 3]);
            if scale.contains(&0.0) {
                let problem = format!("{scale:?} has a zero factor");
                return Err(invalid(at.clone(), "mesh scale", problem));
            }
            Shape::Mesh { filename, scale }
        }
        other => {
            let problem = format!("<{}> is not a supported shape", one_line(other));
            return Err(invalid(at.clone(), "geometry", problem));
        }
    })
}

/// The `N` finite numbers of the optional attribute `attr` of `node` (a `tag` element),
/// `None` when it is absent.
fn numbers<const N: usize>(
    at: &Location,
    node: &Node,
    tag: &str,
    attr: &str,
) -> Result<Option<[f64; N]>, UrdfError> {
    let Some(text) = node.attribute(attr) else {
        return Ok(None);
    };
    let values: Vec<f64> = text
        .split_whitespace()
        .map(|t| t.parse::<f64>().unwrap_or(f64::NAN))
        .collect();
    match <[f64; N]>::try_from(values) {
        Ok(v) if v.iter().all(|x| x.is_finite()) => Ok(Some(v)),
        _ => {
            let what = if N == 1 {
                "a finite number".to_string()
            } else {
                format!("{N} finite numbers")
            };
            let problem = format!("{:?} is not {what}", one_line(text));
            Err(invalid(at.clone(), &format!("{tag} {attr}"), problem))
        }
    }
}

/// The `N` numbers of the required attribute `attr` of `node`, each > 0.
fn positive<const N: usize>(
    at: &Location,
    node: &Node,
    tag: &str,
    attr: &str,
) -> Result<[f64; N], UrdfError> {
    let field = format!("{tag} {attr}");
    match numbers::<N>(at, node, tag, attr)? {
        None => Err(invalid(at.clone(), &field, "missing".into())),
        Some(v) if v.iter().any(|&x| x <= 0.0) => {
            let problem = format!("{v:?} must be > 0");
            Err(invalid(at.clone(), &field, problem))
        }
        Some(v) => Ok(v),
    }
}

/// An [`UrdfError::Invalid`].
fn invalid(at: Location, field: &str, problem: String) -> UrdfError {
    UrdfError::Invalid(InvalidElement {
        at,
        field: field.to_string(),
        problem,
    })
}
