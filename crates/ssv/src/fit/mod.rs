//! Fitting SSVs that contain a body's geometry, for a first collision model from CAD-like
//! shapes (spheres, capsules, cylinders, boxes, meshes as point clouds).
//!
//! - sphere -> point SSV and capsule -> line SSV (exact);
//! - cylinder -> the line SSV of its axis with its radius (contains it, rounded ends);
//! - box -> the smallest of: the rectangle of its two largest dimensions (two triangle SSVs)
//!   swept by half the smallest, the line SSV of its longest axis, the bounding sphere;
//! - points (mesh vertices) -> the smallest of the bounding sphere, the line SSV along the
//!   principal axis (radius = largest distance from the axis, segment shortened as far as
//!   containment allows) and the rectangle in the plane of the two principal axes.
//!
//! Every fit is checked against the points it must contain (box corners, cylinder rims, mesh
//! vertices) with the library's own [`distance`](crate::distance()); a positive distance left by
//! rounding is added to the radius, so each point ends up inside.

mod cloud;
pub mod pairs;
mod shapes;
mod volume;

use crate::distance;
use crate::error::SsvError;
use crate::primitives::{Lss, Pss, Ssv, Tss};
use nalgebra::{Isometry3, Point3, Vector3};
use std::fmt;

/// What can be wrong with a fit's input.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FitError {
    /// A point cloud without points.
    #[error("no points to fit")]
    NoPoints,
    /// A dimension that is not finite and > 0.
    #[error("{what} must be finite and > 0, got {value}")]
    BadDimension {
        /// Which dimension.
        what: &'static str,
        /// Its value.
        value: f64,
    },
    /// A coordinate the SSV primitives reject (non-finite or beyond their range).
    #[error(transparent)]
    Ssv(#[from] SsvError),
}

/// A shape to contain, in its own frame (placed by the `pose` of [`fit`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Geometry<'a> {
    /// A sphere about the origin.
    Sphere {
        /// Radius.
        radius: f64,
    },
    /// A capsule: cylinder of `length` along z, centred, with hemispherical caps.
    Capsule {
        /// Radius.
        radius: f64,
        /// Length of the cylindrical part.
        length: f64,
    },
    /// A cylinder of `length` along z, centred at the origin.
    Cylinder {
        /// Radius.
        radius: f64,
        /// Length.
        length: f64,
    },
    /// A box with these full edge lengths, centred at the origin.
    Cuboid {
        /// Edge lengths along x, y, z.
        size: [f64; 3],
    },
    /// A point cloud (e.g. mesh vertices) and the volume it encloses, if known.
    Points {
        /// The points.
        points: &'a [Point3<f64>],
        /// Enclosed volume (a closed mesh's), `None` if unknown.
        volume: Option<f64>,
    },
}

impl Geometry<'_> {
    /// The shape's volume (`None` for points of unknown volume).
    pub fn volume(&self) -> Option<f64> {
        use std::f64::consts::PI;
        match *self {
            Geometry::Sphere { radius: r } => Some(4.0 / 3.0 * PI * r.powi(3)),
            Geometry::Capsule { radius: r, length } => {
                Some(PI * r * r * length + 4.0 / 3.0 * PI * r.powi(3))
            }
            Geometry::Cylinder { radius: r, length } => Some(PI * r * r * length),
            Geometry::Cuboid { size } => Some(size.iter().product()),
            Geometry::Points { volume, .. } => volume,
        }
    }
}

/// The kind of SSV compound a fit chose.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FitKind {
    /// One point SSV (sphere).
    Point,
    /// One line SSV (capsule).
    Line,
    /// A rectangle: two triangle SSVs sharing a diagonal.
    Rectangle,
}

impl fmt::Display for FitKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FitKind::Point => "point",
            FitKind::Line => "line",
            FitKind::Rectangle => "rectangle",
        })
    }
}

/// The SSVs fitted to one shape.
#[derive(Debug, Clone, PartialEq)]
pub struct Fitted {
    /// What was chosen.
    pub kind: FitKind,
    /// The SSVs (one, or two for a rectangle), in the frame of the `pose` given to [`fit`].
    pub ssvs: Vec<Ssv>,
    /// Volume of the SSV compound.
    pub volume: f64,
    /// Volume of the shape (`None` if unknown).
    pub shape_volume: Option<f64>,
}

impl Fitted {
    /// SSV volume over shape volume (>= 1 for a containing fit), `None` if unknown.
    pub fn overhead(&self) -> Option<f64> {
        self.shape_volume
            .filter(|&v| v > 0.0)
            .map(|v| self.volume / v)
    }
}

/// The SSVs containing `geometry` placed at `pose` (see the module docs).
pub fn fit(geometry: &Geometry, pose: &Isometry3<f64>) -> Result<Fitted, FitError> {
    let candidate = match *geometry {
        Geometry::Sphere { radius } => shapes::sphere(pose, radius)?,
        Geometry::Capsule { radius, length } => shapes::capsule(pose, radius, length)?,
        Geometry::Cylinder { radius, length } => shapes::cylinder(pose, radius, length)?,
        Geometry::Cuboid { size } => shapes::cuboid(pose, size)?,
        Geometry::Points { points, .. } => {
            let placed: Vec<Point3<f64>> = points.iter().map(|p| pose * p).collect();
            cloud::fit_points(&placed)?
        }
    };
    Ok(Fitted {
        kind: candidate.kind(),
        volume: candidate.volume(),
        ssvs: candidate.ssvs()?,
        shape_volume: geometry.volume(),
    })
}

/// An SSV compound during fitting: a sphere, a capsule or a rounded rectangle.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Candidate {
    Point(Point3<f64>, f64),
    Line(Point3<f64>, Point3<f64>, f64),
    /// Corner and the two side vectors.
    Rectangle(Point3<f64>, Vector3<f64>, Vector3<f64>, f64),
}

impl Candidate {
    /// The rectangle `corner + s u + t v`, a line or a point if it is degenerate.
    fn rectangle(corner: Point3<f64>, u: Vector3<f64>, v: Vector3<f64>, r: f64) -> Self {
        match (u == Vector3::zeros(), v == Vector3::zeros()) {
            (true, true) => Candidate::Point(corner, r),
            (false, true) => Candidate::line(corner, corner + u, r),
            (true, false) => Candidate::line(corner, corner + v, r),
            (false, false) => Candidate::Rectangle(corner, u, v, r),
        }
    }

    /// The capsule about `a`-`b`, a point if `a == b`.
    fn line(a: Point3<f64>, b: Point3<f64>, r: f64) -> Self {
        match a == b {
            true => Candidate::Point(a, r),
            false => Candidate::Line(a, b, r),
        }
    }

    fn kind(&self) -> FitKind {
        match self {
            Candidate::Point(..) => FitKind::Point,
            Candidate::Line(..) => FitKind::Line,
            Candidate::Rectangle(..) => FitKind::Rectangle,
        }
    }

    fn volume(&self) -> f64 {
        match *self {
            Candidate::Point(_, r) => volume::point(r),
            Candidate::Line(a, b, r) => volume::line((b - a).norm(), r),
            Candidate::Rectangle(_, u, v, r) => volume::rectangle(u.norm(), v.norm(), r),
        }
    }

    fn radius_mut(&mut self) -> &mut f64 {
        match self {
            Candidate::Point(_, r)
            | Candidate::Line(_, _, r)
            | Candidate::Rectangle(_, _, _, r) => r,
        }
    }

    fn ssvs(&self) -> Result<Vec<Ssv>, SsvError> {
        Ok(match *self {
            Candidate::Point(c, r) => vec![Pss::new(c, r)?.into()],
            Candidate::Line(a, b, r) => vec![Lss::new(a, b, r)?.into()],
            Candidate::Rectangle(c, u, v, r) => vec![
                Tss::new(c, c + u, c + u + v, r)?.into(),
                Tss::new(c, c + u + v, c + v, r)?.into(),
            ],
        })
    }

    /// This candidate with its radius grown until every point has signed distance <= 0.
    fn containing(mut self, points: &[Point3<f64>]) -> Result<Self, SsvError> {
        let excess = max_distance(&self.ssvs()?, points)?;
        if excess > 0.0 {
            *self.radius_mut() += excess;
        }
        Ok(self)
    }
}

/// The largest signed distance of any of `points` to the union of `ssvs` (the distance of a
/// point SSV of radius 0 to the nearest SSV).
pub fn max_distance(ssvs: &[Ssv], points: &[Point3<f64>]) -> Result<f64, SsvError> {
    let mut worst = f64::NEG_INFINITY;
    for p in points {
        let probe = Ssv::from(Pss::new(*p, 0.0)?);
        let d = ssvs
            .iter()
            .map(|s| distance(&probe, s).distance)
            .fold(f64::INFINITY, f64::min);
        worst = worst.max(d);
    }
    Ok(worst)
}

/// Checks that `x` is finite and > 0.
fn positive(what: &'static str, value: f64) -> Result<f64, FitError> {
    match value.is_finite() && value > 0.0 {
        true => Ok(value),
        false => Err(FitError::BadDimension { what, value }),
    }
}
