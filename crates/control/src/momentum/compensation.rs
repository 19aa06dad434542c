//! Angular momentum compensation via null-space motion (thesis 7.3.2, (7.3)-(7.9)).
//!
//! The DoFs are split into producing (`p`: base, legs, pelvis, head, ...) and reducing (`r`)
//! sets. The thesis takes `q_r := q_free`, the arm DoFs once the arm CoG tasks are removed
//! from `x`. [`LOLA_ARM_FLEXION`] (shoulder and elbow flexion, both about `y`, the arm swing
//! that moves mass fore-aft and so carries most of the vertical momentum) is the default;
//! [`LOLA_ARMS`] adds the shoulder adduction. Any 1-DoF joints can be chosen by name.
//!
//! Sign convention (resolved): (7.4) defines `L_r` as the momentum *removed*, so with the
//! physical Jacobian `J_{L,r,z}` the thesis's `qdot_r` of (7.7) is the negative of the arm
//! velocity that achieves `J_Lz qdot = L_d`. It enters `y` of (7.3), and RMRC applies
//! `-N W^-1 y`, so the two signs cancel: with `W = E` and arms free of tasks (`N_rr = E`) the
//! arms move by `-qdot_r` and the total is `J_{L,p,z} qdot_p - J_{L,r,z} qdot_r = L_d` (7.5).
//! [`Compensation::add_to`] therefore returns `y` in the same convention as a cost gradient
//! `(dH/dq)^T`, i.e. exactly what (7.8) adds.
//!
//! `qdot_p` is the caller's estimate of the producing velocities: in a 1 kHz loop, the
//! previous cycle's solution (Alg. 4.3 needs `y` before it solves for `qdot`). Only its
//! producing entries are read.

use super::error::{check_finite, check_len, MomentumError};
use biped_dynamics::Model;
use nalgebra::DVector;

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

/// `|J_{L,r,z}|^2` below which the exact law (7.7) is reported singular.
const SINGULAR_NORM2: f64 = 1e-20;

/// Which solution of (7.6) is fed to the null space.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompensationLaw {
    /// `qdot_r = J_{L,r,z}^# (J_{L,p,z} qdot_p - L_d)`, the minimum-norm solution (7.7).
    Exact,
    /// `qdot_r = |J_{L,r,z}| J_{L,r,z}^# (...)`, the bounded normalised law (7.9).
    Normalised,
}

/// Split of the DoFs into producing and reducing sets and the compensation law (7.7)/(7.9).
#[derive(Clone, Debug)]
pub struct Compensation {
    reducing: Vec<usize>,
    is_reducing: Vec<bool>,
    law: CompensationLaw,
    gain: f64,
}

/// Result of one compensation evaluation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompensationTerms {
    /// Producing momentum `L_{p,z} = J_{L,p,z} qdot_p` (7.5).
    pub producing: f64,
    /// `|J_{L,r,z}|`.
    pub reducing_norm: f64,
    /// Scalar `s` with `qdot_r = s J_{L,r,z}^T` (before the gain).
    pub scale: f64,
}

impl Compensation {
    /// Reducing set from 1-DoF joint names of `model`, with `law` and gain 1.
    pub fn new(
        model: &Model,
        joints: &[&str],
        law: CompensationLaw,
    ) -> Result<Self, MomentumError> {
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
            law,
            gain: 1.0,
        })
    }

    /// Lola's default: [`LOLA_ARM_FLEXION`] with the normalised law (7.9).
    pub fn lola(model: &Model) -> Result<Self, MomentumError> {
        Self::new(model, &LOLA_ARM_FLEXION, CompensationLaw::Normalised)
    }

    /// Sets the gain `k` multiplying `qdot_r` in `y` (finite, >= 0).
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

    /// The law in use.
    pub fn law(&self) -> CompensationLaw {
        self.law
    }

    /// Evaluates (7.5) and the scale of (7.7)/(7.9) for `J_Lz^T` (`jlz`), the producing velocity
    /// estimate `qdot` and the desired `L_d`.
    pub fn terms(
        &self,
        jlz: &DVector<f64>,
        qdot: &DVector<f64>,
        l_desired: f64,
    ) -> Result<CompensationTerms, MomentumError> {
        let n = self.is_reducing.len();
        check_len("jlz", jlz.len(), n)?;
        check_len("qdot", qdot.len(), n)?;
        check_finite("jlz", jlz.iter())?;
        check_finite("qdot", qdot.iter())?;
        check_finite("l_desired", [l_desired].iter())?;
        let mut producing = 0.0;
        for ((j, v), r) in jlz.iter().zip(qdot.iter()).zip(&self.is_reducing) {
            if !r {
                producing += j * v;
            }
        }
        let norm2: f64 = self.reducing.iter().map(|&i| jlz[i] * jlz[i]).sum();
        let error = producing - l_desired;
        let scale = match self.law {
            CompensationLaw::Exact if norm2 <= SINGULAR_NORM2 => {
                return Err(MomentumError::Singular { norm: norm2.sqrt() })
            }
            CompensationLaw::Exact => error / norm2,
            CompensationLaw::Normalised if norm2 == 0.0 => 0.0,
            CompensationLaw::Normalised => error / norm2.sqrt(),
        };
        Ok(CompensationTerms {
            producing,
            reducing_norm: norm2.sqrt(),
            scale,
        })
    }

    /// Adds `k qdot_r` (7.7)/(7.9) to the reducing entries of the null-space input `y` (7.8);
    /// other entries are untouched. Returns the evaluated terms.
    pub fn add_to(
        &self,
        jlz: &DVector<f64>,
        qdot: &DVector<f64>,
        l_desired: f64,
        y: &mut DVector<f64>,
    ) -> Result<CompensationTerms, MomentumError> {
        check_len("y", y.len(), self.is_reducing.len())?;
        let terms = self.terms(jlz, qdot, l_desired)?;
        let s = self.gain * terms.scale;
        for &i in &self.reducing {
            y[i] += s * jlz[i];
        }
        Ok(terms)
    }
}
