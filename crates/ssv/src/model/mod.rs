//! Collision models: segments attached to bodies, segment pairs and the activation distance
//! `d_a` (thesis 6.7-6.8, Figure 6.14).
//!
//! [`CollisionModel::update`] takes the body poses, moves every segment that takes part in a
//! pair (each SSV is transformed once per update, not per pair) and evaluates every pair with
//! the enlarged-OBB pre-check and the exact, pruned closest-pair search (warm-started with
//! the previous update's closest SSV pair of each segment pair); [`PairQuery`]
//! chooses whether pairs farther than `d_a` still report their closest pair. All buffers are
//! allocated at construction; an update does not allocate.

use crate::segment::{segment_pair_query_hinted, ClosestPair, PairDistance, PairQuery, Segment};
use nalgebra::Isometry3;

/// What can be wrong when building or updating a collision model.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// The activation distance must be finite and >= 0.
    #[error("activation distance must be finite and >= 0, got {0}")]
    BadActivationDistance(f64),
    /// A body index beyond the body list.
    #[error("body index {index} out of range ({count} bodies)")]
    BodyOutOfRange {
        /// Offending index.
        index: usize,
        /// Number of bodies.
        count: usize,
    },
    /// A segment index beyond the segment list.
    #[error("segment index {index} out of range ({count} segments)")]
    SegmentOutOfRange {
        /// Offending index.
        index: usize,
        /// Number of segments.
        count: usize,
    },
    /// Two segments or bodies with the same name.
    #[error("duplicate name `{0}`")]
    DuplicateName(String),
    /// A pair of a segment with itself.
    #[error("segment pair ({0}, {0}) pairs a segment with itself")]
    SelfPair(usize),
    /// `update` got the wrong number of body poses.
    #[error("expected {expected} body poses, got {got}")]
    PoseCount {
        /// Number of bodies in the model.
        expected: usize,
        /// Number of poses given.
        got: usize,
    },
    /// A body pose with a NaN or infinite component.
    #[error("pose of body {0} is not finite")]
    NonFinitePose(usize),
}

/// A segment pair (SegmentPair of Fig. 6.14): indices into the model's segments.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct SegmentPair {
    /// First segment.
    pub a: usize,
    /// Second segment.
    pub b: usize,
}

/// Segments on bodies, the pairs to check and the activation distance `d_a`.
///
/// # Example
///
/// A hand (sphere of radius 0.04 at the end of the forearm body) and a thigh (capsule of
/// radius 0.06 along its body's `-z`), built in code. With the hand 0.2 m beside the thigh
/// axis the pair is beyond `d_a = 0.05`; moved to 0.13 m, by hand
/// `d = 0.13 - 0.04 - 0.06 = 0.03`.
///
/// ```
/// use biped_ssv::{CollisionModel, Lss, Pss, Segment, Ssv};
/// use nalgebra::{Isometry3, Point3};
///
/// let mut model = CollisionModel::new(vec!["thigh".into(), "forearm".into()], 0.05)?;
/// let thigh = Lss::new(Point3::origin(), Point3::new(0.0, 0.0, -0.4), 0.06)?;
/// let hand = Pss::new(Point3::new(0.0, 0.0, -0.25), 0.04)?;
/// let a = model.add_segment(Segment::new("thigh", vec![Ssv::from(thigh)])?, 0)?;
/// let b = model.add_segment(Segment::new("hand", vec![Ssv::from(hand)])?, 1)?;
/// model.add_pair(a, b)?;
///
/// let thigh_pose = Isometry3::translation(0.0, 0.0, 0.9);
/// model.update(&[thigh_pose, Isometry3::translation(0.0, 0.2, 1.0)])?;
/// assert!(model.min_distance().is_none()); // every pair beyond d_a
///
/// model.update(&[thigh_pose, Isometry3::translation(0.0, 0.13, 1.0)])?;
/// let (pair, closest) = model.min_distance().unwrap();
/// assert_eq!(pair, 0);
/// assert!((closest.result.distance - 0.03).abs() < 1e-12);
/// // the closest point on the thigh's surface faces the hand, at the hand's height
/// assert!((closest.result.point_a - Point3::new(0.0, 0.06, 0.75)).norm() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CollisionModel {
    bodies: Vec<String>,
    segments: Vec<Segment>,
    segment_body: Vec<usize>,
    pairs: Vec<SegmentPair>,
    activation_distance: f64,
    query: PairQuery,
    in_pair: Vec<bool>,
    results: Vec<PairDistance>,
}

impl CollisionModel {
    /// An empty model over named bodies with activation distance `d_a`.
    pub fn new(bodies: Vec<String>, activation_distance: f64) -> Result<Self, ModelError> {
        if !(activation_distance.is_finite() && activation_distance >= 0.0) {
            return Err(ModelError::BadActivationDistance(activation_distance));
        }
        if let Some(dup) = first_duplicate(bodies.iter().map(String::as_str)) {
            return Err(ModelError::DuplicateName(dup.to_string()));
        }
        Ok(Self {
            bodies,
            segments: Vec::new(),
            segment_body: Vec::new(),
            pairs: Vec::new(),
            activation_distance,
            query: PairQuery::default(),
            in_pair: Vec::new(),
            results: Vec::new(),
        })
    }

    /// Attaches a segment (SSVs in the body frame) to body `body`; returns its index.
    pub fn add_segment(&mut self, segment: Segment, body: usize) -> Result<usize, ModelError> {
        if body >= self.bodies.len() {
            return Err(ModelError::BodyOutOfRange {
                index: body,
                count: self.bodies.len(),
            });
        }
        if self.segment_index(segment.name()).is_some() {
            return Err(ModelError::DuplicateName(segment.name().to_string()));
        }
        self.segments.push(segment);
        self.segment_body.push(body);
        self.in_pair.push(false);
        Ok(self.segments.len() - 1)
    }

    /// Adds the pair of segments `a`, `b` (e.g. two thigh versions in different pairs, 6.8).
    pub fn add_pair(&mut self, a: usize, b: usize) -> Result<usize, ModelError> {
        for index in [a, b] {
            if index >= self.segments.len() {
                return Err(ModelError::SegmentOutOfRange {
                    index,
                    count: self.segments.len(),
                });
            }
        }
        if a == b {
            return Err(ModelError::SelfPair(a));
        }
        self.pairs.push(SegmentPair { a, b });
        self.in_pair[a] = true;
        self.in_pair[b] = true;
        self.results.push(PairDistance::Beyond);
        Ok(self.pairs.len() - 1)
    }

    /// Body names; `update` takes one pose per body in this order.
    pub fn bodies(&self) -> &[String] {
        &self.bodies
    }
    /// Index of a body by name.
    pub fn body_index(&self, name: &str) -> Option<usize> {
        self.bodies.iter().position(|b| b == name)
    }
    /// The segments (body-frame SSVs and world copies at the last update).
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }
    /// Index of a segment by name.
    pub fn segment_index(&self, name: &str) -> Option<usize> {
        self.segments.iter().position(|s| s.name() == name)
    }
    /// Body index each segment is attached to.
    pub fn segment_bodies(&self) -> &[usize] {
        &self.segment_body
    }
    /// The segment pairs.
    pub fn pairs(&self) -> &[SegmentPair] {
        &self.pairs
    }
    /// Activation distance `d_a` (6.7).
    pub fn activation_distance(&self) -> f64 {
        self.activation_distance
    }
    /// How overlapping pairs are evaluated (default [`PairQuery::Closest`]).
    pub fn pair_query(&self) -> PairQuery {
        self.query
    }
    /// Sets how overlapping pairs are evaluated; [`PairQuery::WithinActivation`] reports
    /// only pairs closer than `d_a` and is much cheaper when few pairs are that close.
    pub fn set_pair_query(&mut self, query: PairQuery) {
        self.query = query;
    }
    /// Total number of SSVs over all segments.
    pub fn ssv_count(&self) -> usize {
        self.segments.iter().map(Segment::len).sum()
    }

    /// Moves the segments to the body poses and evaluates every pair (no allocation).
    pub fn update(&mut self, body_poses: &[Isometry3<f64>]) -> Result<(), ModelError> {
        self.set_poses(body_poses)?;
        self.evaluate();
        Ok(())
    }

    /// Moves every segment that takes part in a pair to its body's pose.
    pub fn set_poses(&mut self, body_poses: &[Isometry3<f64>]) -> Result<(), ModelError> {
        check_poses(body_poses, self.bodies.len())?;
        for ((segment, &body), &used) in self
            .segments
            .iter_mut()
            .zip(&self.segment_body)
            .zip(&self.in_pair)
        {
            if used {
                segment.set_pose(&body_poses[body]);
            }
        }
        Ok(())
    }

    /// Evaluates every pair at the current segment poses.
    pub fn evaluate(&mut self) {
        let (d_a, query) = (self.activation_distance, self.query);
        for (result, pair) in self.results.iter_mut().zip(&self.pairs) {
            let (a, b) = (&self.segments[pair.a], &self.segments[pair.b]);
            // Temporal coherence: last update's closest SSV pair is evaluated first.
            let hint = result.computed().map(|c| (c.ssv_a, c.ssv_b));
            *result = segment_pair_query_hinted(a, b, d_a, query, hint);
        }
    }

    /// Per-pair results of the last update, in pair order.
    pub fn results(&self) -> &[PairDistance] {
        &self.results
    }

    /// Iterator over `(pair, result)` of the last update.
    pub fn distances(&self) -> impl Iterator<Item = (&SegmentPair, &PairDistance)> + '_ {
        self.pairs.iter().zip(&self.results)
    }

    /// The pair with the smallest computed distance at the last update, `None` if every pair
    /// is beyond `d_a`.
    pub fn min_distance(&self) -> Option<(usize, &ClosestPair)> {
        self.results
            .iter()
            .enumerate()
            .filter_map(|(k, r)| r.computed().map(|c| (k, c)))
            .min_by(|x, y| x.1.result.distance.total_cmp(&y.1.result.distance))
    }
}

fn check_poses(poses: &[Isometry3<f64>], count: usize) -> Result<(), ModelError> {
    if poses.len() != count {
        return Err(ModelError::PoseCount {
            expected: count,
            got: poses.len(),
        });
    }
    for (k, p) in poses.iter().enumerate() {
        let finite = p.translation.vector.iter().all(|x| x.is_finite())
            && p.rotation.coords.iter().all(|x| x.is_finite());
        if !finite {
            return Err(ModelError::NonFinitePose(k));
        }
    }
    Ok(())
}

fn first_duplicate<'a>(names: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let all: Vec<&str> = names.collect();
    all.iter()
        .enumerate()
        .find(|(k, n)| all[..*k].contains(n))
        .map(|(_, n)| *n)
}
