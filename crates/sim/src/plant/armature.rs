//! Drive rotors of URDF plants: URDF has no motor data, so the reflected rotor inertia
//! ("armature" `N^2 J`, kg m^2) of the joints is given by joint-name patterns and enters the
//! model as geared rotor bodies (thesis 3.1, [`Model::with_geared_rotors`]).

use crate::error::SimError;
use crate::glob::glob_match;
use biped_dynamics::{Body, JointModel, Model, RotorSpec};

/// Reflected rotor inertia for the joints whose name matches `pattern` (`*` matches any run of
/// characters, e.g. `*_knee_joint`).
#[derive(Clone, Debug, PartialEq)]
pub struct Armature {
    /// Joint-name pattern.
    pub pattern: String,
    /// `N^2 J` in kg m^2 (>= 0).
    pub inertia: f64,
    /// A required entry that matches no revolute joint is an error (a typo in `--armature`);
    /// others are skipped (SRDF rotors of joints a reduced URDF locks).
    pub required: bool,
}

/// `model` with a rotor of gear ratio `ratio` on every revolute joint that an entry of
/// `armature` names (the first matching entry wins); a required entry that matches no revolute
/// joint, or a negative or non-finite inertia, is an error.
pub(crate) fn with_rotors(
    model: &Model,
    armature: &[Armature],
    ratio: f64,
) -> Result<Model, SimError> {
    let invalid = |reason: String| SimError::InvalidParameter {
        what: "armature".into(),
        reason,
    };
    let revolute = |(_, b): &(usize, &Body)| matches!(b.joint(), JointModel::Revolute { .. });
    let mut used = vec![false; armature.len()];
    let mut specs = Vec::new();
    for (j, body) in model.bodies().iter().enumerate().filter(revolute) {
        let name = body.joint_name();
        let Some(k) = armature.iter().position(|a| glob_match(&a.pattern, name)) else {
            continue;
        };
        used[k] = true;
        let a = armature[k].inertia;
        if !(a.is_finite() && a >= 0.0) {
            let p = &armature[k].pattern;
            return Err(invalid(format!(
                "`{p}`: inertia {a} kg m^2, must be finite and >= 0"
            )));
        }
        let spec = RotorSpec::from_armature(model, j, ratio, a)
            .map_err(|e| invalid(format!("joint `{name}`: {e}")))?;
        specs.push(spec);
    }
    if let Some(k) = (0..armature.len()).find(|&k| !used[k] && armature[k].required) {
        let p = &armature[k].pattern;
        return Err(invalid(format!("pattern `{p}` matches no revolute joint")));
    }
    model
        .with_geared_rotors(&specs)
        .map_err(|e| invalid(e.to_string()))
}
