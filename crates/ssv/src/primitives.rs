//! The three swept-sphere-volume primitives PSS, LSS, TSS (thesis 6.3).
//!
//! Constructors validate their input (finite coordinates, radius >= 0), so the distance
//! functions that take these types never see NaN or infinity and never fail.

use crate::error::SsvError;
use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

/// `rot p + t` (a rigid transform in matrix form).
#[inline(always)]
fn affine(rot: &Matrix3<f64>, t: &Vector3<f64>, p: &Point3<f64>) -> Point3<f64> {
    Point3::from(rot * p.coords + t)
}

/// Largest accepted |coordinate| and radius: the distance formulas form products of up to four
/// coordinates, and 1e50 keeps every such product far from overflow (robot models live in
/// 1e-6 ... 1e6).
pub const MAX_MAGNITUDE: f64 = 1e50;

/// A finite value of magnitude at most [`MAX_MAGNITUDE`], or the error naming it.
fn check_value(value: f64, what: impl FnOnce() -> String) -> Result<(), SsvError> {
    if !value.is_finite() {
        return Err(SsvError::NonFinite {
            what: what(),
            value,
        });
    }
    if value.abs() > MAX_MAGNITUDE {
        return Err(SsvError::OutOfRange {
            what: what(),
            value,
        });
    }
    Ok(())
}

fn check_point(p: &Point3<f64>, what: &str) -> Result<(), SsvError> {
    for (axis, v) in ["x", "y", "z"].iter().zip(p.iter()) {
        check_value(*v, || format!("{what} {axis}"))?;
    }
    Ok(())
}

fn check_radius(r: f64) -> Result<(), SsvError> {
    if r.is_finite() && r < 0.0 {
        return Err(SsvError::NegativeRadius(r));
    }
    check_value(r, || "radius".into())
}

/// Point-swept-sphere volume: a sphere of radius `r` about centre `p` (6.3.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pss {
    center: Point3<f64>,
    radius: f64,
}

/// Line-swept-sphere volume: a capsule about segment `v0 + s e`, `s in [0, 1]` (6.3.2, 6.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lss {
    vertices: [Point3<f64>; 2],
    radius: f64,
}

/// Triangle-swept-sphere volume: a rounded triangle `v0 + s0 e0 + s1 e1` (6.3.3, 6.5-6.6).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tss {
    vertices: [Point3<f64>; 3],
    radius: f64,
}

impl Pss {
    /// A PSS; errors on non-finite input or negative radius.
    pub fn new(center: Point3<f64>, radius: f64) -> Result<Self, SsvError> {
        check_point(&center, "center")?;
        check_radius(radius)?;
        Ok(Self { center, radius })
    }
    /// Centre point p.
    #[inline]
    pub fn center(&self) -> &Point3<f64> {
        &self.center
    }
    /// Sphere radius r.
    #[inline]
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// This PSS moved by `x -> rot x + t`, with `rot` a rotation matrix (not validated: the
    /// caller passes the matrix of a finite rigid pose; cheaper than [`Self::transformed`]
    /// when many primitives share one pose).
    #[inline]
    pub fn transformed_by(&self, rot: &Matrix3<f64>, t: &Vector3<f64>) -> Self {
        Self {
            center: affine(rot, t, &self.center),
            radius: self.radius,
        }
    }
    /// This PSS moved by a rigid transform.
    #[inline]
    pub fn transformed(&self, pose: &Isometry3<f64>) -> Self {
        Self {
            center: pose * self.center,
            radius: self.radius,
        }
    }
}

impl Lss {
    /// An LSS from its two vertices; errors on non-finite input or negative radius.
    pub fn new(v0: Point3<f64>, v1: Point3<f64>, radius: f64) -> Result<Self, SsvError> {
        check_point(&v0, "vertex 0")?;
        check_point(&v1, "vertex 1")?;
        check_radius(radius)?;
        Ok(Self {
            vertices: [v0, v1],
            radius,
        })
    }
    /// The vertices v0, v1.
    #[inline]
    pub fn vertices(&self) -> &[Point3<f64>; 2] {
        &self.vertices
    }
    /// Sphere radius r.
    #[inline]
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// Point on the segment at parameter s, eq. (6.4).
    #[inline]
    pub fn point_at(&self, s: f64) -> Point3<f64> {
        self.vertices[0] + (self.vertices[1] - self.vertices[0]) * s
    }
    /// This LSS moved by `x -> rot x + t`, with `rot` a rotation matrix (not validated: the
    /// caller passes the matrix of a finite rigid pose; cheaper than [`Self::transformed`]
    /// when many primitives share one pose).
    #[inline]
    pub fn transformed_by(&self, rot: &Matrix3<f64>, t: &Vector3<f64>) -> Self {
        Self {
            vertices: self.vertices.map(|v| affine(rot, t, &v)),
            radius: self.radius,
        }
    }
    /// This LSS moved by a rigid transform.
    #[inline]
    pub fn transformed(&self, pose: &Isometry3<f64>) -> Self {
        Self {
            vertices: [pose * self.vertices[0], pose * self.vertices[1]],
            radius: self.radius,
        }
    }
}

impl Tss {
    /// A TSS from its three vertices; errors on non-finite input or negative radius.
    pub fn new(
        v0: Point3<f64>,
        v1: Point3<f64>,
        v2: Point3<f64>,
        radius: f64,
    ) -> Result<Self, SsvError> {
        check_point(&v0, "vertex 0")?;
        check_point(&v1, "vertex 1")?;
        check_point(&v2, "vertex 2")?;
        check_radius(radius)?;
        Ok(Self {
            vertices: [v0, v1, v2],
            radius,
        })
    }
    /// The vertices v0, v1, v2.
    #[inline]
    pub fn vertices(&self) -> &[Point3<f64>; 3] {
        &self.vertices
    }
    /// Sphere radius r.
    #[inline]
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// Point on the triangle at parameters (s0, s1), eq. (6.5).
    #[inline]
    pub fn point_at(&self, s0: f64, s1: f64) -> Point3<f64> {
        let [v0, v1, v2] = self.vertices;
        v0 + (v1 - v0) * s0 + (v2 - v0) * s1
    }
    /// This TSS moved by `x -> rot x + t`, with `rot` a rotation matrix (not validated: the
    /// caller passes the matrix of a finite rigid pose; cheaper than [`Self::transformed`]
    /// when many primitives share one pose).
    #[inline]
    pub fn transformed_by(&self, rot: &Matrix3<f64>, t: &Vector3<f64>) -> Self {
        Self {
            vertices: self.vertices.map(|v| affine(rot, t, &v)),
            radius: self.radius,
        }
    }
    /// This TSS moved by a rigid transform.
    #[inline]
    pub fn transformed(&self, pose: &Isometry3<f64>) -> Self {
        Self {
            vertices: self.vertices.map(|v| pose * v),
            radius: self.radius,
        }
    }
}

/// Any of the three SSV primitives.
///
/// # Example
///
/// SSVs are usually defined in a body frame and moved with the body: a sphere 0.1 m along
/// the body's x axis, with the body turned by 90 degrees about z, lands on the world y axis.
///
/// ```
/// use biped_ssv::{distance, Pss, Ssv};
/// use nalgebra::{Isometry3, Point3, Vector3};
///
/// let local = Ssv::from(Pss::new(Point3::new(0.1, 0.0, 0.0), 0.02)?);
/// let pose = Isometry3::new(Vector3::new(0.0, 0.0, 1.0), Vector3::z() * std::f64::consts::FRAC_PI_2);
/// let world = local.transformed(&pose);
/// assert!((world.vertices()[0] - Point3::new(0.0, 0.1, 1.0)).norm() < 1e-15);
///
/// // two spheres: centre distance minus both radii
/// let other = Ssv::from(Pss::new(Point3::new(0.0, 0.1, 1.5), 0.08)?);
/// assert!((distance(&world, &other).distance - (0.5 - 0.02 - 0.08)).abs() < 1e-15);
/// # Ok::<(), biped_ssv::SsvError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ssv {
    /// Point-swept sphere.
    Point(Pss),
    /// Line-swept sphere (capsule).
    Line(Lss),
    /// Triangle-swept sphere.
    Triangle(Tss),
}

impl Ssv {
    /// Sphere radius r of the primitive.
    #[inline]
    pub fn radius(&self) -> f64 {
        match self {
            Ssv::Point(p) => p.radius(),
            Ssv::Line(l) => l.radius(),
            Ssv::Triangle(t) => t.radius(),
        }
    }
    /// The primitive's vertices (1, 2 or 3 of them).
    pub fn vertices(&self) -> &[Point3<f64>] {
        match self {
            Ssv::Point(p) => std::slice::from_ref(&p.center),
            Ssv::Line(l) => &l.vertices,
            Ssv::Triangle(t) => &t.vertices,
        }
    }
    /// Sets `self` to `body` moved by `x -> rot x + t`, in place (see
    /// [`Pss::transformed_by`]); cheaper than assigning a new value when the kinds agree.
    #[inline]
    pub fn set_transformed_by(&mut self, body: &Ssv, rot: &Matrix3<f64>, t: &Vector3<f64>) {
        match (self, body) {
            (Ssv::Point(w), Ssv::Point(b)) => w.center = affine(rot, t, &b.center),
            (Ssv::Line(w), Ssv::Line(b)) => {
                for (x, v) in w.vertices.iter_mut().zip(&b.vertices) {
                    *x = affine(rot, t, v);
                }
            }
            (Ssv::Triangle(w), Ssv::Triangle(b)) => {
                for (x, v) in w.vertices.iter_mut().zip(&b.vertices) {
                    *x = affine(rot, t, v);
                }
            }
            (w, b) => *w = b.transformed_by(rot, t),
        }
    }

    /// This SSV moved by `x -> rot x + t` (see [`Pss::transformed_by`]).
    #[inline]
    pub fn transformed_by(&self, rot: &Matrix3<f64>, t: &Vector3<f64>) -> Self {
        match self {
            Ssv::Point(p) => Ssv::Point(p.transformed_by(rot, t)),
            Ssv::Line(l) => Ssv::Line(l.transformed_by(rot, t)),
            Ssv::Triangle(x) => Ssv::Triangle(x.transformed_by(rot, t)),
        }
    }
    /// This SSV moved by a rigid transform.
    #[inline]
    pub fn transformed(&self, pose: &Isometry3<f64>) -> Self {
        match self {
            Ssv::Point(p) => Ssv::Point(p.transformed(pose)),
            Ssv::Line(l) => Ssv::Line(l.transformed(pose)),
            Ssv::Triangle(t) => Ssv::Triangle(t.transformed(pose)),
        }
    }
}

impl From<Pss> for Ssv {
    fn from(p: Pss) -> Self {
        Ssv::Point(p)
    }
}
impl From<Lss> for Ssv {
    fn from(l: Lss) -> Self {
        Ssv::Line(l)
    }
}
impl From<Tss> for Ssv {
    fn from(t: Tss) -> Self {
        Ssv::Triangle(t)
    }
}
