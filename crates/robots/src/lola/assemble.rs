//! Turns the parameter file into a [`Model`]: link bodies, then the drive parts of each joint
//! (Harmonic Drive rotors, knee screw parts, ankle slider-crank parts, Type 3 motor bodies).

use super::params::{BodyParams, Locator, LolaError, LolaParams, PartParams};
use super::{ElasticGear, JointLimit, LolaModel, LolaType};
use biped_dynamics::mechanism::ankle::{AnkleDrive, AnkleDriveParams, AnklePart};
use biped_dynamics::mechanism::harmonic_drive::{HarmonicDriveParams, HarmonicDriveRotor};
use biped_dynamics::mechanism::knee::{KneeDrive, KneeDriveParams, KneePart};
use biped_dynamics::model::Mechanism;
use biped_dynamics::{BodyId, BodySpec, JointModel, ModelBuilder, RigidInertia};
use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, Unit, UnitQuaternion, Vector3};
use std::collections::HashMap;

mod drives;

/// Inertia of a solid box of the given size centred at the CoM.
pub(crate) fn box_inertia(p: &PartParams) -> Result<RigidInertia, LolaError> {
    let [a, b, c] = p.size.map(|x| x * x);
    let k = p.mass / 12.0;
    let diag = Matrix3::from_diagonal(&Vector3::new(k * (b + c), k * (a + c), k * (a + b)));
    Ok(RigidInertia::new(p.mass, Vector3::from(p.com), diag)?)
}

/// A link joint waiting for the second ankle input.
struct PendingAnkle {
    shank: BodyId,
    cross: BodyId,
    center: Vector3<f64>,
    lower: f64,
    upper: f64,
}

/// State of the assembly.
struct Assembler<'a> {
    p: &'a LolaParams,
    loc: &'a Locator<'a>,
    variant: LolaType,
    builder: ModelBuilder,
    ids: HashMap<String, BodyId>,
    /// (body id, name, lower, upper) of the actuated joints.
    actuated: Vec<(BodyId, String, f64, f64)>,
    /// (link body, motor body, ratio, name) of Type 3.
    motors: Vec<(BodyId, BodyId, f64, String)>,
    ankles: HashMap<BodyId, PendingAnkle>,
}

/// Builds the model of `p` for `variant`.
pub(crate) fn assemble(
    p: &LolaParams,
    loc: &Locator,
    variant: LolaType,
) -> Result<LolaModel, LolaError> {
    let mut a = Assembler {
        p,
        loc,
        variant,
        builder: ModelBuilder::new(),
        ids: HashMap::new(),
        actuated: Vec::new(),
        motors: Vec::new(),
        ankles: HashMap::new(),
    };
    for body in &p.body {
        a.add(body)
            .map_err(|e| loc.locate(e, Some(body.name.span())))?;
    }
    if let Some((_, pending)) = a.ankles.iter().next() {
        let name = a.builder_name(pending.cross);
        return Err(LolaError::Invalid {
            file: loc.file.to_string(),
            line: 0,
            field: "drive",
            reason: format!("ankle flexion `{name}` has no ankle_adduction child"),
        });
    }
    a.finish().map_err(|e| loc.locate(e, None))
}

impl Assembler<'_> {
    fn builder_name(&self, id: BodyId) -> String {
        self.ids
            .iter()
            .find(|(_, &v)| v == id)
            .map_or_else(String::new, |(k, _)| k.clone())
    }

    /// Adds one body of the file and its drive parts.
    fn add(&mut self, b: &BodyParams) -> Result<(), LolaError> {
        let name = b.name.get_ref().clone();
        if self.ids.contains_key(&name) {
            let reason = format!("duplicate body `{name}`");
            return Err(self.loc.invalid(b.name.span(), "name", reason));
        }
        let parent = self.parent(b)?;
        let kind = b
            .joint
            .as_ref()
            .map_or("revolute", |j| j.get_ref().as_str());
        let (joint, joint_name) = match kind {
            "free" => (JointModel::FreeQuaternion, "root".to_string()),
            "fixed" => (JointModel::Fixed, name.clone()),
            "revolute" => (
                JointModel::Revolute {
                    axis: self.axis(b)?,
                },
                name.clone(),
            ),
            other => {
                let span = b.joint.as_ref().map_or(0..0, |j| j.span());
                let reason = format!("unknown joint `{other}` (revolute, free, fixed)");
                return Err(self.loc.invalid(span, "joint", reason));
            }
        };
        let inertia = box_inertia(&PartParams {
            mass: b.mass,
            com: b.com,
            size: b.size,
        })?;
        let id = self.builder.add_body(BodySpec {
            name: name.clone(),
            joint_name,
            parent,
            joint,
            placement: Isometry3::translation(b.origin[0], b.origin[1], b.origin[2]),
            inertia,
        })?;
        self.ids.insert(name.clone(), id);
        if kind == "revolute" {
            let [lower, upper] = self.limits(b)?;
            self.actuated.push((id, name, lower, upper));
            self.drive(b, id, parent, lower, upper)?;
        }
        Ok(())
    }

    fn parent(&self, b: &BodyParams) -> Result<Option<BodyId>, LolaError> {
        let Some(p) = &b.parent else { return Ok(None) };
        self.ids.get(p.get_ref()).copied().map(Some).ok_or_else(|| {
            let reason = format!("unknown parent `{}` (parents must come first)", p.get_ref());
            self.loc.invalid(p.span(), "parent", reason)
        })
    }

    fn axis(&self, b: &BodyParams) -> Result<Unit<Vector3<f64>>, LolaError> {
        let Some(a) = &b.axis else {
            return Err(self.loc.invalid(b.name.span(), "axis", "missing".into()));
        };
        match a.get_ref().as_str() {
            "x" => Ok(Vector3::x_axis()),
            "y" => Ok(Vector3::y_axis()),
            "z" => Ok(Vector3::z_axis()),
            other => Err(self
                .loc
                .invalid(a.span(), "axis", format!("`{other}` is not x, y or z"))),
        }
    }

    fn limits(&self, b: &BodyParams) -> Result<[f64; 2], LolaError> {
        let Some(l) = &b.limits else {
            return Err(self.loc.invalid(b.name.span(), "limits", "missing".into()));
        };
        let [lo, hi] = *l.get_ref();
        if !(lo.is_finite() && hi.is_finite() && lo < hi) {
            return Err(self.loc.invalid(
                l.span(),
                "limits",
                format!("[{lo}, {hi}] is not a finite range with lower < upper"),
            ));
        }
        Ok([lo, hi])
    }

    /// Builds the model and the index tables.
    fn finish(self) -> Result<LolaModel, LolaError> {
        let model = self.builder.build()?;
        let body = |id: BodyId| &model.bodies()[id];
        let limits = self
            .actuated
            .iter()
            .map(|(id, name, lower, upper)| JointLimit {
                name: name.clone(),
                q_index: body(*id).q_index(),
                v_index: body(*id).v_index(),
                lower: *lower,
                upper: *upper,
            })
            .collect();
        let gears = self
            .motors
            .iter()
            .map(|(link, motor, ratio, name)| ElasticGear {
                joint: name.clone(),
                link_q: body(*link).q_index(),
                link_v: body(*link).v_index(),
                motor_q: body(*motor).q_index(),
                motor_v: body(*motor).v_index(),
                ratio: *ratio,
            })
            .collect();
        Ok(LolaModel {
            model,
            variant: self.variant,
            limits,
            gears,
        })
    }
}
