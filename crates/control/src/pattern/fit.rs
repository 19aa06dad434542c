//! Defaults fitted to the Lola-like model: standing CoM height, hip spacing and toe axis.
//!
//! The standing pose bends both knees by `knee` with hip and ankle pitch `-knee / 2` each, so
//! the soles stay flat and parallel; all other joints are zero. The CoM height is the CoM
//! `z` minus the mean sole `z` at that pose (base orientation identity).

use super::PatternError;
use biped_dynamics::{center_of_mass, Data};
use biped_robots::lola::LolaModel;
use nalgebra::DVector;

/// Configuration of the flat-footed bent-knee standing pose with knee angle `knee` \[rad].
pub fn bent_knee_pose(lola: &LolaModel, knee: f64) -> Result<DVector<f64>, PatternError> {
    let mut q = lola.model.neutral();
    for side in ["l_", "r_"] {
        for (joint, angle) in [
            ("thigh", -0.5 * knee),
            ("shank", knee),
            ("ankle_cross", -0.5 * knee),
        ] {
            let name = format!("{side}{joint}");
            let limit = lola
                .limits
                .iter()
                .find(|l| l.name == name)
                .ok_or_else(|| PatternError::Model(format!("no joint `{name}`")))?;
            q[limit.q_index] = angle;
        }
    }
    Ok(q)
}

/// World position of body `name` at the last kinematics run in `data`.
fn body_z(lola: &LolaModel, data: &Data, name: &str) -> Result<f64, PatternError> {
    let id = lola
        .model
        .body_id(name)
        .ok_or_else(|| PatternError::Model(format!("no body `{name}`")))?;
    Ok(data.body_pose(id).translation.z)
}

/// Height of the CoM above the soles in the bent-knee standing pose (`knee` \[rad]).
pub fn standing_com_height(lola: &LolaModel, knee: f64) -> Result<f64, PatternError> {
    let q = bent_knee_pose(lola, knee)?;
    let mut data = Data::new(&lola.model);
    let com = center_of_mass(&lola.model, &mut data, &q, None)
        .map_err(|e| PatternError::Model(e.to_string()))?;
    let soles = 0.5 * (body_z(lola, &data, "l_sole")? + body_z(lola, &data, "r_sole")?);
    Ok(com.position.z - soles)
}

/// Lateral distance between the two hip joints (nominal step width) \[m].
pub fn hip_spacing(lola: &LolaModel) -> Result<f64, PatternError> {
    let q = lola.model.neutral();
    let mut data = Data::new(&lola.model);
    biped_dynamics::update_placements(&lola.model, &mut data, &q)
        .map_err(|e| PatternError::Model(e.to_string()))?;
    let y = |name: &str| -> Result<f64, PatternError> {
        let id = lola
            .model
            .body_id(name)
            .ok_or_else(|| PatternError::Model(format!("no body `{name}`")))?;
        Ok(data.body_pose(id).translation.y)
    };
    Ok(y("l_hip_rotation")? - y("r_hip_rotation")?)
}

/// Toe joint axis of the left foot in its sole frame at the neutral pose: `(x, z)` \[m]
/// (the defaults `FootGeometry::front` and `toe_height`).
pub fn toe_axis(lola: &LolaModel) -> Result<(f64, f64), PatternError> {
    let q = lola.model.neutral();
    let mut data = Data::new(&lola.model);
    biped_dynamics::update_placements(&lola.model, &mut data, &q)
        .map_err(|e| PatternError::Model(e.to_string()))?;
    let pos = |name: &str| -> Result<nalgebra::Vector3<f64>, PatternError> {
        let id = lola
            .model
            .body_id(name)
            .ok_or_else(|| PatternError::Model(format!("no body `{name}`")))?;
        Ok(data.body_pose(id).translation.vector)
    };
    let d = pos("l_toe")? - pos("l_sole")?;
    Ok((d.x, d.z))
}
