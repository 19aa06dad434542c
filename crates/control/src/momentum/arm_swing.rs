//! Reference arm-swing method (thesis 7.3.1, after Buschmann, thesis ref. 28): the arm CoG
//! tasks of Table 4.2 follow the *opposite* leg, scaled down because the arms are shorter.
//!
//! Target of the right arm CoG relative to the robot CoG (same frame as the inputs, e.g. the
//! torso planning frame of Table 4.2):
//! `r_arm,R = r0_arm,R + k * mask .* (r_leg,L - r0_leg,L)`, `v_arm,R = k * mask .* v_leg,L`,
//! and symmetrically for the left arm. `r_leg` is the opposite leg point relative to the CoG
//! (the thesis uses the leg CoG; the foot/ankle target is the usual stand-in, the map is the
//! same), `r0` are the nominal (standing) positions. Resolved: the thesis gives no axes; the
//! default `mask = (1, 1, 0)` swings horizontally only, so lifting a foot does not lift an arm.

use super::error::{check_finite, MomentumError};
use nalgebra::Vector3;

/// Position and velocity of a point target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointTarget {
    /// Position.
    pub position: Vector3<f64>,
    /// Velocity.
    pub velocity: Vector3<f64>,
}

/// Left and right arm CoG targets relative to the robot CoG.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArmTargets {
    /// Left arm CoG target.
    pub left: PointTarget,
    /// Right arm CoG target.
    pub right: PointTarget,
}

/// Nominal positions relative to the CoG (standing posture).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArmSwingNominal {
    /// Left arm CoG.
    pub left_arm: Vector3<f64>,
    /// Right arm CoG.
    pub right_arm: Vector3<f64>,
    /// Left leg (foot) point.
    pub left_leg: Vector3<f64>,
    /// Right leg (foot) point.
    pub right_leg: Vector3<f64>,
}

/// Scaled opposite-leg arm swing of the reference method (7.3.1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArmSwing {
    gain: Vector3<f64>,
    nominal: ArmSwingNominal,
}

impl ArmSwing {
    /// Scale `k` (finite, typically arm length / leg length < 1) on the horizontal axes.
    pub fn new(scale: f64, nominal: ArmSwingNominal) -> Result<Self, MomentumError> {
        Self::with_mask(scale, Vector3::new(1.0, 1.0, 0.0), nominal)
    }

    /// Scale `k` on the axes selected by `mask` (entries usually 0 or 1).
    pub fn with_mask(
        scale: f64,
        mask: Vector3<f64>,
        nominal: ArmSwingNominal,
    ) -> Result<Self, MomentumError> {
        check_finite("scale", [scale].iter())?;
        check_finite("mask", mask.iter())?;
        let n = &nominal;
        let all = [n.left_arm, n.right_arm, n.left_leg, n.right_leg];
        check_finite("nominal", all.iter().flat_map(|v| v.iter()))?;
        Ok(Self {
            gain: mask * scale,
            nominal,
        })
    }

    /// Arm CoG targets from the current left/right leg targets relative to the CoG.
    pub fn targets(
        &self,
        left_leg: &PointTarget,
        right_leg: &PointTarget,
    ) -> Result<ArmTargets, MomentumError> {
        for p in [left_leg, right_leg] {
            check_finite("leg target", p.position.iter().chain(p.velocity.iter()))?;
        }
        let n = &self.nominal;
        Ok(ArmTargets {
            left: self.follow(&n.left_arm, right_leg, &n.right_leg),
            right: self.follow(&n.right_arm, left_leg, &n.left_leg),
        })
    }

    /// One arm following the opposite leg `leg` with nominal `leg0`.
    fn follow(&self, arm0: &Vector3<f64>, leg: &PointTarget, leg0: &Vector3<f64>) -> PointTarget {
        PointTarget {
            position: arm0 + self.gain.component_mul(&(leg.position - leg0)),
            velocity: self.gain.component_mul(&leg.velocity),
        }
    }
}
