//! Robot segments as compounds of SSVs fixed in a body frame (thesis 6.6.1, 6.8).
//!
//! A [`Segment`] keeps its SSVs in the body frame (constant) and a world-frame copy that
//! [`Segment::set_pose`] refreshes without allocating. Mirroring about the coordinate planes
//! gives the opposite-side segment ([`Segment::mirrored`]) or symmetric copies of single SSVs
//! ([`Segment::with_mirrored_copies`]); [`Segment::version`] builds a reduced version holding
//! a subset of the SSVs (e.g. only the inner side of a thigh, 6.8).

mod bounds;
mod mirror;
mod pair;
mod sphere;
mod transform;

pub use mirror::{MirrorPlane, UnknownPlane};
pub(crate) use pair::segment_pair_query_hinted;
pub use pair::{
    closest_ssv_pair, closest_ssv_pair_brute_force, closest_ssv_pair_brute_force_with,
    closest_ssv_pair_with, segment_pair_distance, segment_pair_query, ClosestPair, PairDistance,
    PairQuery,
};
pub use sphere::BoundingSphere;

use crate::obb::{LocalInterval, Obb};
use crate::primitives::Ssv;
use nalgebra::Isometry3;
use transform::RigidMatrix;

/// What can be wrong when building a segment.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SegmentError {
    /// A segment needs at least one SSV.
    #[error("segment `{0}` has no SSVs")]
    Empty(String),
    /// An SSV index beyond the segment's SSV count.
    #[error("segment `{segment}` has {count} SSVs, index {index} is out of range")]
    IndexOutOfRange {
        /// Segment name.
        segment: String,
        /// Offending index.
        index: usize,
        /// Number of SSVs in the segment.
        count: usize,
    },
}

/// A named compound of SSVs in a body frame with its tight OBB (SSV_Segment of Fig. 6.14).
///
/// # Example
///
/// A right shank (capsule 0.1 m to the right of the body origin, radius 0.05) and its mirror
/// image about the body's `xz` plane as the left shank: at the identity pose the two axes are
/// 0.2 m apart, so by hand `d = 0.2 - 2 * 0.05 = 0.1`. With an activation distance below that,
/// the enlarged bounding boxes already rule the pair out.
///
/// ```
/// use biped_ssv::segment::segment_pair_distance;
/// use biped_ssv::{Lss, MirrorPlane, PairDistance, Segment, Ssv};
/// use nalgebra::Point3;
///
/// let axis = Lss::new(Point3::new(0.0, -0.1, 0.0), Point3::new(0.0, -0.1, -0.4), 0.05)?;
/// let right = Segment::new("shank_r", vec![Ssv::from(axis)])?;
/// let left = right.mirrored("shank_l", MirrorPlane::Xz);
/// let d = segment_pair_distance(&right, &left, 0.5).distance().unwrap();
/// assert!((d - 0.1).abs() < 1e-12);
/// assert_eq!(segment_pair_distance(&right, &left, 0.05), PairDistance::Beyond);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Segment {
    name: String,
    ssvs: Vec<Ssv>,
    spheres: Vec<BoundingSphere>,
    obb: Obb,
    intervals: Vec<LocalInterval>,
    world_ssvs: Vec<Ssv>,
    world_spheres: Vec<BoundingSphere>,
    world_obb: Obb,
}

impl Segment {
    /// A segment from body-frame SSVs; fits its OBB once. Starts at the identity pose.
    pub fn new(name: impl Into<String>, ssvs: Vec<Ssv>) -> Result<Self, SegmentError> {
        let name = name.into();
        if ssvs.is_empty() {
            return Err(SegmentError::Empty(name));
        }
        let obb = Obb::fit(&ssvs);
        Ok(Self::with_obb(name, ssvs, obb))
    }

    /// A segment with a given body-frame OBB (which must contain every SSV).
    fn with_obb(name: String, ssvs: Vec<Ssv>, obb: Obb) -> Self {
        let spheres: Vec<_> = ssvs.iter().map(BoundingSphere::of_ssv).collect();
        let intervals = ssvs.iter().map(|s| obb.local_interval(s)).collect();
        Self {
            name,
            intervals,
            world_ssvs: ssvs.clone(),
            world_spheres: spheres.clone(),
            world_obb: obb,
            ssvs,
            spheres,
            obb,
        }
    }

    /// Segment name.
    pub fn name(&self) -> &str {
        &self.name
    }
    /// The SSVs in the body frame.
    pub fn ssvs(&self) -> &[Ssv] {
        &self.ssvs
    }
    /// Number of SSVs.
    pub fn len(&self) -> usize {
        self.ssvs.len()
    }
    /// Always false: a segment has at least one SSV.
    pub fn is_empty(&self) -> bool {
        self.ssvs.is_empty()
    }
    /// Per-SSV bounding spheres in the body frame.
    pub fn bounding_spheres(&self) -> &[BoundingSphere] {
        &self.spheres
    }
    /// Tight OBB in the body frame (6.7).
    pub fn obb(&self) -> &Obb {
        &self.obb
    }
    /// Per-SSV bounds in the frame of the segment's own OBB (invariant under rigid motion).
    pub fn ssv_intervals(&self) -> &[LocalInterval] {
        &self.intervals
    }
    /// The SSVs at the last pose set by [`Segment::set_pose`].
    pub fn world_ssvs(&self) -> &[Ssv] {
        &self.world_ssvs
    }
    /// Per-SSV bounding spheres at the last pose.
    pub fn world_spheres(&self) -> &[BoundingSphere] {
        &self.world_spheres
    }
    /// The OBB at the last pose.
    pub fn world_obb(&self) -> &Obb {
        &self.world_obb
    }

    /// Moves the segment to `pose` (body frame to world): transforms SSVs, spheres and OBB
    /// in place, without allocating.
    pub fn set_pose(&mut self, pose: &Isometry3<f64>) {
        let m = RigidMatrix::new(pose);
        let ssvs = self.world_ssvs.iter_mut().zip(&self.ssvs);
        for ((w, s), sphere) in ssvs.zip(self.world_spheres.iter_mut().zip(&self.spheres)) {
            w.set_transformed_by(s, &m.rot, &m.t);
            // The sphere centre of a point or segment follows from the moved vertices
            // (BoundingSphere::of_ssv); a triangle's centre is moved itself.
            sphere.0.center = match w {
                Ssv::Point(p) => *p.center(),
                Ssv::Line(l) => nalgebra::center(&l.vertices()[0], &l.vertices()[1]),
                Ssv::Triangle(_) => m.point(&sphere.1.center),
            };
        }
        self.world_obb = self.obb.transformed_by(&m.rot, &m.t);
    }

    /// The whole segment mirrored about a body-frame plane: the opposite-side version (6.6.1).
    /// Its OBB is the mirror image of this one (equally tight).
    pub fn mirrored(&self, name: impl Into<String>, plane: MirrorPlane) -> Self {
        let ssvs = self.ssvs.iter().map(|s| plane.reflect_ssv(s)).collect();
        Self::with_obb(name.into(), ssvs, self.obb.reflected(plane))
    }

    /// This segment plus mirror images of the SSVs at `indices` (symmetry inside a segment).
    pub fn with_mirrored_copies(
        &self,
        indices: &[usize],
        plane: MirrorPlane,
    ) -> Result<Self, SegmentError> {
        let mut ssvs = self.ssvs.clone();
        for &i in indices {
            ssvs.push(plane.reflect_ssv(self.get(i)?));
        }
        Self::new(self.name.clone(), ssvs)
    }

    /// A reduced version holding only the SSVs at `indices`, with its own tight OBB (6.8).
    pub fn version(
        &self,
        name: impl Into<String>,
        indices: &[usize],
    ) -> Result<Self, SegmentError> {
        let ssvs = indices
            .iter()
            .map(|&i| self.get(i).copied())
            .collect::<Result<Vec<_>, _>>()?;
        Self::new(name, ssvs)
    }

    fn get(&self, index: usize) -> Result<&Ssv, SegmentError> {
        self.ssvs
            .get(index)
            .ok_or_else(|| SegmentError::IndexOutOfRange {
                segment: self.name.clone(),
                index,
                count: self.ssvs.len(),
            })
    }
}
