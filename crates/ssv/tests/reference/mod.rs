//! Reference solver for the distance between two simplices (point, segment, triangle),
//! built on the KKT framework of thesis 6.4.7 and sharing no code with `src/distance`.
//!
//! # Problem
//! Problem (6.50)-(6.51): minimise `phi = |S_b(x_b) - S_a(x_a)|^2` over the product of the
//! two simplices, each written in barycentric form `S(x) = sum_i lambda_i v_i` with
//! `lambda_i >= 0`, `sum_i lambda_i = 1` (this is (6.4)/(6.5) with the constraints (6.6)).
//!
//! # Method: enumeration of active sets
//! A face of a simplex is the hull of a non-empty subset of its vertices (vertex, edge,
//! interior); choosing a face pair `(F_a, F_b)` fixes which inequalities of (6.6) are active
//! (the others are slack, so their multipliers vanish by (6.53)). On the affine hulls of the
//! pair the problem is an unconstrained linear least-squares problem
//! `min_z |(b_0 - a_0) + M z|^2`, `M = [-(a_i - a_0) .. | (b_j - b_0) ..]`, solved by a
//! rank-revealing (column-pivoted) QR factorisation.
//! Every candidate is made feasible (kept only when its barycentric weights are `>= -FEAS_TOL`,
//! then clamped to the simplex) and its objective is evaluated at the actual points, so each
//! candidate is an honest upper bound; the answer is the minimum over all candidates. The
//! vertex-vertex pairs have no unknowns, so the candidate set is never empty.
//!
//! # Why this is exact
//! `phi` is convex and the feasible set is compact, so a global minimiser exists. Among all
//! global minimisers pick one, `z*`, whose smallest containing face pair `G` (the one with
//! `z*` in its relative interior) has the least dimension. Because `z*` is in the relative
//! interior of `G` and minimises the convex `phi` over `G`, it minimises `phi` over the whole
//! affine hull `aff(G)` (a local minimum of a convex function on an affine set is global).
//! If that least-squares problem had more than one solution, its solution set would be an
//! affine subspace through `z*` of dimension >= 1; following it from `z*` reaches the
//! relative boundary of `G` (which is bounded) at a point of the same, minimal, value lying
//! in a face pair of smaller dimension -- contradicting the choice of `z*`. So the
//! least-squares problem on `aff(G)` has the unique solution `z*`, the QR solve returns it, it is
//! feasible, and it is among the candidates. Consequences used below:
//! * pairs with `dim F_a + dim F_b > 3` are skipped: `M` is 3 x (>3), its solution set is
//!   never unique, so such a pair is never the `G` above (only triangle-interior pairs);
//! * solving every pair additionally with a truncated QR (near-dependent columns dropped)
//!   is harmless: it only adds feasible points, i.e. more upper bounds.
//!
//! Floating point makes the argument approximate; [`certified_gap`] bounds the actual error
//! of each solution from the other side (weak duality with the separating direction), and
//! `tests/reference_selftest.rs` checks it against dense sampling and hand-derived cases.
#![allow(dead_code)]

use nalgebra::{Point3, Vector3};

/// Barycentric weights below `-FEAS_TOL` reject a candidate; weights above are clamped.
const FEAS_TOL: f64 = 1e-9;

/// Relative rank thresholds of the two least-squares solves of every face pair.
const RCONDS: [f64; 2] = [1e-15, 1e-9];

/// Closest points between two simplices (reference solution of (6.50)-(6.51)).
#[derive(Debug, Clone, Copy)]
pub struct Closest {
    /// Distance |point_b - point_a| between the underlying primitives (no radii).
    pub dist: f64,
    /// Closest point on simplex a.
    pub point_a: Point3<f64>,
    /// Closest point on simplex b.
    pub point_b: Point3<f64>,
    /// Barycentric weights of `point_a` (unused vertices 0).
    pub bary_a: [f64; 3],
    /// Barycentric weights of `point_b` (unused vertices 0).
    pub bary_b: [f64; 3],
}

/// The faces of a simplex with `n` vertices: (vertex indices, how many of them).
fn faces(n: usize) -> impl Iterator<Item = ([usize; 3], usize)> {
    (1u32..(1 << n)).map(move |mask| {
        let mut idx = [0; 3];
        let mut k = 0;
        for i in (0..n).filter(|i| mask & (1 << i) != 0) {
            idx[k] = i;
            k += 1;
        }
        (idx, k)
    })
}

/// Closest points between simplices `a` and `b` (1 to 3 vertices each) by face-pair KKT
/// enumeration; see the module documentation for why the minimum over candidates is exact.
pub fn closest(a: &[Point3<f64>], b: &[Point3<f64>]) -> Closest {
    assert!((1..=3).contains(&a.len()) && (1..=3).contains(&b.len()));
    let mut best = Closest {
        dist: f64::INFINITY,
        point_a: a[0],
        point_b: b[0],
        bary_a: [1.0, 0.0, 0.0],
        bary_b: [1.0, 0.0, 0.0],
    };
    for (fa, na) in faces(a.len()) {
        for (fb, nb) in faces(b.len()) {
            if na + nb - 2 <= 3 {
                face_pair(a, &fa[..na], b, &fb[..nb], &mut best);
            }
        }
    }
    best
}

/// Least-squares candidates of one face pair, offered to `best`.
fn face_pair(a: &[Point3<f64>], fa: &[usize], b: &[Point3<f64>], fb: &[usize], best: &mut Closest) {
    let (a0, b0) = (a[fa[0]], b[fb[0]]);
    let mut cols = [Vector3::zeros(); 3];
    let edges = fa[1..]
        .iter()
        .map(|&i| a0 - a[i])
        .chain(fb[1..].iter().map(|&j| b[j] - b0));
    let mut k = 0;
    for (c, e) in cols.iter_mut().zip(edges) {
        *c = e;
        k += 1;
    }
    for rcond in RCONDS {
        let t = least_squares(&cols[..k], &(a0 - b0), rcond);
        let (ta, tb) = t.split_at(fa.len() - 1);
        let (Some(la), Some(lb)) = (weights(fa, ta), weights(fb, &tb[..fb.len() - 1])) else {
            continue;
        };
        offer(a, b, la, lb, best);
    }
}

/// A least-squares solution of `sum_c t_c cols[c] = rhs` by Gram-Schmidt with column
/// pivoting and re-orthogonalisation (a rank-revealing QR). Columns whose remaining
/// component falls below `rcond` times their length are dropped (their unknown is 0),
/// so near-singular systems give a bounded "basic" solution.
///
/// Written by hand because nalgebra 0.35's SVD stops iterating early on small matrices
/// (reconstruction errors around 1e-11 were observed), which is too coarse here.
fn least_squares(cols: &[Vector3<f64>], rhs: &Vector3<f64>, rcond: f64) -> [f64; 3] {
    let k = cols.len();
    let mut len = [0.0; 3];
    let mut work = [Vector3::zeros(); 3];
    for c in 0..k {
        len[c] = cols[c].norm();
        work[c] = cols[c];
    }
    let mut q = [Vector3::zeros(); 3];
    let mut order = [0usize; 3];
    let mut used = [false; 3];
    let mut rank = 0;
    while rank < k {
        // Pivot: the column with the largest remaining part relative to its length.
        let pick = (0..k)
            .filter(|&j| !used[j] && len[j] > 0.0)
            .map(|j| (j, work[j].norm() / len[j]))
            .max_by(|x, y| x.1.total_cmp(&y.1));
        let Some((j, rel)) = pick else { break };
        if rel <= rcond {
            break;
        }
        let mut v = work[j];
        for qi in &q[..rank] {
            v -= qi * qi.dot(&v);
        }
        q[rank] = v.normalize();
        order[rank] = j;
        used[j] = true;
        for (o, w) in work.iter_mut().enumerate().take(k) {
            if !used[o] {
                *w -= q[rank] * q[rank].dot(w);
            }
        }
        rank += 1;
    }
    // Back substitution in R z = Q^T rhs, R = Q^T A on the chosen columns.
    let mut z = [0.0; 3];
    for l in (0..rank).rev() {
        let mut acc = q[l].dot(rhs);
        for m in l + 1..rank {
            acc -= q[l].dot(&cols[order[m]]) * z[order[m]];
        }
        z[order[l]] = acc / q[l].dot(&cols[order[l]]);
    }
    z
}

/// Barycentric weights of a face point `v_f0 + sum t_k (v_fk - v_f0)`, clamped to the simplex;
/// `None` when a weight is below `-FEAS_TOL` (the candidate violates (6.6)).
fn weights(face: &[usize], t: &[f64]) -> Option<[f64; 3]> {
    let mut w = [0.0; 3];
    w[face[0]] = 1.0 - t.iter().sum::<f64>();
    for (k, &tk) in t.iter().enumerate() {
        w[face[k + 1]] = tk;
    }
    if w.iter().any(|&x| !x.is_finite() || x < -FEAS_TOL) {
        return None;
    }
    let w = w.map(|x| x.max(0.0));
    let sum: f64 = w.iter().sum();
    Some(w.map(|x| x / sum))
}

/// The point with barycentric weights `w` on simplex `v`.
pub fn point(v: &[Point3<f64>], w: &[f64; 3]) -> Point3<f64> {
    let mut p = Vector3::zeros();
    for (vi, wi) in v.iter().zip(w) {
        p += vi.coords * *wi;
    }
    Point3::from(p)
}

/// Keep the feasible candidate `(la, lb)` if it beats `best`.
fn offer(a: &[Point3<f64>], b: &[Point3<f64>], la: [f64; 3], lb: [f64; 3], best: &mut Closest) {
    let (pa, pb) = (point(a, &la), point(b, &lb));
    let dist = (pb - pa).norm();
    if dist < best.dist {
        *best = Closest {
            dist,
            point_a: pa,
            point_b: pb,
            bary_a: la,
            bary_b: lb,
        };
    }
}

/// Lower bound on the true distance from the direction `n = (point_b - point_a)/|..|`:
/// for any unit `n`, `|y - x| >= n.(y - x) >= min_j n.b_j - max_i n.a_i` (weak duality).
pub fn lower_bound(a: &[Point3<f64>], b: &[Point3<f64>], sol: &Closest) -> f64 {
    let c = sol.point_b - sol.point_a;
    let len = c.norm();
    if len == 0.0 {
        return 0.0;
    }
    let n = c / len;
    let min_b = b
        .iter()
        .map(|v| n.dot(&v.coords))
        .fold(f64::INFINITY, f64::min);
    let max_a = a
        .iter()
        .map(|v| n.dot(&v.coords))
        .fold(f64::NEG_INFINITY, f64::max);
    (min_b - max_a).max(0.0)
}

/// Certified bound on the error of `sol`: the true distance lies in
/// `[lower_bound, sol.dist]`, so `sol.dist - lower_bound` bounds its error.
pub fn certified_gap(a: &[Point3<f64>], b: &[Point3<f64>], sol: &Closest) -> f64 {
    sol.dist - lower_bound(a, b, sol)
}
