//! Fits of the analytic shapes: sphere, capsule, cylinder, box.

use super::{positive, Candidate, FitError};
use nalgebra::{Isometry3, Point3, Vector3};

/// Points sampled on each rim of a cylinder for the containment check.
const RIM_SAMPLES: usize = 64;

/// A sphere is a point SSV.
pub(super) fn sphere(pose: &Isometry3<f64>, radius: f64) -> Result<Candidate, FitError> {
    let r = positive("sphere radius", radius)?;
    Ok(Candidate::Point(pose * Point3::origin(), r))
}

/// A capsule is a line SSV.
pub(super) fn capsule(
    pose: &Isometry3<f64>,
    radius: f64,
    length: f64,
) -> Result<Candidate, FitError> {
    let r = positive("capsule radius", radius)?;
    let h = positive("capsule length", length)? / 2.0;
    Ok(Candidate::line(
        pose * Point3::new(0.0, 0.0, -h),
        pose * Point3::new(0.0, 0.0, h),
        r,
    ))
}

/// A cylinder is contained by the line SSV of its axis with its radius: every point of the
/// solid is within the radius of the axis segment.
pub(super) fn cylinder(
    pose: &Isometry3<f64>,
    radius: f64,
    length: f64,
) -> Result<Candidate, FitError> {
    let r = positive("cylinder radius", radius)?;
    let h = positive("cylinder length", length)? / 2.0;
    let rims: Vec<Point3<f64>> = (0..RIM_SAMPLES)
        .flat_map(|k| {
            let phi = std::f64::consts::TAU * k as f64 / RIM_SAMPLES as f64;
            let (s, c) = phi.sin_cos();
            [-h, h].map(|z| pose * Point3::new(r * c, r * s, z))
        })
        .collect();
    let axis = Candidate::line(
        pose * Point3::new(0.0, 0.0, -h),
        pose * Point3::new(0.0, 0.0, h),
        r,
    );
    Ok(axis.containing(&rims)?)
}

/// The eight corners of a box of half extents `h` at `pose`.
pub(super) fn box_corners(pose: &Isometry3<f64>, h: &Vector3<f64>) -> Vec<Point3<f64>> {
    (0..8)
        .map(|k| {
            let s = |bit: usize| if k >> bit & 1 == 1 { 1.0 } else { -1.0 };
            pose * Point3::new(s(0) * h.x, s(1) * h.y, s(2) * h.z)
        })
        .collect()
}

/// A box: the smallest of the rectangle of its two largest dimensions swept by half the
/// smallest, the line SSV of its longest axis (radius: half the diagonal of the other two)
/// and its circumscribed sphere.
pub(super) fn cuboid(pose: &Isometry3<f64>, size: [f64; 3]) -> Result<Candidate, FitError> {
    for (what, s) in ["box size x", "box size y", "box size z"]
        .into_iter()
        .zip(size)
    {
        positive(what, s)?;
    }
    let h = Vector3::from(size) / 2.0;
    let mut order = [0, 1, 2];
    order.sort_by(|&a, &b| size[b].total_cmp(&size[a]));
    let [i, j, k] = order;
    let axis = |n: usize| pose.rotation * Vector3::ith(n, 1.0);
    let center = pose * Point3::origin();
    let corner = center - axis(i) * h[i] - axis(j) * h[j];
    let rectangle = Candidate::rectangle(corner, axis(i) * size[i], axis(j) * size[j], h[k]);
    let r_line = (h[j] * h[j] + h[k] * h[k]).sqrt();
    let line = Candidate::line(center - axis(i) * h[i], center + axis(i) * h[i], r_line);
    let ball = Candidate::Point(center, h.norm());
    let corners = box_corners(pose, &h);
    let mut best: Option<Candidate> = None;
    for c in [rectangle, line, ball] {
        let c = c.containing(&corners)?;
        if best.is_none_or(|b| c.volume() < b.volume()) {
            best = Some(c);
        }
    }
    Ok(best.unwrap_or(ball))
}
