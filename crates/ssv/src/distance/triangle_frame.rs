//! Per-triangle precomputation shared by PT, LT and TT: the plane projection (6.21) solved by
//! orthogonalisation against the longest edge (QR, not the normal equations), the relative
//! flatness test and the edges.
//!
//! With E the longest edge from vertex v_k, F = v_{k+2} - v_k and F' the part of F orthogonal
//! to E (two Gram-Schmidt passes, so F' is orthogonal to E to machine precision), a point
//! q = p - v_k has the weight mu = q.F'/F'.F' of v_{k+2} and nu = (q.E - mu F.E)/E.E of
//! v_{k+1}. The back substitution makes the reconstructed point backward stable even for
//! slivers whose barycentric coordinates are ill-conditioned.

use super::assemble::{boundary_edges, clamp01, longest, SIN2_EPS};
use crate::primitives::Tss;
use nalgebra::{Point3, Vector3};

/// A triangle prepared for distance queries (6.5, 6.21).
#[derive(Debug, Clone, Copy)]
pub(crate) struct TriFrame {
    /// Vertices v0, v1, v2.
    pub v: [Point3<f64>; 3],
    /// Boundary edges v_{i+1} - v_i.
    pub e: [Vector3<f64>; 3],
    /// Unnormalised normal E x F (same orientation as e0 x e1 of (6.5)).
    pub n: Vector3<f64>,
    /// Index k of the longest edge E = e_k.
    pub k: usize,
    /// F' / |F'|^2: q . fp is the weight of v_{k+2}.
    fp: Vector3<f64>,
    /// F . E.
    fe: f64,
    /// 1 / E.E.
    inv_ee: f64,
    /// The angle at v_k has sin^2 <= SIN2_EPS (includes collinear and coincident vertices):
    /// the triangle is treated as its longest edge.
    pub flat: bool,
}

/// Plane projection of a point: weights of v_{k+2}, v_{k+1} and the scaled height n . q.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Proj {
    /// Weight of v_{k+2}.
    pub mu: f64,
    /// Weight of v_{k+1}.
    pub nu: f64,
    /// n . (p - v_k): signed height times |n|.
    pub h: f64,
}

impl Proj {
    /// True when the projection lies in the triangle, i.e. (6.6) holds.
    #[inline(always)]
    pub fn inside(&self) -> bool {
        self.mu >= 0.0 && self.nu >= 0.0 && self.mu + self.nu <= 1.0
    }
}

impl TriFrame {
    /// Prepares a triangle.
    #[inline(always)]
    pub fn new(t: &Tss) -> Self {
        let v = *t.vertices();
        let e = boundary_edges(&v);
        let k = longest(&e);
        let big_e = e[k];
        let f = -e[(k + 2) % 3];
        let ee = big_e.norm_squared();
        let inv_ee = if ee > 0.0 { 1.0 / ee } else { 0.0 };
        let fe = f.dot(&big_e);
        let fp = f - big_e * (fe * inv_ee);
        let fp = fp - big_e * (fp.dot(&big_e) * inv_ee);
        let fpfp = fp.norm_squared();
        let flat = fpfp <= SIN2_EPS * f.norm_squared();
        // E x F' = E x F, but with the rounding error of F' tilting it about E only.
        let n = big_e.cross(&fp);
        let fp = if flat { Vector3::zeros() } else { fp / fpfp };
        Self {
            v,
            e,
            n,
            k,
            fp,
            fe,
            inv_ee,
            flat,
        }
    }

    /// Plane projection (6.21) of a point, in the weights of the frame.
    #[inline(always)]
    pub fn project(&self, p: &Point3<f64>) -> Proj {
        let q = p - self.v[self.k];
        let mu = self.fp.dot(&q);
        let nu = (self.e[self.k].dot(&q) - mu * self.fe) * self.inv_ee;
        Proj {
            mu,
            nu,
            h: self.n.dot(&q),
        }
    }

    /// The point of the plane with the weights of `w`.
    #[inline(always)]
    pub fn point(&self, w: &Proj) -> Point3<f64> {
        let k = self.k;
        self.v[k] + self.e[k] * w.nu - self.e[(k + 2) % 3] * w.mu
    }

    /// Triangle parameters (s0, s1) of (6.5) of the weights `w`, forced into (6.6).
    #[inline(always)]
    pub fn params(&self, w: &Proj) -> (f64, f64) {
        let rest = 1.0 - w.mu - w.nu;
        let (s0, s1) = match self.k {
            0 => (w.nu, w.mu),
            1 => (rest, w.nu),
            _ => (w.mu, rest),
        };
        let s0 = clamp01(s0);
        (s0, clamp01(s1).min(1.0 - s0))
    }

    /// Point (6.5) at parameters (s0, s1).
    #[inline(always)]
    pub fn point_at(&self, s: (f64, f64)) -> Point3<f64> {
        self.v[0] + self.e[0] * s.0 - self.e[2] * s.1
    }
}
