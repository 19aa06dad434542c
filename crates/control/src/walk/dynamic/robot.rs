//! [`DynamicRobot`]: what the dynamic walk needs to know about a robot beyond its kinematic walk
//! ([`WalkRobot`]): how its plant is built, the frames that carry the planned ground wrench
//! ([`super::feedforward`]), the leg joints of the foot force control ([`super::force`]), the
//! ankle joints of the stabiliser ([`super::stabiliser`]) and its size, which scales the gains
//! ([`super::DynamicWalkParams::for_robot`]).
//!
//! Built for the Lola-like model ([`DynamicRobot::lola`]: its plant `lola_plant`, its foot and
//! toe segments, its ankle joints) or from a robot description ([`DynamicRobot::from_description`]):
//! a URDF plant ([`biped_sim::plant::urdf_plant`]) with the description's sole rectangles as the
//! contact feet, its drive data as the rotor inertias and the URDF ranges as end stops; the
//! bodies of the walk's sole (and toe) frames carry the ground wrench; each leg group's joints move its foot, and of its last two joints
//! (the ankle) the one whose axis lies closer to the lateral axis in the walking posture is the
//! pitch joint, the other the roll joint. The ground contact law follows from the robot's
//! weight, CoM height, sole and foot mass ([`SOLE_ROLL_MARGIN`]).

use super::robot_legs::{ankle_of, leg_names, DynamicLeg};
use crate::tasks::Frame;
use crate::walk::error::{model_err, WalkError};
use crate::walk::evaluate::body;
use crate::walk::robot::WalkRobot;
use biped_robots::description::Robot;
use biped_robots::lola::{self, LolaType};
use biped_sim::contact::{sole_rectangle, ContactParams};
use biped_sim::plant::{Armature, UrdfFeet};
use nalgebra::Vector3;
use std::path::PathBuf;

/// How the plant of a [`DynamicRobot`] is built.
#[derive(Debug, Clone, PartialEq)]
pub enum PlantSource {
    /// The Lola-like biped of `biped_robots::plant::lola_plant`.
    Lola(LolaType),
    /// A floating-base URDF plant ([`biped_sim::plant::urdf_plant`]).
    Urdf {
        /// The URDF file.
        path: PathBuf,
        /// The sole rectangles of the feet.
        feet: UrdfFeet,
        /// Reflected rotor inertias by joint-name pattern.
        armature: Vec<Armature>,
    },
}

/// A robot as the dynamic walk sees it (see the module docs). Pairs are `[left, right]`.
#[derive(Debug, Clone)]
pub struct DynamicRobot {
    /// The robot of the kinematic walk the reference comes from.
    pub walk: WalkRobot,
    /// How the plant is built.
    pub source: PlantSource,
    /// The ground's contact law (the friction coefficient is the walk's).
    pub contact: ContactParams,
    /// Legs: the joints that move each foot and its ankle joints.
    pub legs: [DynamicLeg; 2],
    /// Bodies that carry each side's share of the planned ground wrench with the foot flat.
    pub feet: [usize; 2],
    /// Bodies that carry it in toe-off (feet with toe segments).
    pub toes: Option<[usize; 2]>,
    /// Sole frames the foot force control moves.
    pub soles: [Frame; 2],
    /// Total mass of the model \[kg].
    pub mass: f64,
}

impl DynamicRobot {
    /// The Lola-like model of `variant`: its plant, foot (`l_foot`, `r_foot`) and toe
    /// segments, soles (`l_sole`, `r_sole`), legs `l_*` / `r_*` (hip rotation to foot) and
    /// ankles (flexion `*_ankle_cross`, adduction `*_foot`).
    pub fn lola(variant: LolaType) -> Result<Self, WalkError> {
        let model = lola::build(variant).map_err(model_err)?;
        let walk = WalkRobot::lola(&model)?;
        let m = &walk.model;
        let id = |n: &str| body(m, n);
        let legs = [DynamicLeg::lola("l"), DynamicLeg::lola("r")];
        Ok(Self {
            source: PlantSource::Lola(variant),
            contact: ContactParams::default(),
            legs,
            feet: [id("l_foot")?, id("r_foot")?],
            toes: Some([id("l_toe")?, id("r_toe")?]),
            soles: [id("l_sole")?, id("r_sole")?].map(Frame::body),
            mass: m.mass(),
            walk,
        })
    }

    /// The robot of a loaded description with its walk `walk` (of
    /// [`WalkRobot::from_description`]); see the module docs. Both feet must have the same
    /// sole rectangle, and every leg six joints.
    pub fn from_description(robot: &Robot, walk: WalkRobot) -> Result<Self, WalkError> {
        let d = &robot.description;
        let file = &d.file;
        let feet = urdf_feet(robot)?;
        let armature = d
            .armature
            .iter()
            .map(|(pattern, inertia)| Armature {
                pattern: pattern.clone(),
                inertia: *inertia,
                required: false,
            })
            .collect();
        let names = [leg_names(&d.legs[0], file)?, leg_names(&d.legs[1], file)?];
        let legs = names.map(|joints| ankle_of(&walk, joints));
        let [Ok(left), Ok(right)] = legs else {
            return Err(WalkError::Description(format!(
                "{file}: a leg's last two joints are no revolute ankle joints"
            )));
        };
        // the walk's slots are [right, left]
        let [sr, sl] = walk.frames.soles;
        let toes = walk.frames.toes.map(|[tr, tl]| [tl.body, tr.body]);
        let contact = sole_contact(&walk, &feet, sl.body)?;
        Ok(Self {
            source: PlantSource::Urdf {
                path: d.urdf.clone(),
                feet,
                armature,
            },
            contact,
            legs: [left, right],
            feet: [sl.body, sr.body],
            toes,
            soles: [sl, sr],
            mass: walk.model.mass(),
            walk,
        })
    }

    /// The weight of the robot \[N].
    pub fn weight(&self) -> f64 {
        self.mass * self.walk.model.gravity().norm()
    }

    /// Height of the robot's CoM above its soles in the walking posture \[m].
    pub fn com_height(&self) -> f64 {
        self.walk.com_height
    }
}

/// The description's feet as the plant's contact feet (one rectangle for both).
fn urdf_feet(robot: &Robot) -> Result<UrdfFeet, WalkError> {
    let d = &robot.description;
    let [l, r] = &d.feet;
    if l.sole_center != r.sole_center || l.sole_size != r.sole_size {
        return Err(WalkError::Description(format!(
            "{}: the dynamic walk needs the same sole rectangle on both feet",
            d.file
        )));
    }
    Ok(UrdfFeet {
        links: vec![
            ("left".into(), l.frame.clone()),
            ("right".into(), r.frame.clone()),
        ],
        center: l.sole_center,
        length: l.sole_size[0],
        width: l.sole_size[1],
    })
}

/// Roll stiffness of the soles on the ground over the robot's toppling stiffness `m g h` that
/// `sole_contact` asks for (at 1x a described G1 falls sideways over its 5.5 cm wide sole, at
/// 2x after 8 steps, at 4x it walks).
pub const SOLE_ROLL_MARGIN: f64 = 4.0;

/// Damping ratio of a foot's vertical mode on the contact points (`sole_contact`).
pub const FOOT_DAMPING_RATIO: f64 = 0.6;

/// Largest `h omega` of a foot's vertical mode at the 1 ms control period (RK4 is stable up
/// to 2.8 on the imaginary axis).
const FOOT_MODE_STEP: f64 = 2.0;

/// The ground contact law of a described robot: the defaults with the point stiffness `k` that
/// gives one sole the roll stiffness `k sum y_i^2` (points `y_i` across the sole) of
/// [`SOLE_ROLL_MARGIN`] times the robot's `m g h` (h: the walk's CoM height; a laterally
/// compliant sole under a narrow foot topples the robot), capped so that the foot's vertical
/// mode `omega = sqrt(n k / m_foot)` (n points, the mass of the foot's body) stays within
/// [`FOOT_MODE_STEP`] of the control period; the damping makes that mode's damping ratio
/// [`FOOT_DAMPING_RATIO`], normal and tangential alike.
fn sole_contact(
    walk: &WalkRobot,
    feet: &UrdfFeet,
    foot: usize,
) -> Result<ContactParams, WalkError> {
    let points = sole_rectangle(Vector3::zeros(), feet.length, feet.width);
    let n = points.len() as f64;
    let roll: f64 = points.iter().map(|p| p.y * p.y).sum();
    let m = &walk.model;
    let topple = m.mass() * m.gravity().norm() * walk.com_height;
    let m_foot = m.bodies().get(foot).map_or(0.0, |b| b.inertia().mass());
    let h = crate::pattern::PatternParams::default().dt;
    let cap = (FOOT_MODE_STEP / h).powi(2) * m_foot / n;
    let k = (SOLE_ROLL_MARGIN * topple / roll).min(cap);
    let d = FOOT_DAMPING_RATIO * 2.0 * (k * m_foot / n).sqrt();
    if !(k.is_finite() && k > 0.0 && d > 0.0) {
        return Err(model_err(format!(
            "no contact law for a {:.3} m x {:.3} m sole under a {m_foot:.3} kg foot",
            feet.length, feet.width
        )));
    }
    Ok(ContactParams::default().with_spring_damper(k, d))
}

/// How [`super::DynamicWalkParams::for_robot`] scales the defaults (tuned on the Lola-like
/// model) to another robot: by the ratios of its weight and CoM height to the reference's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RobotScale {
    /// Weight over the reference's.
    pub weight: f64,
    /// CoM height over the reference's.
    pub height: f64,
}

impl RobotScale {
    /// The scale of `robot` against `reference`.
    pub fn between(robot: &DynamicRobot, reference: &DynamicRobot) -> Self {
        Self {
            weight: robot.weight() / reference.weight(),
            height: robot.com_height() / reference.com_height(),
        }
    }

    /// `p` with the size-dependent entries scaled: the foot force control's compliance by
    /// the inverse weight (the same height offset per share of the weight), its offset limit
    /// and the fall drop by the height.
    pub fn apply(&self, p: super::DynamicWalkParams) -> super::DynamicWalkParams {
        let force = p.force.map(|g| super::ForceGains {
            compliance: g.compliance / self.weight,
            max_offset: g.max_offset * self.height,
            ..g
        });
        super::DynamicWalkParams {
            force,
            fall_drop: p.fall_drop * self.height,
            ..p
        }
    }
}
