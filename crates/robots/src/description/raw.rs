//! The robot description file as written: serde structures that keep every value's byte span
//! (`toml::Spanned`) so that errors can name its line.

use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

/// A list of names with spans.
pub(super) type Names = Spanned<Vec<Spanned<String>>>;

/// The whole file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawDescription {
    pub name: Spanned<String>,
    pub urdf: Spanned<String>,
    #[serde(default = "yes")]
    pub floating: bool,
    pub feet: RawFeet,
    pub groups: RawGroups,
    pub momentum: RawMomentum,
    #[serde(default)]
    pub comfort: RawComfort,
    pub collision: Option<RawCollision>,
    #[serde(default)]
    pub drives: RawDrives,
}

fn yes() -> bool {
    true
}

/// `[feet.left]` and `[feet.right]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFeet {
    pub left: RawFoot,
    pub right: RawFoot,
}

/// One foot.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFoot {
    pub frame: Spanned<String>,
    pub sole_center: Spanned<[f64; 3]>,
    pub sole_size: Spanned<[f64; 2]>,
    pub toe_joint: Option<Spanned<String>>,
}

/// `[groups]`: joint groups of the limbs.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawGroups {
    pub left_leg: Names,
    pub right_leg: Names,
    pub left_arm: Names,
    pub right_arm: Names,
}

/// `[momentum]`: the DoF split of the angular momentum compensation (thesis 7.3.2).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawMomentum {
    pub reducing: Names,
    pub producing: Option<Names>,
}

/// `[comfort]`: the comfort pose.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawComfort {
    pub srdf_state: Option<Spanned<String>>,
    #[serde(default)]
    pub joints: BTreeMap<String, Spanned<f64>>,
}

/// `[collision]`: the SSV model file and optionally the pairs to check.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawCollision {
    pub model: Spanned<String>,
    pub pairs: Option<Spanned<Vec<Spanned<[String; 2]>>>>,
    #[serde(default)]
    pub exclude: Vec<Spanned<[String; 2]>>,
}

/// `[drives]`: SRDF (rotors, named states) and reflected rotor inertias.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawDrives {
    pub srdf: Option<Spanned<String>>,
    #[serde(default)]
    pub armature: Vec<Spanned<RawArmature>>,
}

/// One `drives.armature` entry.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawArmature {
    pub joints: String,
    pub inertia: f64,
}
