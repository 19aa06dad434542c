//! The result of a distance query between two SSVs, eqs. (6.9)-(6.11).

use nalgebra::{Point3, Vector3};

/// Where the closest point lies on an underlying primitive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PrimitiveParam {
    /// A point has no parameter.
    Point,
    /// Line parameter s in [0, 1] of eq. (6.4).
    Line(f64),
    /// Triangle parameters (s0, s1) of eq. (6.5), subject to (6.6).
    Triangle(f64, f64),
}

impl PrimitiveParam {
    /// Barycentric weights of the vertices (1, 2 or 3 of them; unused ones are 0).
    pub fn barycentric(&self) -> [f64; 3] {
        match *self {
            PrimitiveParam::Point => [1.0, 0.0, 0.0],
            PrimitiveParam::Line(s) => [1.0 - s, s, 0.0],
            PrimitiveParam::Triangle(s0, s1) => [1.0 - s0 - s1, s0, s1],
        }
    }
}

/// Result of `dist(A, B)`: signed distance, closest points on both SSV surfaces and on
/// both underlying primitives (6.9)-(6.11).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DistanceResult {
    /// Signed distance d = |c*| - r_a - r_b; negative when the volumes overlap.
    pub distance: f64,
    /// Closest point on the surface of SSV a, p_SSV,0 of (6.11).
    pub point_a: Point3<f64>,
    /// Closest point on the surface of SSV b, p_SSV,1 of (6.11).
    pub point_b: Point3<f64>,
    /// Unit direction from a towards b (c*/|c*|; the documented rule when c* = 0).
    pub normal: Vector3<f64>,
    /// Closest point p*_0 on the underlying primitive of a (6.9).
    pub closest_a: Point3<f64>,
    /// Closest point p*_1 on the underlying primitive of b (6.9).
    pub closest_b: Point3<f64>,
    /// Parameters of `closest_a` on primitive a.
    pub param_a: PrimitiveParam,
    /// Parameters of `closest_b` on primitive b.
    pub param_b: PrimitiveParam,
}

impl DistanceResult {
    /// Connecting vector r_c = p_SSV,1 - p_SSV,0 of (6.11) (equals `distance * normal`).
    #[inline]
    pub fn connecting(&self) -> Vector3<f64> {
        self.point_b - self.point_a
    }
    /// Vector c* = p*_1 - p*_0 between the underlying primitives, eq. (6.10).
    #[inline]
    pub fn c_star(&self) -> Vector3<f64> {
        self.closest_b - self.closest_a
    }
    /// The result of the reversed query dist(B, A): the swap relation of Table 6.1.
    #[inline]
    pub fn swapped(self) -> Self {
        Self {
            distance: self.distance,
            point_a: self.point_b,
            point_b: self.point_a,
            normal: -self.normal,
            closest_a: self.closest_b,
            closest_b: self.closest_a,
            param_a: self.param_b,
            param_b: self.param_a,
        }
    }
}
