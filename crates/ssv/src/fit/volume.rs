//! Volumes of the SSV compounds (Steiner's formula for a flat convex set swept by a ball:
//! area x thickness + perimeter x half-cylinder + sphere).

use std::f64::consts::PI;

/// A sphere of radius `r`.
pub(super) fn point(r: f64) -> f64 {
    4.0 / 3.0 * PI * r.powi(3)
}

/// A capsule: segment of length `l` swept by radius `r`.
pub(super) fn line(l: f64, r: f64) -> f64 {
    PI * r * r * l + point(r)
}

/// An `a` x `b` rectangle swept by radius `r`: slab `2 r a b`, half cylinders along the
/// perimeter `pi r^2 (a + b)`, quarter spheres at the corners.
pub(super) fn rectangle(a: f64, b: f64, r: f64) -> f64 {
    2.0 * r * a * b + PI * r * r * (a + b) + point(r)
}
