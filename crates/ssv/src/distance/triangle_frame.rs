//! Per-triangle precomputation shared by PT, LT and TT: the plane projection (6.21) solved by
//! orthogonalisation (QR, not the normal equations), the relative flatness test and the edges.
//!
//! With e0 = v1 - v0, e1 = v2 - v0 and F' the part of e1 orthogonal to e0 (two Gram-Schmidt
//! passes, so F' is orthogonal to e0 to machine precision), a point q = p - v0 has
//! s1 = q.F'/F'.F' and s0 = (q.e0 - s1 e1.e0)/e0.e0. This back substitution keeps the
//! reconstructed point backward stable even for slivers whose parameters are ill-conditioned.

use super::assemble::{boundary_edges, clamp01, inv_or_zero, SIN2_EPS};
use super::line_line::Seg;
use crate::primitives::Tss;
use nalgebra::{Point3, Vector3};

/// A triangle prepared for distance queries (6.5, 6.21).
#[derive(Debug, Clone, Copy)]
pub(crate) struct TriFrame {
    /// Vertices v0, v1, v2.
    pub v: [Point3<f64>; 3],
    /// Boundary edges v_{i+1} - v_i (e[0] = e0 of (6.5), e[2] = -e1).
    pub e: [Vector3<f64>; 3],
    /// |e_i|^2 per boundary edge.
    pub ee: [f64; 3],
    /// 1/|e_i|^2 per boundary edge (0 for a zero-length edge).
    pub inv_ee: [f64; 3],
    /// Unnormalised normal e0 x F' (= e0 x e1, with rounding that only tilts it about e0).
    pub n: Vector3<f64>,
    /// 1/|n|^2 (0 when flat).
    pub inv_nn: f64,
    /// F': the part of e1 orthogonal to e0.
    fp: Vector3<f64>,
    /// 1/|F'|^2 (0 when flat).
    inv_fpfp: f64,
    /// e1 . e0.
    fe: f64,
    /// The angle at v0 has sin^2 <= SIN2_EPS (includes collinear and coincident vertices):
    /// no face, the triangle is the union of its edges (its longest edge).
    pub flat: bool,
}

/// Plane projection of a point: parameters (s0, s1) of (6.21) and the scaled height n . q.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Proj {
    /// s0 (weight of v1).
    pub s0: f64,
    /// s1 (weight of v2).
    pub s1: f64,
    /// n . (p - v0): signed height times |n|.
    pub h: f64,
}

impl Proj {
    /// True when the projection lies in the triangle, i.e. (6.6) holds.
    #[inline(always)]
    pub fn inside(&self) -> bool {
        (self.s0 >= 0.0) & (self.s1 >= 0.0) & (self.s0 + self.s1 <= 1.0)
    }

    /// The parameters forced into (6.6).
    #[inline(always)]
    pub fn params(&self) -> (f64, f64) {
        let s0 = clamp01(self.s0);
        (s0, clamp01(self.s1).min(1.0 - s0))
    }
}

impl TriFrame {
    /// Prepares a triangle.
    #[inline(always)]
    pub fn new(t: &Tss) -> Self {
        let v = *t.vertices();
        let e = boundary_edges(&v);
        let ee = e.map(|x| x.norm_squared());
        let inv_ee = ee.map(inv_or_zero);
        let e1 = v[2] - v[0];
        let fe = e1.dot(&e[0]);
        let fp = e1 - e[0] * (fe * inv_ee[0]);
        let fp = fp - e[0] * (fp.dot(&e[0]) * inv_ee[0]);
        let fpfp = fp.norm_squared();
        let flat = fpfp * ee[0] <= SIN2_EPS * ee[0] * ee[2];
        let inv_fpfp = if flat { 0.0 } else { 1.0 / fpfp };
        Self {
            v,
            e,
            ee,
            inv_ee,
            n: e[0].cross(&fp),
            inv_nn: inv_fpfp * inv_ee[0],
            fp,
            inv_fpfp,
            fe,
            flat,
        }
    }

    /// Plane projection (6.21) of a point.
    #[inline(always)]
    pub fn project(&self, p: &Point3<f64>) -> Proj {
        let q = p - self.v[0];
        let s1 = self.fp.dot(&q) * self.inv_fpfp;
        let s0 = (self.e[0].dot(&q) - s1 * self.fe) * self.inv_ee[0];
        Proj {
            s0,
            s1,
            h: self.n.dot(&q),
        }
    }

    /// Boundary edge i as a segment from v_i.
    #[inline(always)]
    pub fn edge(&self, i: usize) -> Seg {
        Seg {
            p: self.v[i],
            u: self.e[i],
            uu: self.ee[i],
            inv_uu: self.inv_ee[i],
        }
    }

    /// Point (6.5) at parameters (s0, s1).
    #[inline(always)]
    pub fn point_at(&self, s: (f64, f64)) -> Point3<f64> {
        self.v[0] + self.e[0] * s.0 - self.e[2] * s.1
    }
}
