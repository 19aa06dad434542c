//! Tight oriented bounding boxes of SSV segments and their enlarged overlap test (thesis 6.7).
//!
//! A box is fitted once per segment in its body frame ([`Obb::fit`]) and moved rigidly with
//! the body ([`Obb::transformed`]). Two segments closer than the activation distance `d_a`
//! always have overlapping boxes when each box is enlarged by `d_a / 2` (Figure 6.13):
//! a pair of points closer than `d_a` has its midpoint within `d_a / 2` of both boxes.

mod fit;
mod overlap;

use crate::primitives::Ssv;
use crate::segment::MirrorPlane;
use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

/// An oriented box: centre, orthonormal right-handed axes (columns) and half extents.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Obb {
    /// Box centre.
    pub center: Point3<f64>,
    /// Box axes as the columns of a rotation matrix (det = +1).
    pub axes: Matrix3<f64>,
    /// Half extents along the three axes (>= 0).
    pub half_extents: Vector3<f64>,
}

impl Obb {
    /// A box from the axis-aligned interval `[min, max]` expressed in the frame `axes`.
    pub fn from_frame_interval(axes: Matrix3<f64>, min: Vector3<f64>, max: Vector3<f64>) -> Self {
        let mid = (min + max) * 0.5;
        Self {
            center: Point3::from(axes * mid),
            axes,
            half_extents: (max - min) * 0.5,
        }
    }

    /// Tight box around a set of SSVs, radii included (PCA frame refined by local rotations).
    pub fn fit(ssvs: &[Ssv]) -> Self {
        fit::fit(ssvs)
    }

    /// Radius of the sphere through the corners, `|h|`.
    #[inline]
    pub fn circumradius(&self) -> f64 {
        self.half_extents.norm()
    }

    /// Volume of the box.
    #[inline]
    pub fn volume(&self) -> f64 {
        8.0 * self.half_extents.x * self.half_extents.y * self.half_extents.z
    }

    /// This box moved by a rigid transform.
    #[inline]
    pub fn transformed(&self, pose: &Isometry3<f64>) -> Self {
        let rot = pose.rotation.to_rotation_matrix();
        Self {
            center: pose * self.center,
            axes: rot.matrix() * self.axes,
            half_extents: self.half_extents,
        }
    }

    /// This box moved by `x -> rot x + t` (`rot` the rotation matrix of a rigid pose).
    #[inline]
    pub(crate) fn transformed_by(&self, rot: &Matrix3<f64>, t: &Vector3<f64>) -> Self {
        Self {
            center: Point3::from(rot * self.center.coords + t),
            axes: rot * self.axes,
            half_extents: self.half_extents,
        }
    }

    /// The mirror image of the box about a coordinate plane (axes kept right-handed).
    pub fn reflected(&self, plane: MirrorPlane) -> Self {
        let k = plane.normal_axis();
        let mut axes = self.axes;
        axes.row_mut(k).neg_mut();
        axes.column_mut(0).neg_mut();
        Self {
            center: plane.reflect(&self.center),
            axes,
            half_extents: self.half_extents,
        }
    }

    /// This box with every half extent grown by `margin` (e.g. `d_a / 2`, Figure 6.13).
    #[inline]
    pub fn enlarged(&self, margin: f64) -> Self {
        Self {
            half_extents: self.half_extents.add_scalar(margin),
            ..*self
        }
    }

    /// Whether the box contains the whole swept volume of `ssv`, up to `tolerance`.
    pub fn contains_ssv(&self, ssv: &Ssv, tolerance: f64) -> bool {
        (0..3).all(|k| {
            let axis = self.axes.column(k).into_owned();
            let (lo, hi) = support_interval(ssv, &axis);
            let c = axis.dot(&self.center.coords);
            let h = self.half_extents[k] + tolerance;
            lo >= c - h && hi <= c + h
        })
    }

    /// The axis-aligned bounds of `ssv` (radius included) in this box's frame, centred at
    /// the box centre.
    #[inline]
    pub fn local_interval(&self, ssv: &Ssv) -> LocalInterval {
        let mut lo = Vector3::repeat(f64::INFINITY);
        let mut hi = Vector3::repeat(f64::NEG_INFINITY);
        for v in ssv.vertices() {
            let local = self.axes.tr_mul(&(v - self.center));
            lo = lo.inf(&local);
            hi = hi.sup(&local);
        }
        let r = ssv.radius();
        LocalInterval {
            lo: lo.add_scalar(-r),
            hi: hi.add_scalar(r),
        }
    }

    /// The box itself in its own frame: `[-h, h]`.
    #[inline]
    pub fn own_interval(&self) -> LocalInterval {
        LocalInterval {
            lo: -self.half_extents,
            hi: self.half_extents,
        }
    }

    /// Lower bound on the distance from any point of `ssv` to this box.
    #[inline]
    pub fn ssv_distance_lower_bound(&self, ssv: &Ssv) -> f64 {
        self.local_interval(ssv)
            .distance_squared(&self.own_interval())
            .sqrt()
    }

    /// Separating-axis overlap test (15 axes) of the two boxes, each enlarged by `margin`.
    #[inline]
    pub fn overlaps(&self, other: &Obb, margin: f64) -> bool {
        overlap::overlaps(self, other, margin)
    }
}

/// An axis-aligned box `[lo, hi]` in the frame of some [`Obb`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalInterval {
    /// Lower corner.
    pub lo: Vector3<f64>,
    /// Upper corner.
    pub hi: Vector3<f64>,
}

impl LocalInterval {
    /// Squared distance between two boxes of the same frame: the per-axis gaps `g_k`
    /// combine to `sum g_k^2`, a lower bound on the squared distance between anything inside
    /// them (points differ by at least `g_k` along each orthonormal axis). 0 if they touch.
    #[inline]
    pub fn distance_squared(&self, other: &LocalInterval) -> f64 {
        let gap = |k: usize| {
            let g = (self.lo[k] - other.hi[k]).max(other.lo[k] - self.hi[k]);
            if g > 0.0 {
                g
            } else {
                0.0
            }
        };
        let (x, y, z) = (gap(0), gap(1), gap(2));
        x * x + y * y + z * z
    }
}

/// The interval `[min, max]` of `u . x` over all points x of the swept volume: the support
/// of a swept sphere along unit `u` is `max_v (v . u) + r`.
#[inline]
pub fn support_interval(ssv: &Ssv, u: &Vector3<f64>) -> (f64, f64) {
    let (lo, hi) = ssv
        .vertices()
        .iter()
        .map(|v| v.coords.dot(u))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
    let r = ssv.radius();
    (lo - r, hi + r)
}
