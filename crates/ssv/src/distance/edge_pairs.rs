//! The nine edge-edge pairs of TT (6.4.6) in structure-of-arrays form, so the LL solves of
//! (6.31) and Tables 6.3/6.4 run as packed SIMD operations; nearly parallel pairs are then
//! redone with the orthogonalised solve of [`super::line_line`].

use super::assemble::{clamp01, key_index, min_key};
use super::line_line::{near_parallel_s, WELL_CONDITIONED};
use super::triangle_frame::TriFrame;
use nalgebra::Vector3;

/// Nearest edge pair: squared distance, pair index 3 i + j and parameters (s, t) on edge i of
/// `a` and edge j of `b`.
#[allow(clippy::needless_range_loop)] // lane loops over parallel arrays
#[inline(always)]
pub(crate) fn nearest_edge_pair(a: &TriFrame, b: &TriFrame) -> (f64, usize, f64, f64) {
    let mut w = [[0.0; 9]; 3];
    let (mut u, mut v) = ([[0.0; 9]; 3], [[0.0; 9]; 3]);
    let (mut uu, mut vv, mut iu, mut iv) = ([0.0; 9], [0.0; 9], [0.0; 9], [0.0; 9]);
    for k in 0..9 {
        let (i, j) = (k / 3, k % 3);
        let d = b.v[j] - a.v[i];
        for c in 0..3 {
            w[c][k] = d[c];
            u[c][k] = a.e[i][c];
            v[c][k] = b.e[j][c];
        }
        (uu[k], vv[k], iu[k], iv[k]) = (a.ee[i], b.ee[j], a.inv_ee[i], b.inv_ee[j]);
    }
    let dot = |x: &[[f64; 9]; 3], y: &[[f64; 9]; 3], k: usize| {
        x[0][k] * y[0][k] + x[1][k] * y[1][k] + x[2][k] * y[2][k]
    };
    let (mut uv, mut uw, mut vw, mut s0) = ([0.0; 9], [0.0; 9], [0.0; 9], [0.0; 9]);
    let mut ill = [false; 9];
    for k in 0..9 {
        (uv[k], uw[k], vw[k]) = (dot(&u, &v, k), dot(&u, &w, k), dot(&v, &w, k));
        let n = uu[k] * vv[k] - uv[k] * uv[k];
        s0[k] = (vv[k] * uw[k] - uv[k] * vw[k]) / n;
        let well = n > WELL_CONDITIONED * uu[k] * vv[k];
        ill[k] = !well;
    }
    for k in 0..9 {
        if ill[k] {
            let col = |x: &[[f64; 9]; 3]| Vector3::new(x[0][k], x[1][k], x[2][k]);
            s0[k] = near_parallel_s(&col(&u), &col(&v), &col(&w), uv[k], vw[k], iv[k]);
        }
    }
    let (mut s, mut t, mut d2) = ([0.0; 9], [0.0; 9], [0.0; 9]);
    for k in 0..9 {
        t[k] = clamp01((clamp01(s0[k]) * uv[k] - vw[k]) * iv[k]);
        s[k] = clamp01((uw[k] + t[k] * uv[k]) * iu[k]);
        let c = |x: usize| w[x][k] + v[x][k] * t[k] - u[x][k] * s[k];
        d2[k] = c(0) * c(0) + c(1) * c(1) + c(2) * c(2);
    }
    let mut key = u64::MAX;
    for k in 0..9 {
        key = key.min(min_key(d2[k], k));
    }
    let k = key_index(key);
    (d2[k], k, s[k], t[k])
}
