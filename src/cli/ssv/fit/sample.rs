//! Random configurations of a URDF model within its joint limits, and the body poses of a
//! configuration by forward kinematics, for choosing the pairs of a fitted model.

use biped_dynamics::urdf::UrdfModel;
use biped_dynamics::{update_placements, Data, JointModel, Model};
use nalgebra::{DVector, Isometry3};
use rand::{Rng, SeedableRng};

/// Random configurations within the joint limits, and body poses by forward kinematics.
pub(super) struct Sampler {
    rng: rand::rngs::StdRng,
    data: Data,
    /// `q` index and sampled interval of every movable joint.
    ranges: Vec<(usize, f64, f64)>,
}

impl Sampler {
    /// The sampler of `urdf`'s joint ranges, seeded.
    pub(super) fn new(urdf: &UrdfModel, seed: u64) -> Self {
        let model = &urdf.model;
        let mut ranges = Vec::new();
        for joint in &urdf.joints {
            let Some(body) = model.body(joint.body) else {
                continue;
            };
            let turn = matches!(body.joint(), JointModel::Revolute { .. });
            // without a finite bound: a full turn for revolute joints, 0 for prismatic ones
            let free = if turn { std::f64::consts::PI } else { 0.0 };
            let [lo, hi] = joint.range.unwrap_or([-free, free]);
            let lo = if lo.is_finite() {
                lo
            } else {
                hi.min(0.0) - free
            };
            let hi = if hi.is_finite() {
                hi
            } else {
                lo.max(0.0) + free
            };
            ranges.push((body.q_index(), lo, hi.max(lo)));
        }
        Self {
            rng: rand::rngs::StdRng::seed_from_u64(seed),
            data: Data::new(model),
            ranges,
        }
    }

    /// Body poses of a random configuration (the free root, if any, at the origin).
    pub(super) fn random_poses(
        &mut self,
        model: &Model,
        out: &mut [Isometry3<f64>],
    ) -> Result<(), Box<dyn std::error::Error>> {
        let mut q = model.neutral();
        for &(i, lo, hi) in &self.ranges {
            q[i] = if hi > lo {
                self.rng.random_range(lo..=hi)
            } else {
                lo
            };
        }
        self.poses(model, &q, out)
    }

    /// Body poses at `q`; the world body (if `out` has one more entry) at the identity.
    pub(super) fn poses(
        &mut self,
        model: &Model,
        q: &DVector<f64>,
        out: &mut [Isometry3<f64>],
    ) -> Result<(), Box<dyn std::error::Error>> {
        update_placements(model, &mut self.data, q)?;
        for (i, pose) in out.iter_mut().enumerate().take(model.nbodies()) {
            *pose = self.data.body_pose(i);
        }
        Ok(())
    }
}
