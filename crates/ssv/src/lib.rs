//! Swept-sphere volumes (SSVs): exact distances between robot parts for self-collision
//! avoidance (thesis ch. 6).
//!
//! A robot part is covered by a few primitives: spheres ([`Pss`]), capsules ([`Lss`]) and
//! rounded triangles ([`Tss`]). [`distance()`] gives the signed distance between any two of
//! them (negative on overlap), the closest points on both surfaces and the normal, in closed
//! form and without NaN for any valid input. [`Segment`]s group the SSVs of one body, with a
//! tight oriented bounding box as a cheap pre-check, and a [`CollisionModel`] evaluates the
//! segment pairs of a whole robot from its body poses without allocating; collision models
//! are read from TOML files ([`format`](mod@format)).
//!
//! # Example
//!
//! A unit sphere at the origin and a capsule of radius 0.5 around the segment from
//! `(3, -1, 0)` to `(3, 1, 0)`: the closest points of the two axes are `(0, 0, 0)` and
//! `(3, 0, 0)`, so by hand `d = 3 - 1 - 0.5 = 1.5`, with surface points `(1, 0, 0)` and
//! `(2.5, 0, 0)`.
//!
//! ```
//! use biped_ssv::{distance, Lss, Pss, Ssv};
//! use nalgebra::{Point3, Vector3};
//!
//! let ball = Ssv::from(Pss::new(Point3::origin(), 1.0)?);
//! let bar = Ssv::from(Lss::new(Point3::new(3.0, -1.0, 0.0), Point3::new(3.0, 1.0, 0.0), 0.5)?);
//! let r = distance(&ball, &bar);
//! assert!((r.distance - 1.5).abs() < 1e-15);
//! assert!((r.point_a - Point3::new(1.0, 0.0, 0.0)).norm() < 1e-15);
//! assert!((r.point_b - Point3::new(2.5, 0.0, 0.0)).norm() < 1e-15);
//! assert!((r.normal - Vector3::x()).norm() < 1e-15);
//!
//! // the reversed query is the same result with a and b swapped
//! let back = distance(&bar, &ball);
//! assert_eq!(back.distance, r.distance);
//! assert_eq!(back.point_a, r.point_b);
//! # Ok::<(), biped_ssv::SsvError>(())
//! ```
//!
//! More distances and a whole humanoid model: `cargo run -p biped_ssv --example ssv_distances`.
//!
//! # Modules
//!
//! - [`primitives`]: the three SSV types and the [`Ssv`] enum over them.
//! - [`distance`](mod@distance): the six distance functions of Table 6.1 and the dispatch [`distance()`].
//! - [`result`]: [`DistanceResult`], the distance, closest points and normal.
//! - [`segment`]: [`Segment`]s of SSVs in a body frame, mirroring, reduced versions, pair queries.
//! - [`obb`]: oriented bounding boxes and their enlarged overlap test.
//! - [`model`]: [`CollisionModel`], segments on bodies, segment pairs and `d_a`.
//! - [`format`](mod@format): the TOML file format of collision models (load, save).
//! - [`error`]: [`SsvError`], the error of invalid primitive input.
//! - [`mesh`]: triangle meshes from STL and OBJ files, their volume and closedness.
//! - [`fit`]: SSVs that contain spheres, capsules, cylinders, boxes and meshes; pair choice
//!   by sampled configurations.
//! - [`query`]: the JSON form of primitives and distance queries (`biped ssv query`, Python).

pub mod distance;
pub mod error;
pub mod fit;
pub mod format;
pub mod mesh;
pub mod model;
pub mod obb;
pub mod primitives;
pub mod query;
pub mod result;
pub mod segment;

pub use distance::distance;
pub use error::SsvError;
pub use format::{FormatError, LoadedModel};
pub use model::{CollisionModel, ModelError, SegmentPair};
pub use obb::Obb;
pub use primitives::{Lss, Pss, Ssv, Tss};
pub use result::{DistanceResult, PrimitiveParam};
pub use segment::{ClosestPair, MirrorPlane, PairDistance, PairQuery, Segment};
