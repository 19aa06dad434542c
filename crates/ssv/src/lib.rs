//! Swept-sphere-volume distance library (thesis ch. 6).
//!
//! Three primitives ([`Pss`], [`Lss`], [`Tss`]), the six distance functions of Table 6.1
//! with the swap relation for the other three, segments built from many SSVs with
//! oriented-bounding-box pre-checks (6.6-6.7), and collision models of segment pairs.

pub mod distance;
pub mod error;
pub mod format;
pub mod model;
pub mod obb;
pub mod primitives;
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
