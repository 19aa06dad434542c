//! Fits to a point cloud (mesh vertices) in its principal axes (PCA of the points): the
//! bounding sphere, the capsule along the first axis and the rectangle in the plane of the
//! first two; the smallest containing one wins.

use super::{Candidate, FitError};
use nalgebra::{Matrix3, Point3, SymmetricEigen, Vector3};

/// The smallest-volume containing candidate for `points` (see the module docs).
pub(super) fn fit_points(points: &[Point3<f64>]) -> Result<Candidate, FitError> {
    if points.is_empty() {
        return Err(FitError::NoPoints);
    }
    for p in points {
        crate::primitives::Pss::new(*p, 0.0)?;
    }
    let frame = principal_axes(points);
    let local: Vec<Vector3<f64>> = points
        .iter()
        .map(|p| frame.transpose() * p.coords)
        .collect();
    let (lo, hi) = local.iter().fold(
        (
            Vector3::repeat(f64::INFINITY),
            Vector3::repeat(f64::NEG_INFINITY),
        ),
        |(lo, hi), u| (lo.inf(u), hi.sup(u)),
    );
    let mid = (lo + hi) / 2.0;
    let world = |u: Vector3<f64>| Point3::from(frame * u);
    let mut best: Option<Candidate> = None;
    for c in [
        sphere(points, world(mid)),
        line(&local, &mid, &world),
        rectangle(&local, &lo, &hi, &world),
    ] {
        let c = c.containing(points)?;
        if best.is_none_or(|b| c.volume() < b.volume()) {
            best = Some(c);
        }
    }
    best.ok_or(FitError::NoPoints)
}

/// The principal axes of the points (columns, largest variance first, right-handed); the
/// identity if the decomposition is not finite.
fn principal_axes(points: &[Point3<f64>]) -> Matrix3<f64> {
    let n = points.len() as f64;
    let mean = points.iter().map(|p| p.coords).sum::<Vector3<f64>>() / n;
    let cov = points
        .iter()
        .map(|p| (p.coords - mean) * (p.coords - mean).transpose())
        .sum::<Matrix3<f64>>()
        / n;
    let eig = SymmetricEigen::new(cov);
    let mut order = [0, 1, 2];
    order.sort_by(|&a, &b| eig.eigenvalues[b].total_cmp(&eig.eigenvalues[a]));
    let e0 = eig.eigenvectors.column(order[0]).into_owned();
    let e1 = eig.eigenvectors.column(order[1]).into_owned();
    let axes = Matrix3::from_columns(&[e0, e1, e0.cross(&e1)]);
    match axes.iter().all(|x| x.is_finite()) {
        true => axes,
        false => Matrix3::identity(),
    }
}

/// The smaller of the spheres about the centroid and about `mid` (the middle of the
/// principal-axes box) through the farthest point.
fn sphere(points: &[Point3<f64>], mid: Point3<f64>) -> Candidate {
    let centroid =
        Point3::from(points.iter().map(|p| p.coords).sum::<Vector3<f64>>() / points.len() as f64);
    let radius = |c: Point3<f64>| points.iter().map(|p| (p - c).norm()).fold(0.0, f64::max);
    let (r_mid, r_centroid) = (radius(mid), radius(centroid));
    match r_mid <= r_centroid {
        true => Candidate::Point(mid, r_mid),
        false => Candidate::Point(centroid, r_centroid),
    }
}

/// The shortest interval `[a, b]` of the first axis such that each point `(t, h)` (axial
/// coordinate, allowed axial slack) is within `h` of it: `a = min (t + h)`, `b = max (t - h)`;
/// one point (the middle) when `a >= b`.
fn shortened(points: impl Iterator<Item = (f64, f64)>) -> (f64, f64) {
    let (a, b) = points.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), (t, h)| {
        (a.min(t + h), b.max(t - h))
    });
    match a < b {
        true => (a, b),
        false => ((a + b) / 2.0, (a + b) / 2.0),
    }
}

/// The capsule along the first axis through the middle of the other two extents: radius the
/// largest distance from the axis, the segment shortened as far as containment allows.
fn line(
    local: &[Vector3<f64>],
    mid: &Vector3<f64>,
    world: &impl Fn(Vector3<f64>) -> Point3<f64>,
) -> Candidate {
    let rho = |u: &Vector3<f64>| (u.y - mid.y).hypot(u.z - mid.z);
    let r = local.iter().map(rho).fold(0.0, f64::max);
    let (a, b) = shortened(
        local
            .iter()
            .map(|u| (u.x, (r * r - rho(u).powi(2)).max(0.0).sqrt())),
    );
    Candidate::line(
        world(Vector3::new(a, mid.y, mid.z)),
        world(Vector3::new(b, mid.y, mid.z)),
        r,
    )
}

/// The rectangle in the plane of the first two axes through the middle of the third extent,
/// swept by half that extent. Each side is shortened like the capsule, with the in-plane
/// slack of a point split evenly over the two directions (`h / sqrt 2` each).
fn rectangle(
    local: &[Vector3<f64>],
    lo: &Vector3<f64>,
    hi: &Vector3<f64>,
    world: &impl Fn(Vector3<f64>) -> Point3<f64>,
) -> Candidate {
    let (r, mz) = ((hi.z - lo.z) / 2.0, (hi.z + lo.z) / 2.0);
    let slack = |u: &Vector3<f64>| (r * r - (u.z - mz).powi(2)).max(0.0).sqrt() / 2f64.sqrt();
    let (x0, x1) = shortened(local.iter().map(|u| (u.x, slack(u))));
    let (y0, y1) = shortened(local.iter().map(|u| (u.y, slack(u))));
    let corner = world(Vector3::new(x0, y0, mz));
    let u = world(Vector3::new(x1, y0, mz)) - corner;
    let v = world(Vector3::new(x0, y1, mz)) - corner;
    let u = if x1 > x0 { u } else { Vector3::zeros() };
    let v = if y1 > y0 { v } else { Vector3::zeros() };
    Candidate::rectangle(corner, u, v, r)
}
