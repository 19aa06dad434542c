//! Mirroring SSVs about the coordinate planes of the body frame (thesis 6.6.1).

use crate::primitives::{Lss, Pss, Ssv, Tss};
use nalgebra::Point3;
use std::fmt;
use std::str::FromStr;

/// A coordinate plane of the body frame used as mirror plane (6.6.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MirrorPlane {
    /// The xy plane: z is negated.
    Xy,
    /// The yz plane: x is negated.
    Yz,
    /// The xz plane: y is negated (left/right symmetry of a humanoid with y to the left).
    Xz,
}

impl MirrorPlane {
    /// All three planes.
    pub const ALL: [MirrorPlane; 3] = [MirrorPlane::Xy, MirrorPlane::Yz, MirrorPlane::Xz];

    /// Index (0 = x, 1 = y, 2 = z) of the coordinate negated by this mirror.
    #[inline]
    pub fn normal_axis(self) -> usize {
        match self {
            MirrorPlane::Xy => 2,
            MirrorPlane::Yz => 0,
            MirrorPlane::Xz => 1,
        }
    }

    /// The plane's name as used in model files: `"xy"`, `"yz"` or `"xz"`.
    pub fn name(self) -> &'static str {
        match self {
            MirrorPlane::Xy => "xy",
            MirrorPlane::Yz => "yz",
            MirrorPlane::Xz => "xz",
        }
    }

    /// The mirror image of a point.
    #[inline]
    pub fn reflect(self, p: &Point3<f64>) -> Point3<f64> {
        let mut q = *p;
        q[self.normal_axis()] = -q[self.normal_axis()];
        q
    }

    /// The mirror image of an SSV (same kind and radius, reflected vertices).
    pub fn reflect_ssv(self, ssv: &Ssv) -> Ssv {
        // Negating a finite coordinate keeps it finite, so the constructors cannot fail;
        // the fallback keeps this function total without a panic path.
        let v = ssv.vertices();
        let r = ssv.radius();
        let m = |i: usize| self.reflect(&v[i]);
        let mirrored = match ssv {
            Ssv::Point(_) => Pss::new(m(0), r).map(Ssv::from),
            Ssv::Line(_) => Lss::new(m(0), m(1), r).map(Ssv::from),
            Ssv::Triangle(_) => Tss::new(m(0), m(1), m(2), r).map(Ssv::from),
        };
        mirrored.unwrap_or(*ssv)
    }
}

impl fmt::Display for MirrorPlane {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A plane name that is not one of `xy`, `yz`, `xz`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown mirror plane `{0}` (expected \"xy\", \"yz\" or \"xz\")")]
pub struct UnknownPlane(pub String);

impl FromStr for MirrorPlane {
    type Err = UnknownPlane;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().as_str() {
            "xy" | "yx" => Ok(MirrorPlane::Xy),
            "yz" | "zy" => Ok(MirrorPlane::Yz),
            "xz" | "zx" => Ok(MirrorPlane::Xz),
            _ => Err(UnknownPlane(s.to_string())),
        }
    }
}
