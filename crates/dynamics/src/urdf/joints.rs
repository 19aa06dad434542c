//! Joint properties a URDF gives beside the kinematic tree: the position range, effort and
//! velocity limits of `<limit>` and the passive damping and friction of `<dynamics>`.
//!
//! Conventions (URDF joint spec, with URDF 1.2's infinite limits):
//! - `continuous` joints have no range; a `revolute` or `prismatic` joint whose `lower` equals
//!   its `upper` (e.g. no `<limit>` element, both default to 0) has none either, with a warning.
//!   One side may be infinite (`lower="-inf"`).
//! - `effort` and `velocity` of 0 or infinity mean "no limit" (xacro files often write 0 for
//!   passive joints); negative or NaN values are errors.
//! - `<dynamics damping friction>`: viscous \[N m s/rad or N s/m] and Coulomb \[N m or N]
//!   coefficients, 0 when absent; negative or non-finite values are errors.

use super::source::Source;
use super::UrdfError;
use crate::BodyId;
use urdf_rs::JointType;

/// Limits and passive dynamics of one movable URDF joint (revolute, continuous, prismatic).
#[derive(Debug, Clone, PartialEq)]
pub struct JointProps {
    /// URDF joint name (the body's joint name).
    pub name: String,
    /// Body the joint moves.
    pub body: BodyId,
    /// Position range `[lower, upper]` \[rad or m]; `None` without one (see the module docs).
    pub range: Option<[f64; 2]>,
    /// Effort limit \[N m or N], `None` = unlimited.
    pub effort: Option<f64>,
    /// Velocity limit \[rad/s or m/s], `None` = unlimited.
    pub velocity: Option<f64>,
    /// Viscous damping coefficient \[N m s/rad or N s/m].
    pub damping: f64,
    /// Coulomb friction torque or force \[N m or N].
    pub friction: f64,
}

/// Reads and checks the properties of a movable joint that became body `body`.
pub(super) fn joint_props(
    joint: &urdf_rs::Joint,
    body: BodyId,
    src: &Source<'_>,
    warnings: &mut Vec<String>,
) -> Result<JointProps, UrdfError> {
    let bad = |field: &str, problem: String| src.invalid("joint", &joint.name, field, problem);
    let l = &joint.limit;
    let range = match joint.joint_type {
        JointType::Continuous => None,
        _ if l.lower.is_nan() || l.upper.is_nan() => {
            return Err(bad("limit", "lower and upper must be numbers".into()))
        }
        _ if l.lower > l.upper => {
            let problem = format!("lower {} is above upper {}", l.lower, l.upper);
            return Err(bad("limit", problem));
        }
        _ if l.lower == l.upper => {
            warnings.push(format!(
                "{}: limit lower = upper = {}: no joint range (no end stops)",
                src.at("joint", &joint.name),
                l.lower
            ));
            None
        }
        _ => Some([l.lower, l.upper]),
    };
    let (damping, friction) = joint
        .dynamics
        .as_ref()
        .map_or((0.0, 0.0), |d| (d.damping, d.friction));
    Ok(JointProps {
        name: joint.name.clone(),
        body,
        range,
        effort: optional_limit(l.effort).map_err(|p| bad("limit effort", p))?,
        velocity: optional_limit(l.velocity).map_err(|p| bad("limit velocity", p))?,
        damping: coefficient(damping).map_err(|p| bad("dynamics damping", p))?,
        friction: coefficient(friction).map_err(|p| bad("dynamics friction", p))?,
    })
}

/// A magnitude limit: 0 and infinity are "none", negative and NaN are errors.
fn optional_limit(x: f64) -> Result<Option<f64>, String> {
    match x {
        _ if x.is_nan() || x < 0.0 => Err(format!("must be >= 0, got {x}")),
        _ if x == 0.0 || x.is_infinite() => Ok(None),
        _ => Ok(Some(x)),
    }
}

/// A passive coefficient: finite and `>= 0`.
fn coefficient(x: f64) -> Result<f64, String> {
    match x.is_finite() && x >= 0.0 {
        true => Ok(x),
        false => Err(format!("must be finite and >= 0, got {x}")),
    }
}
