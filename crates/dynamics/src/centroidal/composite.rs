//! Composite (subtree) inertias in world axes and the centroidal quantities built from them:
//! CoM Jacobian, `A_G`, `J_L` (7.2), `h_G = A_G v` and the bias `Adot_G v`.

use crate::jacobian::{shape, JacobianError, Jacobians};
use crate::kinematics::propagate_accelerations;
use crate::spatial::{CompositeInertia, Force, SpatialTransform};
use crate::{Data, Model};
use nalgebra::{DMatrix, DVector, Vector3};

/// Preallocated workspace and results of the centroidal computations for one model.
#[derive(Clone, Debug)]
pub struct Centroidal {
    jac: Jacobians,
    /// Subtree masses.
    sub_mass: Vec<f64>,
    /// Subtree first moments `sum m_k r_Ck` (world).
    sub_moment: Vec<Vector3<f64>>,
    /// Subtree inertias in world axes about the world origin.
    sub_inertia: Vec<CompositeInertia>,
    mass: f64,
    com: Vector3<f64>,
    com_velocity: Vector3<f64>,
    ag: DMatrix<f64>,
    momentum: Force,
    bias: Force,
    have_ag: bool,
    have_momentum: bool,
}

impl Centroidal {
    /// Workspace sized for `model`.
    pub fn new(model: &Model) -> Self {
        let n = model.nbodies();
        Self {
            jac: Jacobians::new(model),
            sub_mass: vec![0.0; n],
            sub_moment: vec![Vector3::zeros(); n],
            sub_inertia: vec![CompositeInertia::default(); n],
            mass: 0.0,
            com: Vector3::zeros(),
            com_velocity: Vector3::zeros(),
            ag: DMatrix::zeros(6, model.nv()),
            momentum: Force::zero(),
            bias: Force::zero(),
            have_ag: false,
            have_momentum: false,
        }
    }

    /// CoM Jacobian `J_C` (3 x nv, `rdot_C = J_C v`) at `q`: column of joint `j` is
    /// `(m_j l + a x h_j) / m` with the subtree mass `m_j` and first moment `h_j` of `j`.
    /// Also sets [`Self::mass`] and [`Self::com`]; runs the position kinematics into `data`.
    pub fn com_jacobian(
        &mut self,
        model: &Model,
        data: &mut Data,
        q: &DVector<f64>,
        out: &mut DMatrix<f64>,
    ) -> Result<(), JacobianError> {
        shape("out", out, 3, model.nv())?;
        self.have_ag = false;
        self.have_momentum = false;
        self.jac.fill(model, data, q, None, false)?;
        for (i, body) in model.bodies().iter().enumerate() {
            let inertia = body.inertia();
            let c = data.world_pos[i] + data.world_rot[i] * inertia.com();
            self.sub_mass[i] = inertia.mass();
            self.sub_moment[i] = c * inertia.mass();
        }
        self.mass = 0.0;
        let mut moment = Vector3::zeros();
        for i in (0..model.nbodies()).rev() {
            match model.bodies()[i].parent() {
                Some(p) => {
                    self.sub_mass[p] += self.sub_mass[i];
                    let h = self.sub_moment[i];
                    self.sub_moment[p] += h;
                }
                None => {
                    self.mass += self.sub_mass[i];
                    moment += self.sub_moment[i];
                }
            }
        }
        self.set_com(&moment)?;
        out.as_mut_slice().fill(0.0);
        let scale = 1.0 / self.mass;
        for i in 0..model.nbodies() {
            for k in self.jac.offset[i]..self.jac.offset[i + 1] {
                let s = &self.jac.col[k];
                let lin = (s.lin * self.sub_mass[i] + s.ang.cross(&self.sub_moment[i])) * scale;
                let idx = self.jac.index[k];
                let col = &mut out.as_mut_slice()[3 * idx..3 * idx + 3];
                for r in 0..3 {
                    col[r] += lin[r];
                }
            }
        }
        Ok(())
    }

    /// Full centroidal computation at `(q, v)`: CoM and its velocity, `A_G` (so `h_G = A_G v`,
    /// rows `[J_L; m J_C]`), the momentum `h_G = [L_G; p]` (7.1)-(7.2) and the bias
    /// `Adot_G v` (the momentum rate at zero acceleration). Runs the kinematics into `data`.
    pub fn compute(
        &mut self,
        model: &Model,
        data: &mut Data,
        q: &DVector<f64>,
        v: &DVector<f64>,
    ) -> Result<(), JacobianError> {
        self.have_ag = false;
        self.have_momentum = false;
        self.jac.fill(model, data, q, Some(v), false)?;
        self.assemble(model, data)?;
        self.momentum = self.ag_times(v);
        self.com_velocity = self.momentum.lin / self.mass;
        propagate_accelerations(model, data, None);
        self.bias = shift_to(&momentum_rate(model, data), &self.com);
        self.have_momentum = true;
        Ok(())
    }

    /// Position-only computation at `q`: CoM and `A_G` (hence `J_L`), without momentum and
    /// bias (cheaper, e.g. for inverse kinematics). Runs the position kinematics into `data`.
    pub fn compute_matrix(
        &mut self,
        model: &Model,
        data: &mut Data,
        q: &DVector<f64>,
    ) -> Result<(), JacobianError> {
        self.have_ag = false;
        self.have_momentum = false;
        self.jac.fill(model, data, q, None, false)?;
        self.assemble(model, data)
    }

    /// Same as [`Self::compute_matrix`] but reuses the kinematics of a preceding
    /// [`Jacobians::compute`] (or its derivative variant) at the same `q`: `data` must hold
    /// the body poses of that call, `jac` its world columns. Saves the second FK pass.
    pub fn compute_matrix_with(
        &mut self,
        model: &Model,
        data: &Data,
        jac: &Jacobians,
    ) -> Result<(), JacobianError> {
        self.have_ag = false;
        self.have_momentum = false;
        jac.check_model(model)?;
        crate::check::data(model, data)?;
        if !jac.have_columns {
            return Err(JacobianError::NotComputed("Jacobian columns"));
        }
        self.assemble_from(model, data, Some(jac))
    }

    /// Composite inertias, total mass, CoM and `A_G` from the poses and own columns.
    fn assemble(&mut self, model: &Model, data: &Data) -> Result<(), JacobianError> {
        self.assemble_from(model, data, None)
    }

    /// [`Self::assemble`] with the world columns of `jac` (own columns if `None`).
    fn assemble_from(
        &mut self,
        model: &Model,
        data: &Data,
        jac: Option<&Jacobians>,
    ) -> Result<(), JacobianError> {
        self.composite_inertias(model, data);
        let mut total = CompositeInertia::default();
        for (i, body) in model.bodies().iter().enumerate() {
            if body.parent().is_none() {
                total += self.sub_inertia[i];
            }
        }
        self.mass = total.mass;
        self.set_com(&total.h)?;
        fill_ag(
            &mut self.ag,
            &self.sub_inertia,
            &self.com,
            jac.unwrap_or(&self.jac),
            model,
        );
        self.have_ag = true;
        Ok(())
    }

    /// Total mass from the last computation.
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// Centre of mass (world) from the last computation.
    pub fn com(&self) -> Vector3<f64> {
        self.com
    }

    /// CoM velocity `p / m` from the last [`Self::compute`].
    pub fn com_velocity(&self) -> Result<Vector3<f64>, JacobianError> {
        self.ready_momentum()?;
        Ok(self.com_velocity)
    }

    /// Centroidal momentum matrix `A_G` (6 x nv, `h_G = A_G v`) from the last computation.
    pub fn ag(&self) -> Result<&DMatrix<f64>, JacobianError> {
        self.ready()?;
        Ok(&self.ag)
    }

    /// Angular momentum Jacobian `J_L` (7.2): the top three rows of `A_G`, copied into `out`.
    pub fn angular_momentum_jacobian(&self, out: &mut DMatrix<f64>) -> Result<(), JacobianError> {
        self.ready()?;
        shape("out", out, 3, self.ag.ncols())?;
        let src = self.ag.as_slice().chunks_exact(6);
        for (dst, col) in out.as_mut_slice().chunks_exact_mut(3).zip(src) {
            dst.copy_from_slice(&col[..3]);
        }
        Ok(())
    }

    /// Centroidal momentum `h_G = [L_G; p]` (7.1) from the last [`Self::compute`].
    pub fn momentum(&self) -> Result<Force, JacobianError> {
        self.ready_momentum()?;
        Ok(self.momentum)
    }

    /// Bias `Adot_G v`: `d h_G / dt = A_G vdot + Adot_G v`, from the last [`Self::compute`].
    pub fn ag_bias(&self) -> Result<Force, JacobianError> {
        self.ready_momentum()?;
        Ok(self.bias)
    }

    /// Errors unless [`Self::compute`] has succeeded (momentum and bias).
    fn ready_momentum(&self) -> Result<(), JacobianError> {
        if self.have_momentum {
            Ok(())
        } else {
            Err(JacobianError::NotComputed("centroidal momentum"))
        }
    }

    /// Errors unless [`Self::compute`] or [`Self::compute_matrix`] has succeeded.
    fn ready(&self) -> Result<(), JacobianError> {
        if self.have_ag {
            Ok(())
        } else {
            Err(JacobianError::NotComputed("centroidal momentum matrix"))
        }
    }

    /// CoM from the total first moment; errors on a massless model.
    fn set_com(&mut self, moment: &Vector3<f64>) -> Result<(), JacobianError> {
        if self.mass.is_nan() || self.mass <= 0.0 {
            return Err(JacobianError::ZeroMass);
        }
        self.com = moment / self.mass;
        Ok(())
    }

    /// Subtree inertias in world axes about the world origin (leaves to root).
    fn composite_inertias(&mut self, model: &Model, data: &Data) {
        for (i, body) in model.bodies().iter().enumerate() {
            self.sub_inertia[i] =
                CompositeInertia::from_body(body.inertia(), &data.world_rot[i], &data.world_pos[i]);
        }
        for i in (0..model.nbodies()).rev() {
            if let Some(p) = model.bodies()[i].parent() {
                let (head, tail) = self.sub_inertia.split_at_mut(i);
                head[p] += tail[0];
            }
        }
    }

    /// `A_G v` as a force-like 6-vector.
    fn ag_times(&self, v: &DVector<f64>) -> Force {
        let mut h = [0.0; 6];
        for (col, vj) in self.ag.as_slice().chunks_exact(6).zip(v.iter()) {
            for r in 0..6 {
                h[r] += col[r] * vj;
            }
        }
        Force::new(
            Vector3::new(h[0], h[1], h[2]),
            Vector3::new(h[3], h[4], h[5]),
        )
    }
}

/// A momentum (or wrench) about the world origin re-expressed about point `c`.
#[inline]
fn shift_to(f: &Force, c: &Vector3<f64>) -> Force {
    Force::new(f.ang - c.cross(&f.lin), f.lin)
}

/// Rate of the total momentum about the world origin for the accelerations in `data.acc`:
/// `sum_i C_i^T (M_i a_i + h_i)` with the Newton-Euler body wrench of (2.56).
fn momentum_rate(model: &Model, data: &Data) -> Force {
    let mut total = Force::zero();
    for (i, body) in model.bodies().iter().enumerate() {
        let inertia = body.inertia();
        let f = inertia.apply(&data.acc[i]) + inertia.bias_force(&data.vel[i].ang);
        let to_world = SpatialTransform::new(data.world_rot[i].transpose(), data.world_pos[i]);
        total += to_world.tr_apply_force(&f);
    }
    total
}

/// `A_G`: every world column of `jac` times its subtree inertia, shifted to the CoM `com`.
fn fill_ag(
    ag: &mut DMatrix<f64>,
    sub_inertia: &[CompositeInertia],
    com: &Vector3<f64>,
    jac: &Jacobians,
    model: &Model,
) {
    ag.as_mut_slice().fill(0.0);
    for (i, inertia) in sub_inertia.iter().enumerate().take(model.nbodies()) {
        for k in jac.offset[i]..jac.offset[i + 1] {
            let f = shift_to(&inertia.apply(&jac.col[k]), com);
            let idx = jac.index[k];
            let col = &mut ag.as_mut_slice()[6 * idx..6 * idx + 6];
            for r in 0..3 {
                col[r] += f.ang[r];
                col[r + 3] += f.lin[r];
            }
        }
    }
}
