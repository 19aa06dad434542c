//! The serde image of a model file: every value that semantic checks may reject keeps its
//! byte span (`toml::Spanned`) so errors can name the line.

use super::exact::Exact;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use toml::Spanned;

/// Three coordinates (a point, a position or roll-pitch-yaw angles).
pub(super) type Point = Exact<f64, 3>;

/// A whole model file.
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFile {
    pub activation_distance: Spanned<f64>,
    pub bodies: Vec<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub pairs: Vec<Spanned<Exact<Spanned<String>, 2>>>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub pair: Vec<Spanned<RawPair>>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub segment: Vec<Spanned<RawSegment>>,
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub pose: BTreeMap<String, Spanned<BTreeMap<String, Spanned<RawPose>>>>,
}

/// A pair written as a table `{ a = "..", b = ".." }`.
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawPair {
    pub a: Spanned<String>,
    pub b: Spanned<String>,
}

/// A segment: explicit SSVs, a mirror image of another segment, or a version (subset).
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSegment {
    pub name: Spanned<String>,
    pub body: Spanned<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ssvs: Option<Spanned<Vec<Spanned<RawSsv>>>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mirror_of: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plane: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub version_of: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub keep: Option<Spanned<Vec<Spanned<i64>>>>,
}

/// One SSV: exactly one of `point`, `line`, `triangle`, plus `radius`.
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSsv {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub point: Option<Spanned<Point>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub line: Option<Spanned<Exact<Point, 2>>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub triangle: Option<Spanned<Exact<Point, 3>>>,
    pub radius: Spanned<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mirror_copy: Option<Spanned<String>>,
}

/// A body pose: position and optional roll-pitch-yaw angles (rad, extrinsic x-y-z).
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawPose {
    pub position: Spanned<Point>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rpy: Option<Spanned<Point>>,
}
