//! The serde form of the calibration file: model, calibrated joints, jig constraints,
//! measured poses (see the module documentation of [`super`] for the format). Maps reject a
//! repeated key (JSON would otherwise keep the last value silently).

use nalgebra::{Isometry3, Translation3, UnitQuaternion};
use serde::de::{Deserializer, MapAccess, Visitor};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// Model section: a URDF path (relative to the calibration file) and the floating-base flag.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelSpec {
    /// URDF file.
    pub urdf: PathBuf,
    /// Give the root a free joint.
    #[serde(default)]
    pub floating: bool,
}

/// A pose `xyz` \[m] + `rpy` \[rad] (`R = Rz(yaw) Ry(pitch) Rx(roll)`, as in URDF).
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PoseSpec {
    /// Translation.
    #[serde(default)]
    pub xyz: [f64; 3],
    /// Roll, pitch, yaw.
    #[serde(default)]
    pub rpy: [f64; 3],
}

impl PoseSpec {
    /// As an isometry.
    pub fn isometry(&self) -> Isometry3<f64> {
        let [r, p, y] = self.rpy;
        Isometry3::from_parts(
            Translation3::new(self.xyz[0], self.xyz[1], self.xyz[2]),
            UnitQuaternion::from_euler_angles(r, p, y),
        )
    }
}

/// A frame: URDF link plus an optional offset pose in the link frame.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrameSpec {
    /// URDF link name.
    pub link: String,
    /// Offset in the link frame.
    #[serde(default)]
    pub xyz: [f64; 3],
    /// Offset rotation (roll, pitch, yaw).
    #[serde(default)]
    pub rpy: [f64; 3],
}

/// A jig constraint between two frames.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConstraintSpec {
    /// Unique name, referenced by the poses' `targets`.
    pub name: String,
    /// Reference frame.
    pub frame_a: FrameSpec,
    /// Constrained frame.
    pub frame_b: FrameSpec,
    /// `"pose"` (default) or `"position"`.
    #[serde(default)]
    pub components: ComponentsSpec,
    /// Weight of the position rows \[1/m] (default 1).
    #[serde(default = "one")]
    pub position_weight: f64,
    /// Weight of the orientation rows \[1/rad] (default 1).
    #[serde(default = "one")]
    pub orientation_weight: f64,
}

/// Serde form of [`Components`].
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ComponentsSpec {
    /// Position and orientation.
    #[default]
    Pose,
    /// Position only.
    Position,
}

/// One measured jig pose.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PoseEntry {
    /// Name.
    pub name: String,
    /// Encoder angle per joint \[rad or m]; unlisted joints keep the neutral value.
    #[serde(deserialize_with = "unique_keys")]
    pub encoders: BTreeMap<String, f64>,
    /// Target pose of `frame_b` in `frame_a` per active constraint name.
    #[serde(deserialize_with = "unique_keys")]
    pub targets: BTreeMap<String, PoseSpec>,
}

/// A whole calibration file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CalibrationFile {
    /// The model.
    pub model: ModelSpec,
    /// Joints whose offsets are estimated.
    pub joints: Vec<String>,
    /// Jig constraints.
    pub constraints: Vec<ConstraintSpec>,
    /// Measured poses.
    pub poses: Vec<PoseEntry>,
    /// Optional known offsets (synthetic data), compared against the estimate.
    #[serde(default, deserialize_with = "unique_keys")]
    pub reference_offsets: BTreeMap<String, f64>,
}

/// Default weight.
fn one() -> f64 {
    1.0
}

/// A JSON object as a map, a repeated key being an error ("duplicate key `k`", located by the
/// parser at the repetition).
fn unique_keys<'de, D, V>(deserializer: D) -> Result<BTreeMap<String, V>, D::Error>
where
    D: Deserializer<'de>,
    V: Deserialize<'de>,
{
    /// Visitor collecting the entries.
    struct Unique<V>(std::marker::PhantomData<V>);
    impl<'de, V: Deserialize<'de>> Visitor<'de> for Unique<V> {
        type Value = BTreeMap<String, V>;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("an object with distinct keys")
        }
        fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
            let mut out = BTreeMap::new();
            while let Some((key, value)) = map.next_entry::<String, V>()? {
                if out.contains_key(&key) {
                    return Err(serde::de::Error::custom(format!("duplicate key `{key}`")));
                }
                out.insert(key, value);
            }
            Ok(out)
        }
    }
    deserializer.deserialize_map(Unique(std::marker::PhantomData))
}
