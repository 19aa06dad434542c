//! Bounding spheres of single SSVs: the cheap lower bound used to prune SSV pairs.

use crate::primitives::Ssv;
use nalgebra::{Isometry3, Point3};

/// A sphere enclosing one SSV (centre and radius, the SSV radius included).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundingSphere {
    /// Sphere centre.
    pub center: Point3<f64>,
    /// Sphere radius (>= the SSV radius).
    pub radius: f64,
}

impl BoundingSphere {
    /// A small enclosing sphere of an SSV: exact for PSS and LSS, the minimal sphere of the
    /// triangle's vertices (plus r) for TSS.
    pub fn of_ssv(ssv: &Ssv) -> Self {
        let v = ssv.vertices();
        let center = match v.len() {
            1 => v[0],
            2 => nalgebra::center(&v[0], &v[1]),
            _ => triangle_center(&v[0], &v[1], &v[2]),
        };
        let reach = v
            .iter()
            .map(|p| (p - center).norm())
            .fold(0.0_f64, f64::max);
        Self {
            center,
            radius: reach + ssv.radius(),
        }
    }

    /// This sphere moved by a rigid transform.
    #[inline]
    pub fn transformed(&self, pose: &Isometry3<f64>) -> Self {
        Self {
            center: pose * self.center,
            radius: self.radius,
        }
    }

    /// Lower bound on the signed distance between anything inside `self` and inside `other`.
    #[inline]
    pub fn distance_lower_bound(&self, other: &Self) -> f64 {
        (other.center - self.center).norm() - self.radius - other.radius
    }
}

/// Centre of the minimal circle through/around three points: the midpoint of the longest
/// edge when it covers the third vertex (right or obtuse triangle), else the circumcentre.
fn triangle_center(a: &Point3<f64>, b: &Point3<f64>, c: &Point3<f64>) -> Point3<f64> {
    let edges = [(a, b, c), (b, c, a), (c, a, b)];
    let (p, q, o) = edges
        .iter()
        .copied()
        .max_by(|x, y| {
            let lx = (x.1 - x.0).norm_squared();
            let ly = (y.1 - y.0).norm_squared();
            lx.total_cmp(&ly)
        })
        .unwrap_or((a, b, c));
    let mid = nalgebra::center(p, q);
    let half = 0.5 * (q - p).norm();
    if (o - mid).norm() <= half {
        return mid;
    }
    circumcenter(a, b, c).unwrap_or_else(|| Point3::from((a.coords + b.coords + c.coords) / 3.0))
}

/// Circumcentre of a non-degenerate triangle; `None` when the vertices are (nearly) collinear.
fn circumcenter(a: &Point3<f64>, b: &Point3<f64>, c: &Point3<f64>) -> Option<Point3<f64>> {
    let u = b - a;
    let w = c - a;
    let n = u.cross(&w);
    let n2 = n.norm_squared();
    if n2 <= 1e-24 * u.norm_squared() * w.norm_squared() || n2 == 0.0 {
        return None;
    }
    let offset = (w * u.norm_squared() - u * w.norm_squared()).cross(&n) / (2.0 * n2);
    Some(a + offset)
}
