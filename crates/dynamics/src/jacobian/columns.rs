//! World-frame joint columns: every column of every relative Jacobian `J_j` (2.35) mapped to
//! world axes about the world origin, and their time derivatives.
//!
//! In world coordinates about a fixed point a column of joint `j` is the same for every
//! descendant of `j`, so one O(n) pass serves all body and point Jacobians (5.7).

use super::error::JacobianError;
use crate::check;
use crate::kinematics::body_kinematics;
use crate::model::joint::Joint;
use crate::spatial::{JointAxis, Motion, SpatialTransform, SubspaceKind};
use crate::{Data, DynamicsError, Model};
use nalgebra::{DVector, Matrix3, Vector3};

/// Preallocated world-frame Jacobian columns of one model (the shared input of all Jacobians).
#[derive(Clone, Debug)]
pub struct Jacobians {
    pub(crate) nv: usize,
    /// Parent of each body.
    pub(crate) parent: Vec<Option<usize>>,
    /// First column of each body in `col`; body `i` owns `offset[i]..offset[i + 1]`.
    pub(crate) offset: Vec<usize>,
    /// Velocity index of each column (shared by geared rotors and their drivers).
    pub(crate) index: Vec<usize>,
    /// Columns `S^W` in world axes about the world origin, `[ang; lin]`.
    pub(crate) col: Vec<Motion>,
    /// Time derivatives `d S^W / dt` of the columns.
    pub(crate) dcol: Vec<Motion>,
    /// World rotation of each body frame (body axes as columns).
    pub(crate) rot: Vec<Matrix3<f64>>,
    /// World position of each body origin.
    pub(crate) pos: Vec<Vector3<f64>>,
    /// World angular velocity of each body.
    pub(crate) omega: Vec<Vector3<f64>>,
    /// World velocity of each body origin.
    pub(crate) pos_dot: Vec<Vector3<f64>>,
    pub(crate) have_columns: bool,
    pub(crate) have_derivatives: bool,
}

impl Jacobians {
    /// Workspace sized for `model`.
    pub fn new(model: &Model) -> Self {
        let n = model.nbodies();
        let mut offset = Vec::with_capacity(n + 1);
        let mut index = Vec::new();
        offset.push(0);
        for b in model.bodies() {
            index.extend_from_slice(b.v_set().as_slice());
            offset.push(index.len());
        }
        let ncol = index.len();
        Self {
            nv: model.nv(),
            parent: model.bodies().iter().map(|b| b.parent()).collect(),
            offset,
            index,
            col: vec![Motion::zero(); ncol],
            dcol: vec![Motion::zero(); ncol],
            rot: vec![Matrix3::identity(); n],
            pos: vec![Vector3::zeros(); n],
            omega: vec![Vector3::zeros(); n],
            pos_dot: vec![Vector3::zeros(); n],
            have_columns: false,
            have_derivatives: false,
        }
    }

    /// Number of bodies this workspace was sized for.
    pub fn nbodies(&self) -> usize {
        self.parent.len()
    }

    /// Number of velocity coordinates (columns of every Jacobian).
    pub fn nv(&self) -> usize {
        self.nv
    }

    /// Runs the position kinematics for `q` (into `data`) and maps all joint columns to world.
    pub fn compute(
        &mut self,
        model: &Model,
        data: &mut Data,
        q: &DVector<f64>,
    ) -> Result<(), JacobianError> {
        self.fill(model, data, q, None, false)
    }

    /// Runs the kinematics for `(q, v)` (into `data`) and computes columns and their
    /// derivatives, so that Jacobians and their time derivatives can be read.
    pub fn compute_with_derivatives(
        &mut self,
        model: &Model,
        data: &mut Data,
        q: &DVector<f64>,
        v: &DVector<f64>,
    ) -> Result<(), JacobianError> {
        self.fill(model, data, q, Some(v), true)
    }

    /// Kinematics (with velocities if `v` is given) and columns (with rates if `derivatives`).
    pub(crate) fn fill(
        &mut self,
        model: &Model,
        data: &mut Data,
        q: &DVector<f64>,
        v: Option<&DVector<f64>>,
        derivatives: bool,
    ) -> Result<(), JacobianError> {
        self.check_inputs(model, data, q, v)?;
        let rates = if derivatives { v } else { None };
        if rates.is_some()
            && model
                .bodies
                .iter()
                .any(|b| matches!(b.joint, Joint::Coupled))
        {
            return Err(DynamicsError::Unsupported(
                "Jacobian time derivatives of coupled parts (the mechanism gives only Jdot qd)",
            )
            .into());
        }
        for i in 0..model.nbodies() {
            body_kinematics(model, data, i, q, v);
            self.store_body(model, data, i, q, v.is_some(), rates);
        }
        crate::kinematics::take_fault(data)?;
        self.have_columns = true;
        self.have_derivatives = rates.is_some();
        Ok(())
    }

    /// Errors unless this workspace was sized for `model`.
    pub(crate) fn check_model(&self, model: &Model) -> Result<(), JacobianError> {
        if model.nbodies() != self.nbodies() || model.nv() != self.nv {
            return Err(JacobianError::WorkspaceMismatch {
                workspace_bodies: self.nbodies(),
                workspace_nv: self.nv,
                model_bodies: model.nbodies(),
                model_nv: model.nv(),
            });
        }
        Ok(())
    }

    /// Validates model/workspace agreement and the state vectors.
    fn check_inputs(
        &self,
        model: &Model,
        data: &Data,
        q: &DVector<f64>,
        v: Option<&DVector<f64>>,
    ) -> Result<(), JacobianError> {
        self.check_model(model)?;
        check::data(model, data)?;
        check::configuration(model, q)?;
        if let Some(v) = v {
            check::vector("v", v, model.nv())?;
        }
        Ok(())
    }

    /// Pose, velocity and world columns of body `i` from the kinematics in `data`.
    fn store_body(
        &mut self,
        model: &Model,
        data: &Data,
        i: usize,
        q: &DVector<f64>,
        moving: bool,
        rates: Option<&DVector<f64>>,
    ) {
        let rot = data.world_rot[i];
        let pos = data.world_pos[i];
        self.rot[i] = rot;
        self.pos[i] = pos;
        let to_world = SpatialTransform::new(rot.transpose(), pos);
        let body = &model.bodies[i];
        let vel = data.vel[i];
        if moving {
            self.omega[i] = rot * vel.ang;
            self.pos_dot[i] = rot * vel.lin;
        } else {
            self.omega[i] = Vector3::zeros();
            self.pos_dot[i] = Vector3::zeros();
        }
        if let (Joint::Revolute(ax) | Joint::Rotor(ax), None) = (&body.joint, rates) {
            if ax.kind == SubspaceKind::Angular {
                self.col[self.offset[i]] = revolute_world_column(ax, &rot, &pos);
                return;
            }
        }
        let vel_world = match rates {
            Some(_) => to_world.inv_apply_motion(&vel),
            None => Motion::zero(),
        };
        for c in 0..body.v_set.len() {
            let k = self.offset[i] + c;
            let s = local_column(data, i, &body.joint, c);
            let sw = to_world.inv_apply_motion(&s);
            self.col[k] = sw;
            if let Some(v) = rates {
                let sdot = local_column_rate(model, data, i, (q, v), c);
                self.dcol[k] = cross_motion(&vel_world, &sw) + to_world.inv_apply_motion(&sdot);
            }
        }
    }
}

/// World column `[R a s; p x (R a s)]` of a revolute joint (axis `a`, scale `s`) of a body with
/// world rotation `R` and origin `p`: [`SpatialTransform::inv_apply_motion`] of `[a s; 0]`
/// without the zero linear part (one column of `R` for a coordinate axis).
#[inline]
fn revolute_world_column(ax: &JointAxis, rot: &Matrix3<f64>, pos: &Vector3<f64>) -> Motion {
    let ang = ax.axis.mat_mul(rot) * ax.scale;
    Motion::new(ang, pos.cross(&ang))
}

/// Column `c` of body `i`'s relative Jacobian `J_i` (2.35) in body coordinates.
pub(crate) use crate::kinematics::joint_column as local_column;

/// Time derivative of column `c` of `J_i` in body coordinates: zero except for the Euler-ZXZ
/// joint, whose angular block is `J_R(q)` with rate `Jdot_R` (2.42) and whose linear block
/// `R_q^T` rotates with the relative angular velocity `omega_rel = J_R qdot_R`.
fn local_column_rate(
    model: &Model,
    data: &Data,
    i: usize,
    (q, v): (&DVector<f64>, &DVector<f64>),
    c: usize,
) -> Motion {
    let body = &model.bodies[i];
    if !matches!(body.joint, Joint::EulerZxz) {
        return Motion::zero();
    }
    let vi = body.v_index;
    let m = &data.jacobian6[i];
    if c < 3 {
        let jr = m.fixed_view::<3, 3>(0, 3);
        let omega_rel = jr * Vector3::new(v[vi + 3], v[vi + 4], v[vi + 5]);
        let lin = Vector3::new(m[(3, c)], m[(4, c)], m[(5, c)]);
        Motion::new(Vector3::zeros(), -omega_rel.cross(&lin))
    } else {
        let angles = (q[body.q_index + 4], q[body.q_index + 5]);
        let jr_dot = euler_zxz_jr_rate(angles, v[vi + 4], v[vi + 5]);
        Motion::new(jr_dot.column(c - 3).into(), Vector3::zeros())
    }
}

/// `Jdot_R` of the Euler-ZXZ joint (2.42) for angles `(theta, psi)` and rates `thetadot`, `psidot`.
fn euler_zxz_jr_rate((theta, psi): (f64, f64), d2: f64, d3: f64) -> Matrix3<f64> {
    let (s2, c2) = theta.sin_cos();
    let (s3, c3) = psi.sin_cos();
    Matrix3::new(
        d2 * c2 * s3 + d3 * s2 * c3,
        -d3 * s3,
        0.0,
        d2 * c2 * c3 - d3 * s2 * s3,
        -d3 * c3,
        0.0,
        -d2 * s2,
        0.0,
        0.0,
    )
}

/// Spatial motion cross product `v x m = [w x a; w x l + u x a]` for `v = [w; u]`, `m = [a; l]`.
#[inline]
pub(crate) fn cross_motion(v: &Motion, m: &Motion) -> Motion {
    Motion::new(
        v.ang.cross(&m.ang),
        v.ang.cross(&m.lin) + v.lin.cross(&m.ang),
    )
}
