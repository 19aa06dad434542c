//! Case families: builders turning raw random numbers into SSV pairs of given kinds.

use super::{log_mag, make, vec3, Kind, Raw};
use crate::reference;
use biped_ssv::Ssv;
use nalgebra::{Point3, Vector3};

/// Three points from the raw vectors, scaled by `s` and shifted by `c`.
fn points(raw: &Raw, c: Vector3<f64>, s: f64) -> [Point3<f64>; 3] {
    [0, 1, 2].map(|i| Point3::from(c + vec3(raw, i) * s))
}

/// Radius from a raw scalar: exactly 0 for a fifth of the cases, else up to `max`.
fn radius(s: f64, max: f64) -> f64 {
    if s < 0.2 {
        0.0
    } else {
        max * (s - 0.2) / 0.8
    }
}

/// Generic positions: coordinates in [-10, 10], radii in [0, 2].
pub fn random(ka: Kind, kb: Kind, a: &Raw, b: &Raw, _c: &Raw) -> (Ssv, Ssv) {
    let shape = |k, r: &Raw| make(k, points(r, Vector3::zeros(), 10.0), radius(r.1[0], 2.0));
    (shape(ka, a), shape(kb, b))
}

/// Integer lattice {-2..2}^3 with radii {0, 0.5, 1}: coincident points, zero-length
/// segments, collinear triangles, exact parallelism, coplanarity and exact touching.
pub fn lattice(ka: Kind, kb: Kind, a: &Raw, b: &Raw, _c: &Raw) -> (Ssv, Ssv) {
    let shape = |k, r: &Raw| {
        let v = points(r, Vector3::zeros(), 2.5).map(|p| p.map(f64::round));
        make(k, v, (r.1[0] * 3.0).floor() * 0.5)
    };
    (shape(ka, a), shape(kb, b))
}

/// Mixed scales: a common centre with coordinates up to 1e6, shapes of size 1e-6..1e6
/// placed 1e-6..1e6 from it, radii 0..1e6 (each magnitude log-uniform).
pub fn mixed_scale(ka: Kind, kb: Kind, a: &Raw, b: &Raw, c: &Raw) -> (Ssv, Ssv) {
    let centre = vec3(c, 0) * log_mag(c.1[0], -6.0, 6.0);
    let shape = |k, r: &Raw, off: Vector3<f64>| {
        let o = centre + off * log_mag(r.1[1], -6.0, 6.0);
        let v = points(r, o, log_mag(r.1[2], -6.0, 6.0));
        make(k, v, radius(r.1[0], log_mag(r.1[3], -6.0, 6.0)))
    };
    (shape(ka, a, vec3(c, 1)), shape(kb, b, vec3(c, 2)))
}

/// Touching: a random pair whose radii split the primitive distance D exactly,
/// so r_a + r_b = D and the signed distance is 0.
pub fn touching(ka: Kind, kb: Kind, a: &Raw, b: &Raw, c: &Raw) -> (Ssv, Ssv) {
    let (va, vb) = (
        points(a, Vector3::zeros(), 10.0),
        points(b, Vector3::zeros(), 10.0),
    );
    let (sa, sb) = (make(ka, va, 0.0), make(kb, vb, 0.0));
    let d = reference::closest(sa.vertices(), sb.vertices()).dist;
    let ra = d * c.1[0];
    (make(ka, va, ra), make(kb, vb, d - ra))
}

/// Intersecting: both primitives contain a common point q (crossing segments, a segment
/// piercing a triangle, intersecting triangles, points on segments/triangles).
pub fn intersecting(ka: Kind, kb: Kind, a: &Raw, b: &Raw, c: &Raw) -> (Ssv, Ssv) {
    let q = vec3(c, 0) * 3.0;
    (through(ka, q, a), through(kb, q, b))
}

/// A primitive of `kind` containing the point q.
fn through(kind: Kind, q: Vector3<f64>, r: &Raw) -> Ssv {
    let rad = radius(r.1[5], 1.0);
    let v = match kind {
        Kind::P => [q; 3],
        Kind::L => {
            let d = vec3(r, 0) * 3.0;
            [q + d * r.1[0], q - d * r.1[1], q]
        }
        Kind::T => {
            let (b0, b1) = (q + vec3(r, 0) * 3.0, q + vec3(r, 1) * 3.0);
            let m = b0 + (b1 - b0) * r.1[0];
            [b0, b1, q + (q - m) * (0.1 + 3.0 * r.1[1])]
        }
    };
    make(kind, v.map(Point3::from), rad)
}

/// An orthonormal frame from two raw vectors (falls back to the axes if degenerate).
fn frame(c: &Raw) -> [Vector3<f64>; 3] {
    let u = vec3(c, 1);
    let w = vec3(c, 2);
    match (u.try_normalize(1e-3), u.cross(&w).try_normalize(1e-3)) {
        (Some(e1), Some(e3)) => [e1, e3.cross(&e1), e3],
        _ => [Vector3::x(), Vector3::y(), Vector3::z()],
    }
}

/// An angle that is exactly 0 for 15% of the cases, else log-uniform in [1e-12, 0.1] rad,
/// with a random sign (anti-parallel included via the caller's direction flips).
fn tiny_angle(s: f64) -> f64 {
    if s < 0.15 {
        0.0
    } else {
        let t = (s - 0.15) / 0.85;
        let mag = log_mag((2.0 * t).fract(), -12.0, -1.0);
        if t < 0.5 {
            mag
        } else {
            -mag
        }
    }
}

/// A small height: exactly 0 for 20% of the cases, else log-uniform in [1e-9, 2].
fn small(s: f64) -> f64 {
    if s < 0.2 {
        0.0
    } else {
        log_mag((s - 0.2) / 0.8, -9.0, 0.3)
    }
}

/// Near-degenerate configurations for each pair type: near-parallel segments, segments
/// near-parallel to triangles and their edges, near-parallel triangle planes, tiny
/// segments, sliver triangles, nearly coincident points.
pub fn near_degenerate(ka: Kind, kb: Kind, a: &Raw, b: &Raw, c: &Raw) -> (Ssv, Ssv) {
    let o = vec3(c, 0) * 5.0;
    let e = frame(c);
    let (ra, rb) = (radius(a.1[5], 1.0), radius(b.1[5], 1.0));
    let at = |x: f64, y: f64, z: f64| Point3::from(o + e[0] * x + e[1] * y + e[2] * z);
    let v = match (ka, kb) {
        (Kind::P, Kind::P) => {
            let p = at(0.0, 0.0, 0.0);
            let step = if a.1[0] < 0.2 {
                0.0
            } else {
                log_mag(a.1[1], -15.0, 0.0)
            };
            [[p; 3], [p + vec3(b, 0) * step; 3]]
        }
        (Kind::P, Kind::L) => {
            // A tiny (or zero-length) segment on e1, a point near its line.
            let len = if b.1[0] < 0.15 {
                0.0
            } else {
                log_mag(b.1[0], -12.0, 0.5)
            };
            let s = b.1[1] * 3.0 - 1.0;
            let seg = [at(0.0, 0.0, 0.0), at(len, 0.0, 0.0), at(0.0, 0.0, 0.0)];
            [[at(s * len, small(a.1[0]), small(a.1[1]) * 0.1); 3], seg]
        }
        (Kind::P, Kind::T) => {
            let tri = sliver(b, &at);
            let (x, y) = (a.1[0] * 3.0 - 1.0, a.1[1] * 2.0 - 1.0);
            [[at(x, y * small(a.1[2]), small(a.1[3])); 3], tri]
        }
        (Kind::L, Kind::L) => near_parallel_segments(a, b, &at),
        (Kind::L, Kind::T) => {
            let tri = planar_triangle(b, &at, 0.0, 0.0);
            [segment_near_plane(a, &tri, &at, &e), tri]
        }
        (Kind::T, Kind::T) => {
            let ta = planar_triangle(a, &at, 0.0, 0.0);
            let tb = if b.1[4] < 0.3 {
                sliver(b, &at)
            } else {
                planar_triangle(b, &at, tiny_angle(b.1[3]), small(b.1[4]))
            };
            [ta, tb]
        }
        _ => unreachable!("pairs are generated in upper-triangle order"),
    };
    (make(ka, v[0], ra), make(kb, v[1], rb))
}

/// Two segments with directions at a tiny angle (or exactly parallel, or anti-parallel),
/// overlapping or disjoint along the common direction, at a small lateral offset.
fn near_parallel_segments(
    a: &Raw,
    b: &Raw,
    at: &dyn Fn(f64, f64, f64) -> Point3<f64>,
) -> [[Point3<f64>; 3]; 2] {
    let la = 0.01 + 2.0 * a.1[0];
    let lb = (0.01 + 2.0 * b.1[0]) * if b.1[1] < 0.5 { 1.0 } else { -1.0 };
    let th = tiny_angle(a.1[1]);
    let start = 6.0 * b.1[2] - 3.0;
    let (h1, h2) = (small(a.1[2]), small(a.1[3]) * (2.0 * b.1[3] - 1.0));
    let a0 = at(0.0, 0.0, 0.0);
    let b0 = at(start, h1, h2);
    let b1 = at(start + lb * th.cos(), h1 + lb * th.sin(), h2);
    [[a0, at(la, 0.0, 0.0), a0], [b0, b1, b0]]
}

/// A triangle with in-plane coordinates from the raw vectors, in the plane through o
/// spanned by e1 and (e2 rotated by `tilt` about e1), lifted by `lift` along e3.
fn planar_triangle(
    r: &Raw,
    at: &dyn Fn(f64, f64, f64) -> Point3<f64>,
    tilt: f64,
    lift: f64,
) -> [Point3<f64>; 3] {
    let (c, s) = (tilt.cos(), tilt.sin());
    [0, 1, 2].map(|i| {
        let (x, y) = (2.0 * r.0[3 * i], 2.0 * r.0[3 * i + 1]);
        at(x, c * y, s * y + lift)
    })
}

/// A segment almost parallel to the plane of `tri` (or to one of its edges), at a small
/// height above it, possibly over its interior.
fn segment_near_plane(
    r: &Raw,
    tri: &[Point3<f64>; 3],
    at: &dyn Fn(f64, f64, f64) -> Point3<f64>,
    e: &[Vector3<f64>; 3],
) -> [Point3<f64>; 3] {
    let th = tiny_angle(r.1[0]);
    let dir = if r.1[1] < 0.5 {
        (tri[1] - tri[0]).try_normalize(0.0).unwrap_or(e[0])
    } else {
        e[0]
    };
    let dir = dir * th.cos() + e[2] * th.sin();
    let start = at(
        2.0 * r.0[0],
        2.0 * r.0[1],
        small(r.1[2]) * (2.0 * r.1[3] - 1.0),
    );
    let len = 0.01 + 3.0 * r.1[4];
    [start, start + dir * len, start]
}

/// A sliver: v2 almost (or exactly) on the line v0 v1, or two coincident vertices.
fn sliver(r: &Raw, at: &dyn Fn(f64, f64, f64) -> Point3<f64>) -> [Point3<f64>; 3] {
    let l = 0.1 + 2.0 * r.1[0];
    let t = 3.0 * r.1[1] - 1.0;
    let w = if r.1[2] < 0.2 {
        0.0
    } else {
        log_mag(r.1[2], -12.0, -1.0)
    };
    let v0 = at(0.0, 0.0, 0.0);
    let v1 = if r.1[3] < 0.15 { v0 } else { at(l, 0.0, 0.0) };
    [v0, v1, at(t * l, w, 0.0)]
}

/// Exact power-of-two rescaling (2^-20 .. 2^20, i.e. about 1e-6 .. 1e6) of a random,
/// near-degenerate or intersecting pair; checked with a purely relative tolerance.
pub fn pow2_scaled(ka: Kind, kb: Kind, a: &Raw, b: &Raw, c: &Raw) -> (Ssv, Ssv) {
    let base: super::Builder = match (c.1[5] * 3.0) as usize {
        0 => random,
        1 => near_degenerate,
        _ => intersecting,
    };
    let (sa, sb) = base(ka, kb, a, b, c);
    let f = 2f64.powi((c.1[4] * 41.0) as i32 - 20);
    (rescale(ka, &sa, f), rescale(kb, &sb, f))
}

/// The SSV with all coordinates and the radius multiplied by `f`.
fn rescale(kind: Kind, s: &Ssv, f: f64) -> Ssv {
    let mut v = [Point3::origin(); 3];
    for (vi, si) in v.iter_mut().zip(s.vertices().iter().cycle()) {
        *vi = si * f;
    }
    make(kind, v, s.radius() * f)
}
