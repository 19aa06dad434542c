//! `biped walk --robot`: the walked robot, the Lola-like biped by default or a robot
//! description (`g1`, `talos` or a description file), as a [`WalkRobot`].

use biped_control::walk::{DynamicRobot, WalkRobot};
use biped_robots::description::Robot;
use biped_robots::lola::{self, LolaType};
use std::path::{Path, PathBuf};

/// The walked robot and how `biped walk` names it in its report.
pub struct Chosen {
    /// The robot.
    pub robot: WalkRobot,
    /// `the Lola-like biped (Type 2, 31 DoF)`, `g1 (bundled g1.toml, 35 DoF)`.
    pub label: String,
    /// The robot of the dynamic walk (with `dynamic`).
    pub dynamic: Option<DynamicRobot>,
}

/// The robot of `--robot` (`None`: the Lola-like biped), with its dynamic walk's robot if
/// `dynamic`; one-line errors start `--robot:`.
pub fn choose(robot: Option<&str>, dynamic: bool) -> Result<Chosen, String> {
    let Some(value) = robot else {
        let lola = lola::build(LolaType::Type2).map_err(|e| e.to_string())?;
        let robot = WalkRobot::lola(&lola).map_err(|e| e.to_string())?;
        let label = format!("the Lola-like biped (Type 2, {} DoF)", robot.model.nv());
        let dynamic = dynamic
            .then(|| DynamicRobot::lola(LolaType::Type2))
            .transpose()
            .map_err(|e| e.to_string())?;
        return Ok(Chosen {
            robot,
            label,
            dynamic,
        });
    };
    let path = description_path(value)?;
    let loaded = Robot::load(&path).map_err(|e| format!("--robot: {e}"))?;
    let robot = WalkRobot::from_description(&loaded).map_err(|e| format!("--robot: {e}"))?;
    let file = match Robot::bundled(value) {
        Some(_) => format!("bundled {value}.toml"),
        None => path.display().to_string(),
    };
    let label = format!("{} ({file}, {} DoF)", robot.name, robot.model.nv());
    let dynamic = dynamic
        .then(|| DynamicRobot::from_description(&loaded, robot.clone()))
        .transpose()
        .map_err(|e| format!("--robot: {e}"))?;
    Ok(Chosen {
        robot,
        label,
        dynamic,
    })
}

/// The description file of `--robot VALUE`: a bundled name or an existing `.toml` file.
fn description_path(value: &str) -> Result<PathBuf, String> {
    if let Some(p) = Robot::bundled(value) {
        return Ok(p);
    }
    let path = Path::new(value);
    match path.is_file() {
        true => Ok(path.to_path_buf()),
        false => Err(format!(
            "--robot: `{value}` is neither a bundled robot (g1, talos) nor a robot description \
             file (docs/robot_description.md)"
        )),
    }
}
