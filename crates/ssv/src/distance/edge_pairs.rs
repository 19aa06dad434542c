//! The nine edge-edge pairs of TT (6.4.6): each pair is the LL solve of (6.31) with the two
//! saturation steps of Tables 6.3/6.4, using the edge lengths and reciprocals the triangle
//! frames already hold; nearly parallel pairs take the orthogonalised solve of
//! [`super::line_line`]. The nearest pair is selected without branches.

use super::assemble::{clamp01, key_index, min_key};
use super::line_line::{near_parallel_s, WELL_CONDITIONED};
use super::triangle_frame::TriFrame;

/// Closest points of edge i of `a` and edge j of `b`: squared distance and parameters (s, t).
#[inline(always)]
pub(crate) fn edge_pair(a: &TriFrame, b: &TriFrame, i: usize, j: usize) -> (f64, f64, f64) {
    let (u, v) = (&a.e[i], &b.e[j]);
    let w = b.v[j] - a.v[i];
    let (uv, uw, vw) = (u.dot(v), u.dot(&w), v.dot(&w));
    let (uu, vv) = (a.ee[i], b.ee[j]);
    let n = uu * vv - uv * uv;
    let s0 = if n > WELL_CONDITIONED * uu * vv {
        (vv * uw - uv * vw) / n
    } else {
        near_parallel_s(u, v, &w, uv, vw, b.inv_ee[j])
    };
    let t = clamp01((clamp01(s0) * uv - vw) * b.inv_ee[j]);
    let s = clamp01((uw + t * uv) * a.inv_ee[i]);
    let c = w + v * t - u * s;
    (c.x * c.x + c.y * c.y + c.z * c.z, s, t)
}

/// Nearest edge pair: squared distance, pair index 3 i + j and parameters (s, t) on edge i of
/// `a` and edge j of `b`.
#[inline(always)]
pub(crate) fn nearest_edge_pair(a: &TriFrame, b: &TriFrame) -> (f64, usize, f64, f64) {
    let mut all = [(0.0, 0.0, 0.0); 9];
    let mut key = u64::MAX;
    for (k, x) in all.iter_mut().enumerate() {
        *x = edge_pair(a, b, k / 3, k % 3);
        key = key.min(min_key(x.0, k));
    }
    let k = key_index(key);
    (all[k].0, k, all[k].1, all[k].2)
}
