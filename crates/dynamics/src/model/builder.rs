//! Validating model builder: bodies are added parent-first, coordinates are assigned in order.

use super::joint::{Joint, JointModel};
use super::{Body, BodyId, IndexSet, JointInfo, Mechanism, Model, MAX_INDEX_SET};
use crate::mechanism::{Coupling, MAX_COUPLED};
use crate::spatial::{RigidInertia, SpatialTransform};
use crate::ModelError;
use nalgebra::{Isometry3, Unit, Vector3};
use std::collections::HashSet;

/// Description of one body and the joint attaching it to its parent.
#[derive(Clone, Debug)]
pub struct BodySpec {
    /// Unique body name.
    pub name: String,
    /// Unique joint name.
    pub joint_name: String,
    /// Parent body (`None` = attached to the fixed world frame).
    pub parent: Option<BodyId>,
    /// Joint model.
    pub joint: JointModel,
    /// Pose of the joint frame in the parent body frame at `q = neutral`.
    pub placement: Isometry3<f64>,
    /// Inertia in this body's frame (the joint's child frame).
    pub inertia: RigidInertia,
}

impl BodySpec {
    /// Body `name` whose joint is named alike.
    pub fn named(
        name: &str,
        parent: Option<BodyId>,
        joint: JointModel,
        placement: Isometry3<f64>,
        inertia: RigidInertia,
    ) -> Self {
        Self {
            name: name.into(),
            joint_name: name.into(),
            parent,
            joint,
            placement,
            inertia,
        }
    }
}

/// Incremental, validating constructor of a [`Model`].
#[derive(Clone, Debug)]
pub struct ModelBuilder {
    bodies: Vec<Body>,
    body_names: HashSet<String>,
    joint_names: HashSet<String>,
    /// Last velocity coordinate owned by each body or its nearest owning ancestor.
    chain_dof: Vec<Option<usize>>,
    dof_parent: Vec<Option<usize>>,
    nq: usize,
    nv: usize,
    gravity: Vector3<f64>,
}

impl Default for ModelBuilder {
    fn default() -> Self {
        Self::new()
    }
}

impl ModelBuilder {
    /// Empty builder with gravity `(0, 0, -9.81)` in the world frame.
    pub fn new() -> Self {
        Self {
            bodies: Vec::new(),
            body_names: HashSet::new(),
            joint_names: HashSet::new(),
            chain_dof: Vec::new(),
            dof_parent: Vec::new(),
            nq: 0,
            nv: 0,
            gravity: Vector3::new(0.0, 0.0, -9.81),
        }
    }

    /// Sets gravity in the world frame (checked for finiteness in [`Self::build`]).
    pub fn set_gravity(&mut self, g: Vector3<f64>) {
        self.gravity = g;
    }

    /// Adds a body whose parent already exists; returns its index.
    pub fn add_body(&mut self, spec: BodySpec) -> Result<BodyId, ModelError> {
        let id = self.bodies.len();
        self.check_parent(&spec, id)?;
        if self.body_names.contains(&spec.name) {
            return Err(ModelError::DuplicateBodyName(spec.name));
        }
        if self.joint_names.contains(&spec.joint_name) {
            return Err(ModelError::DuplicateJointName(spec.joint_name));
        }
        let placement = checked_placement(&spec)?;
        let joint_model = checked_joint(&spec)?;
        let (q_index, v_index, owns) = self.index_set(&spec, &joint_model)?;
        let (nq_set, nv_set) = if owns {
            (joint_model.nq(), joint_model.nv())
        } else {
            (1, 1)
        };
        let joint = Joint::compile(&joint_model);
        let parent_chain = spec.parent.and_then(|p| self.chain_dof[p]);
        let nv = joint_model.nv();
        if owns {
            for c in 0..nv {
                self.dof_parent.push(if c == 0 {
                    parent_chain
                } else {
                    Some(v_index + c - 1)
                });
            }
            self.nq += joint_model.nq();
            self.nv += nv;
        }
        self.chain_dof.push(if owns && nv > 0 {
            Some(v_index + nv - 1)
        } else {
            parent_chain
        });
        let q_set = self.coupled_set(&joint_model, |b| b.q_index, q_index, nq_set);
        let v_set = self.coupled_set(&joint_model, |b| b.v_index, v_index, nv_set);
        self.body_names.insert(spec.name.clone());
        self.joint_names.insert(spec.joint_name.clone());
        self.bodies.push(Body {
            name: spec.name,
            joint_name: spec.joint_name,
            parent: spec.parent,
            first_child: None,
            brother: None,
            joint_model,
            joint,
            placement,
            placement_x: SpatialTransform::from_pose(&placement),
            inertia: spec.inertia,
            q_index,
            v_index,
            q_set,
            v_set,
            owns_coordinates: owns,
        });
        Ok(id)
    }

    /// Finishes the model: links children and brothers (Fig. 2.7), lists the joints.
    pub fn build(mut self) -> Result<Model, ModelError> {
        if !self.gravity.iter().all(|x| x.is_finite()) {
            return Err(ModelError::NonFiniteGravity);
        }
        let mut last_child: Vec<Option<BodyId>> = vec![None; self.bodies.len()];
        let mut last_root: Option<BodyId> = None;
        for i in 0..self.bodies.len() {
            let slot = match self.bodies[i].parent {
                Some(p) => &mut last_child[p],
                None => &mut last_root,
            };
            match *slot {
                Some(prev) => self.bodies[prev].brother = Some(i),
                None => {
                    if let Some(p) = self.bodies[i].parent {
                        self.bodies[p].first_child = Some(i);
                    }
                }
            }
            *slot = Some(i);
        }
        let joints = self
            .bodies
            .iter()
            .filter(|b| b.owns_coordinates && b.joint_model.nv() > 0)
            .map(|b| JointInfo {
                name: b.joint_name.clone(),
                nq: b.joint_model.nq(),
                nv: b.joint_model.nv(),
                q_index: b.q_index,
                v_index: b.v_index,
            })
            .collect();
        let has_rotors = self.bodies.iter().any(|b| !b.owns_coordinates);
        let (subsystems, nodes) = crate::subsystem::generate(&self.bodies)?;
        Ok(Model {
            bodies: self.bodies,
            joints,
            nq: self.nq,
            nv: self.nv,
            gravity: self.gravity,
            dof_ancestors: super::ancestors::DofAncestors::new(&self.dof_parent),
            dof_parent: self.dof_parent,
            has_rotors,
            subsystems,
            nodes,
        })
    }

    /// Parent must exist, must not be the body itself and must not be a rotor.
    fn check_parent(&self, spec: &BodySpec, id: BodyId) -> Result<(), ModelError> {
        let Some(p) = spec.parent else { return Ok(()) };
        if p == id {
            return Err(ModelError::CyclicParent {
                body: spec.name.clone(),
            });
        }
        if p > id {
            return Err(ModelError::UnknownParent {
                body: spec.name.clone(),
                parent: p,
                nbodies: id,
            });
        }
        if !self.bodies[p].owns_coordinates {
            return Err(ModelError::ChildOfRotor {
                body: spec.name.clone(),
                rotor: self.bodies[p].name.clone(),
            });
        }
        Ok(())
    }

    /// Index set of a coupled part: its inputs' coordinates; otherwise `start..start + len`.
    fn coupled_set(
        &self,
        joint: &JointModel,
        index: impl Fn(&Body) -> usize,
        start: usize,
        len: usize,
    ) -> IndexSet {
        let JointModel::Coupled { inputs, .. } = joint else {
            return IndexSet::contiguous(start, len);
        };
        let mut idx = [0; MAX_INDEX_SET];
        for (slot, &b) in idx.iter_mut().zip(inputs) {
            *slot = index(&self.bodies[b]);
        }
        IndexSet::from_slice(&idx[..inputs.len()])
    }

    /// Index set (2.26) of a new body: own fresh coordinates, or its driver's for a rotor.
    fn index_set(
        &self,
        spec: &BodySpec,
        joint: &JointModel,
    ) -> Result<(usize, usize, bool), ModelError> {
        if let JointModel::Coupled { mechanism, inputs } = joint {
            return self.coupled_index_set(spec, mechanism, inputs);
        }
        let JointModel::GearedRotor { driver, .. } = joint else {
            return Ok((self.nq, self.nv, true));
        };
        let bad = |reason| ModelError::BadDriver {
            body: spec.name.clone(),
            driver: *driver,
            reason,
        };
        let d = self
            .bodies
            .get(*driver)
            .ok_or(bad("no such body (drivers must precede rotors)"))?;
        if !matches!(d.joint, Joint::Revolute(_) | Joint::Prismatic(_)) {
            return Err(bad("driver joint is not revolute or prismatic"));
        }
        let tip = spec.parent.and_then(|p| self.chain_dof[p]);
        if let Some(t) = tip {
            if !self.dof_is_ancestor(d.v_index, t) && !self.dof_is_ancestor(t, d.v_index) {
                return Err(bad("driver coordinate not on the rotor's path to the root"));
            }
        }
        Ok((d.q_index, d.v_index, false))
    }

    /// Validates the inputs of a coupled part: existing one-DoF bodies, as many as the
    /// mechanism reads, whose coordinates lie on one path of the DoF tree together with the
    /// part's parent (so the mass matrix keeps the sparsity pattern of `lambda`).
    fn coupled_index_set(
        &self,
        spec: &BodySpec,
        mechanism: &Mechanism,
        inputs: &[BodyId],
    ) -> Result<(usize, usize, bool), ModelError> {
        let bad = |driver: usize, reason| ModelError::BadDriver {
            body: spec.name.clone(),
            driver,
            reason,
        };
        if inputs.is_empty() || inputs.len() > MAX_COUPLED || inputs.len() != mechanism.n_inputs() {
            return Err(bad(
                inputs.len(),
                "number of inputs differs from the mechanism's (or exceeds MAX_COUPLED)",
            ));
        }
        let mut dofs = [0; MAX_COUPLED + 1];
        for (k, &d) in inputs.iter().enumerate() {
            let body = self
                .bodies
                .get(d)
                .ok_or(bad(d, "no such body (inputs must precede the part)"))?;
            if !matches!(body.joint, Joint::Revolute(_) | Joint::Prismatic(_))
                || !body.owns_coordinates
            {
                return Err(bad(d, "input joint is not revolute or prismatic"));
            }
            if inputs[..k].contains(&d) {
                return Err(bad(d, "input listed twice"));
            }
            dofs[k] = body.v_index;
        }
        let mut n = inputs.len();
        if let Some(t) = spec.parent.and_then(|p| self.chain_dof[p]) {
            dofs[n] = t;
            n += 1;
        }
        let dofs = &mut dofs[..n];
        dofs.sort_unstable();
        for w in dofs.windows(2) {
            if !self.dof_is_ancestor(w[0], w[1]) {
                return Err(bad(
                    inputs[0],
                    "inputs and parent are not on one path to the root",
                ));
            }
        }
        let first = &self.bodies[inputs[0]];
        Ok((first.q_index, first.v_index, false))
    }

    /// True if DoF `a` is DoF `b` or one of its ancestors in the DoF tree.
    fn dof_is_ancestor(&self, a: usize, b: usize) -> bool {
        let mut k = Some(b);
        while let Some(i) = k {
            if i == a {
                return true;
            }
            if i < a {
                return false;
            }
            k = self.dof_parent[i];
        }
        false
    }
}

/// Placement with finite entries and a normalised rotation.
fn checked_placement(spec: &BodySpec) -> Result<Isometry3<f64>, ModelError> {
    let p = &spec.placement;
    let q = p.rotation.quaternion();
    let finite = p.translation.vector.iter().all(|x| x.is_finite())
        && q.coords.iter().all(|x| x.is_finite())
        && q.norm() > 1e-12;
    if !finite {
        return Err(ModelError::NonFinitePlacement {
            body: spec.name.clone(),
        });
    }
    let rotation = nalgebra::UnitQuaternion::new_normalize(*q);
    Ok(Isometry3::from_parts(p.translation, rotation))
}

/// Joint model with a renormalised, non-zero axis and a valid gear ratio.
fn checked_joint(spec: &BodySpec) -> Result<JointModel, ModelError> {
    let axis = |a: &Unit<Vector3<f64>>| {
        let v = a.as_ref();
        let n = v.norm();
        if !v.iter().all(|x| x.is_finite()) || n <= 1e-9 {
            return Err(ModelError::ZeroAxis {
                body: spec.name.clone(),
            });
        }
        Ok(Unit::new_unchecked(v / n))
    };
    Ok(match &spec.joint {
        JointModel::Revolute { axis: a } => JointModel::Revolute { axis: axis(a)? },
        JointModel::Prismatic { axis: a } => JointModel::Prismatic { axis: axis(a)? },
        JointModel::GearedRotor {
            axis: a,
            ratio,
            driver,
        } => {
            if !ratio.is_finite() || *ratio == 0.0 {
                return Err(ModelError::InvalidGearRatio {
                    body: spec.name.clone(),
                    ratio: *ratio,
                });
            }
            JointModel::GearedRotor {
                axis: axis(a)?,
                ratio: *ratio,
                driver: *driver,
            }
        }
        other => other.clone(),
    })
}
