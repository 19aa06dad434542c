//! The simulated robot: the Lola-like biped (`--lola`) or a floating-base URDF robot
//! (`--urdf --floating --feet ...`), as a plant with its scenario options and default step.

use super::parse::{names, parse_armature};
use super::SimulateArgs;
use crate::cli::out::errln;
use crate::cli::range::simulate::{CONTACT, FRICTION, SOLE_CENTER, SOLE_SIZE};
use biped_dynamics::urdf::srdf::{load_srdf_file, Srdf};
use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::contact::ContactParams;
use biped_sim::plant::{urdf_plant, Armature, Plant, PlantConfig, UrdfFeet};
use biped_sim::scenario::{ScenarioKind, ScenarioOptions, SwayJoints};
use biped_sim::SimError;
use nalgebra::Vector3;
use std::path::Path;

/// Error of this module: one line naming the option.
type SetupError = Box<dyn std::error::Error>;

/// Fixed step of Type 3 \[s]: its elastic gears (~9000 rad/s on the toe) need <= 0.25 ms.
const TYPE3_STEP: f64 = 1e-4;

/// Plant, scenario options, label and default fixed step of the Lola-like biped.
pub type Source = (Plant, ScenarioOptions, String, f64);

/// The Lola-like biped of `crates/robots/data/lola.toml`.
pub fn lola_source(a: &SimulateArgs) -> Result<Source, SetupError> {
    let text = a.lola.as_deref().unwrap_or("type2");
    let variant: LolaType = text.parse().map_err(|e| format!("--lola: {e}"))?;
    let lp = lola_plant(variant, plant_config(a, ContactParams::default())?)?;
    let options = ScenarioOptions::lola();
    let step = match variant {
        LolaType::Type2 => options.period,
        LolaType::Type3 => TYPE3_STEP,
    };
    Ok((lp.plant, options, format!("Lola {variant:?}"), step))
}

/// Rejects the URDF options without `--urdf`.
pub fn urdf_only(a: &SimulateArgs) -> Result<(), String> {
    let given = [
        ("--floating", a.floating),
        ("--feet", a.feet.is_some()),
        ("--sole-center", a.sole_center.is_some()),
        ("--sole-size", a.sole_size.is_some()),
        ("--armature", a.armature.is_some()),
        ("--no-end-stops", a.no_end_stops),
        ("--no-joint-friction", a.no_joint_friction),
        ("--sway-joints", a.sway_joints.is_some()),
        ("--srdf", a.srdf.is_some()),
        ("--srdf-state", a.srdf_state.is_some()),
    ];
    match given.iter().find(|(_, on)| *on) {
        Some((option, _)) => Err(format!("{option}: only applies with --urdf FILE")),
        None => Ok(()),
    }
}

/// A floating-base URDF robot with the sole rectangles and sway joints of the options.
pub fn urdf_source(
    a: &SimulateArgs,
    path: &Path,
    kind: ScenarioKind,
) -> Result<Source, SetupError> {
    if a.lola.is_some() {
        return Err("--lola: give either --lola TYPE or --urdf FILE, not both".into());
    }
    if !a.floating {
        let why = "--urdf: add --floating (the scenarios put a free-floating robot on the ground)";
        return Err(why.into());
    }
    let feet = urdf_feet(a)?;
    let srdf = srdf(a)?;
    let mut armature = armature(a)?;
    if let Some((_, s)) = &srdf {
        armature.extend(s.rotors.iter().map(|r| Armature {
            pattern: r.joint.clone(),
            inertia: r.armature(),
            required: false,
        }));
    }
    let mut config = plant_config(a, ContactParams::light_feet())?;
    config.passive.end_stops = !a.no_end_stops;
    config.passive.joint_friction = !a.no_joint_friction;
    let plant = urdf_plant(path, &feet, &armature, config).map_err(|e| match e {
        SimError::InvalidParameter { what, reason } if what == "armature" => {
            format!("--armature: {reason} in {}", path.display())
        }
        SimError::InvalidParameter { what, reason } if what == "urdf" => reason,
        e @ SimError::Unknown { .. } => format!("--feet: {e} in {}", path.display()),
        e => format!("{}: {e}", path.display()),
    })?;
    let mut options = ScenarioOptions {
        sway_joints: sway_joints(a, kind)?,
        ..ScenarioOptions::default()
    };
    if let Some((file, s)) = &srdf {
        warn_unused_rotors(file, s, &plant, path);
        if let Some(name) = &a.srdf_state {
            options.pose = srdf_pose(file, s, name, &plant)?;
        }
    }
    let step = options.period;
    Ok((plant, options, path.display().to_string(), step))
}

/// The SRDF of `--srdf` with its file name; `--srdf-state` needs it.
fn srdf(a: &SimulateArgs) -> Result<Option<(String, Srdf)>, String> {
    match (&a.srdf, &a.srdf_state) {
        (Some(path), _) => {
            let s = load_srdf_file(path).map_err(|e| format!("--srdf: {e}"))?;
            Ok(Some((path.display().to_string(), s)))
        }
        (None, Some(_)) => Err("--srdf-state: needs --srdf FILE".into()),
        (None, None) => Ok(None),
    }
}

/// True if `joint` is one of the plant's actuated (movable) joints.
fn moves(plant: &Plant, joint: &str) -> bool {
    plant.actuators().iter().any(|a| a.name == joint)
}

/// Warns (stderr) about SRDF rotors of joints the URDF model does not move (e.g. a reduced
/// model's locked joints): they were skipped.
fn warn_unused_rotors(file: &str, s: &Srdf, plant: &Plant, urdf: &Path) {
    let unused: Vec<_> = s
        .rotors
        .iter()
        .filter(|r| !moves(plant, &r.joint))
        .collect();
    if let Some(first) = unused.first() {
        errln!(
            "warning: {file}:{}: {} rotor_params entries name joints that {} does not move \
             (first `{}`); skipped",
            first.line,
            unused.len(),
            urdf.display(),
            first.joint
        );
    }
}

/// The one-DoF joint values of the SRDF group state `name` as a start pose; a free-flyer's
/// value is left out (the scenario places the base) and so, with a warning, are joints the
/// URDF model does not move.
fn srdf_pose(
    file: &str,
    s: &Srdf,
    name: &str,
    plant: &Plant,
) -> Result<Vec<(String, f64)>, String> {
    let state = s.state(name).ok_or_else(|| {
        let have: Vec<_> = s.states.iter().map(|g| g.name.as_str()).collect();
        format!(
            "--srdf-state: no group_state `{name}` in {file} (it has: {})",
            if have.is_empty() {
                "none".to_string()
            } else {
                have.join(", ")
            }
        )
    })?;
    let mut pose = Vec::new();
    let mut unknown = Vec::new();
    for (joint, values) in &state.joints {
        match values[..] {
            [x] if moves(plant, joint) => pose.push((joint.clone(), x)),
            [_] => unknown.push(joint.as_str()),
            _ => {} // A multi-coordinate joint: the floating base.
        }
    }
    if let Some(first) = unknown.first() {
        errln!(
            "warning: {file}:{}: group_state `{name}` sets {} joints the URDF does not move \
             (first `{first}`); skipped",
            state.line,
            unknown.len()
        );
    }
    Ok(pose)
}

/// Rotor inertias from `--armature` (none without it).
fn armature(a: &SimulateArgs) -> Result<Vec<Armature>, String> {
    let Some(text) = &a.armature else {
        return Ok(Vec::new());
    };
    let pairs = parse_armature(text)?;
    Ok(pairs
        .into_iter()
        .map(|(pattern, inertia)| Armature {
            pattern,
            inertia,
            required: true,
        })
        .collect())
}

/// Sole links and rectangle from `--feet`, `--sole-center`, `--sole-size`.
fn urdf_feet(a: &SimulateArgs) -> Result<UrdfFeet, String> {
    let text = a
        .feet
        .as_deref()
        .ok_or("--urdf: add --feet LEFT,RIGHT (the links carrying the soles)")?;
    let links = names(text, 2, "--feet", "LEFT,RIGHT")?;
    let mut feet = UrdfFeet::new(&links[0], &links[1]);
    if let Some(text) = &a.sole_center {
        feet.center = Vector3::from(SOLE_CENTER.parse(text)?);
    }
    if let Some(text) = &a.sole_size {
        [feet.length, feet.width] = SOLE_SIZE.parse(text)?;
    }
    Ok(feet)
}

/// Sway joints from `--sway-joints` (required by `sway` on a URDF robot, and only for it).
fn sway_joints(a: &SimulateArgs, kind: ScenarioKind) -> Result<Option<SwayJoints>, String> {
    const SHAPE: &str = "HIP_L,HIP_R,ANKLE_L,ANKLE_R";
    match &a.sway_joints {
        Some(_) if kind != ScenarioKind::Sway => {
            Err("--sway-joints: only applies with --scenario sway".into())
        }
        Some(text) => {
            let j = names(text, 4, "--sway-joints", SHAPE)?;
            Ok(Some(SwayJoints {
                hips: [j[0].clone(), j[1].clone()],
                ankles: [j[2].clone(), j[3].clone()],
            }))
        }
        None if kind == ScenarioKind::Sway => Err(format!(
            "--scenario sway on a URDF robot needs --sway-joints {SHAPE}"
        )),
        None => Ok(None),
    }
}

/// Plant options: `--contact K,D` and `--friction MU` on top of the `base` contact law.
fn plant_config(a: &SimulateArgs, base: ContactParams) -> Result<PlantConfig, SetupError> {
    let contact = match &a.contact {
        Some(text) => {
            let [k, d] = CONTACT.parse(text)?;
            base.with_spring_damper(k, d)
        }
        None => base,
    };
    let friction = match &a.friction {
        Some(text) => FRICTION.parse(text)?,
        None => contact.friction,
    };
    Ok(PlantConfig {
        contact: ContactParams {
            friction,
            ..contact
        },
        ..PlantConfig::default()
    })
}
