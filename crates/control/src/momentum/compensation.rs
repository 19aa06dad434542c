//! Angular momentum compensation via null-space motion (thesis 7.3.2, (7.3)-(7.9)).
//!
//! The DoFs are split into producing (`p`: base, legs, pelvis, head, ...) and reducing (`r`)
//! sets. The thesis takes `q_r := q_free`, the arm DoFs once the arm CoG tasks are removed
//! from `x`. [`LOLA_ARM_FLEXION`] (shoulder and elbow flexion, both about `y`, the arm swing
//! that moves mass fore-aft and so carries most of the vertical momentum) is the default;
//! [`LOLA_ARMS`] adds the shoulder adduction. Any 1-DoF joints can be chosen by name.
//!
//! The reducing joints move along `J_{L,r,z}^T`, the direction of both (7.7) and (7.9); only
//! the scale differs. The thesis estimates it from the previous cycle's producing velocities
//! and feeds `qdot_r` into `y` of (7.3), which at 1 kHz with gain 1 oscillates. Here the
//! scale is measured within the cycle instead ([`super::in_cycle`]): RMRC is linear in the
//! null-space input, so after the cycle's solve the response `qd_r` to `y_r = J_{L,r,z}^T`
//! (zero task velocity, same factorisation) gives `qd += f qd_r` with
//! `f = k (L_d - J_Lz qd) / (J_Lz qd_r)` (7.5), which sets `L_z` to `k L_d + (1 - k) L_z`
//! exactly, the tasks' reaction to the arm motion included. With the arms free of tasks and
//! `W = E`, `qd_r = -J_{L,r,z}^T` on the reducing joints and the term is the minimum-norm
//! solution (7.7), `f qd_r = k J_{L,r,z}^# (L_d - L_z)`.

use super::error::MomentumError;
use biped_dynamics::Model;

/// Lola's shoulder and elbow flexion joints (default reducing set).
pub const LOLA_ARM_FLEXION: [&str; 4] = ["l_shoulder", "l_forearm", "r_shoulder", "r_forearm"];

/// All six arm joints of Lola.
pub const LOLA_ARMS: [&str; 6] = [
    "l_shoulder",
    "l_upper_arm",
    "l_forearm",
    "r_shoulder",
    "r_upper_arm",
    "r_forearm",
];

/// Split of the DoFs into producing and reducing sets and the gain `k` of the compensation.
#[derive(Clone, Debug)]
pub struct Compensation {
    reducing: Vec<usize>,
    is_reducing: Vec<bool>,
    gain: f64,
}

impl Compensation {
    /// Reducing set from 1-DoF joint names of `model`, with gain 1.
    pub fn new(model: &Model, joints: &[&str]) -> Result<Self, MomentumError> {
        let mut is_reducing = vec![false; model.nv()];
        let mut reducing = Vec::with_capacity(joints.len());
        for name in joints {
            let info = model
                .joints()
                .iter()
                .find(|j| j.name == *name)
                .ok_or_else(|| MomentumError::UnknownJoint((*name).to_string()))?;
            if info.nv != 1 {
                return Err(MomentumError::NotOneDof {
                    name: info.name.clone(),
                    nv: info.nv,
                });
            }
            if is_reducing[info.v_index] {
                return Err(MomentumError::BadReducingSet);
            }
            is_reducing[info.v_index] = true;
            reducing.push(info.v_index);
        }
        if reducing.is_empty() {
            return Err(MomentumError::BadReducingSet);
        }
        Ok(Self {
            reducing,
            is_reducing,
            gain: 1.0,
        })
    }

    /// Lola's default: [`LOLA_ARM_FLEXION`].
    pub fn lola(model: &Model) -> Result<Self, MomentumError> {
        Self::new(model, &LOLA_ARM_FLEXION)
    }

    /// Sets the gain `k` of the compensation: the share of `L_d - L_z` removed per cycle (finite, >= 0).
    pub fn with_gain(mut self, gain: f64) -> Result<Self, MomentumError> {
        if !(gain.is_finite() && gain >= 0.0) {
            return Err(MomentumError::InvalidParameter {
                name: "gain",
                value: gain,
                reason: "must be finite and >= 0",
            });
        }
        self.gain = gain;
        Ok(self)
    }

    /// Velocity indices of the reducing joints.
    pub fn reducing(&self) -> &[usize] {
        &self.reducing
    }

    /// Whether velocity coordinate `i` is reducing.
    pub fn is_reducing(&self, i: usize) -> bool {
        self.is_reducing.get(i).copied().unwrap_or(false)
    }

    /// Number of velocity coordinates of the model the set was built on.
    pub fn nv(&self) -> usize {
        self.is_reducing.len()
    }

    /// The gain `k`.
    pub fn gain(&self) -> f64 {
        self.gain
    }
}
