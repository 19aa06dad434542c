//! Inertia and transmission queries of the plant for gain scheduling and command mapping:
//! the inertias an actuator sees (free, stance), the steady-state transmission matrix from
//! motor torques to joint torques, and the Type 3 gear dampers.

use super::{Plant, PlantConfig};
use crate::error::SimError;
use biped_dynamics::ElasticGear;
use biped_dynamics::{Data, Model};
use nalgebra::DVector;

/// Inertias seen by one actuator \[kg m^2 or kg], for gain scheduling.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ActuatorInertia {
    /// Mass-matrix diagonal at the joint coordinate: the subtree plus reflected rotor inertia
    /// (Type 3: plus `N^2` times the motor's diagonal).
    pub sub: f64,
    /// Rigid inertia of all other bodies about the joint axis if the subtree holds a foot
    /// (what a stance joint moves, e.g. an ankle carrying the body), else 0. A part of a foot
    /// (a toe) does not count: a toe joint carries the body only in toe-off, where a walking
    /// controller's feedforward holds the load, and scheduled for the toe's own inertia it
    /// yields to the ground instead of levering the robot up
    /// ([`crate::contact::ContactSet::side_bodies`]).
    pub rest: f64,
    /// Inertia the actuator drives when everything else moves freely too, `1 / (M^-1)_jj`
    /// (at most `sub`; the decentralised PD's stability cap); for elastic gears the motor
    /// coordinate's, times `N^2`.
    pub free: f64,
}

impl Plant {
    /// Transmission matrix `A` at `q`: joint torque of actuator `j` = `sum_k A[j][k] tau_m,k`
    /// (steady state), from the motor rows (`N` for rigid and elastic gears, the screw
    /// Jacobians for knee and ankles, 1 for direct joints).
    pub fn transmission_matrix(
        &self,
        q: &DVector<f64>,
    ) -> Result<nalgebra::DMatrix<f64>, SimError> {
        let n = self.actuators.len();
        let mut a = nalgebra::DMatrix::zeros(n, n);
        for (k, act) in self.actuators.iter().enumerate() {
            match (act.transmission, act.motor_row(&self.model, q.as_slice())?) {
                (crate::drive::Transmission::Elastic { ratio, .. }, _) => a[(k, k)] = ratio,
                (_, None) => a[(k, k)] = 1.0,
                (_, Some(row)) => {
                    for (v, c) in row.entries() {
                        if let Some(j) = self.actuators.iter().position(|x| x.joint_v == v) {
                            a[(j, k)] = c;
                        }
                    }
                }
            }
        }
        Ok(a)
    }

    /// Why `m` has no Cholesky factor: the actuated joint of the first pivot that vanishes (in
    /// coordinate order), i.e. a joint whose motion moves no inertia beyond its ancestors'
    /// (e.g. a URDF joint to massless or point-mass links without rotor inertia).
    fn singular_mass_matrix(&self, m: &nalgebra::DMatrix<f64>) -> SimError {
        let reason = match first_vanishing_pivot(m)
            .and_then(|v| self.actuators.iter().find(|a| a.joint_v == v))
        {
            Some(a) => format!(
                "not positive definite: joint `{}` moves no inertia of its own (massless or \
                 point-mass links); give its drive a rotor inertia (armature)",
                a.name
            ),
            None => "not positive definite".into(),
        };
        SimError::InvalidParameter {
            what: "mass matrix".into(),
            reason,
        }
    }

    /// `M(q)` and its inverse; a singular `M` names the joint of its first vanishing pivot.
    fn mass_matrix_and_inverse(
        &mut self,
        q: &DVector<f64>,
    ) -> Result<(nalgebra::DMatrix<f64>, nalgebra::DMatrix<f64>), SimError> {
        let m = biped_dynamics::mass_matrix(&self.model, &mut self.data, q)?.clone();
        let minv = m
            .clone()
            .cholesky()
            .map(|c| c.inverse())
            .ok_or_else(|| self.singular_mass_matrix(&m))?;
        Ok((m, minv))
    }

    /// Free inertia `1 / (M^-1)_jj` of every coordinate `j` at `q` (what it moves when all
    /// others move freely too), indexed by `v`.
    pub fn free_inertias(&mut self, q: &DVector<f64>) -> Result<Vec<f64>, SimError> {
        let (_, minv) = self.mass_matrix_and_inverse(q)?;
        Ok(minv.diagonal().iter().map(|d| 1.0 / d).collect())
    }

    /// Inertias seen by each actuator at `q` (see [`ActuatorInertia`]).
    pub fn actuator_inertias(
        &mut self,
        q: &DVector<f64>,
    ) -> Result<Vec<ActuatorInertia>, SimError> {
        let (m, minv) = self.mass_matrix_and_inverse(q)?;
        let mut out = Vec::with_capacity(self.actuators.len());
        for a in &self.actuators {
            let link = m[(a.joint_v, a.joint_v)];
            let (sub, free) = match a.transmission {
                crate::drive::Transmission::Elastic { motor_v, ratio, .. } => {
                    let motor = ratio * ratio * m[(motor_v, motor_v)];
                    (link + motor, ratio * ratio / minv[(motor_v, motor_v)])
                }
                _ => (link, 1.0 / minv[(a.joint_v, a.joint_v)]),
            };
            out.push(ActuatorInertia {
                sub,
                rest: self.rest_inertia(a.joint_v),
                free,
            });
        }
        Ok(out)
    }

    /// Rigid inertia about the axis of the one-DoF joint owning `v` of every body outside its
    /// subtree, if the subtree holds a foot (else 0: nothing can hold it; see
    /// [`ActuatorInertia::rest`]); world poses from the last kinematics pass.
    fn rest_inertia(&self, v: usize) -> f64 {
        let bodies = self.model.bodies();
        let Some(j) = bodies
            .iter()
            .position(|b| b.owns_coordinates() && b.v_index() == v && b.joint().nv() == 1)
        else {
            return 0.0;
        };
        let axis = match bodies[j].joint() {
            biped_dynamics::JointModel::Revolute { axis } => {
                self.data.world_rot[j] * axis.into_inner()
            }
            _ => return 0.0,
        };
        let p = self.data.world_pos[j];
        let in_subtree = |mut i: usize| loop {
            if i == j {
                return true;
            }
            match bodies[i].parent() {
                Some(par) => i = par,
                None => return false,
            }
        };
        if !self.contact.side_bodies().any(in_subtree) {
            return 0.0;
        }
        (0..bodies.len())
            .filter(|&i| !in_subtree(i))
            .map(|i| {
                let (r, inertia) = (self.data.world_rot[i], bodies[i].inertia());
                let c = self.data.world_pos[i] + r * inertia.com() - p;
                let a_body = r.transpose() * axis;
                a_body.dot(&(inertia.inertia_about_com() * a_body))
                    + inertia.mass() * axis.cross(&c).norm_squared()
            })
            .sum()
    }
}

/// Gear dampers `2 zeta sqrt(k J)` with the reduced inertia of link and motor at neutral.
pub(super) fn gear_dampers(
    model: &Model,
    data: &mut Data,
    gears: &[ElasticGear],
    c: &PlantConfig,
) -> Result<Vec<f64>, SimError> {
    if gears.is_empty() {
        return Ok(Vec::new());
    }
    let m = biped_dynamics::mass_matrix(model, data, &model.neutral())?;
    Ok(gears
        .iter()
        .map(|g| {
            let (jl, jm) = (
                m[(g.link_v, g.link_v)],
                g.ratio * g.ratio * m[(g.motor_v, g.motor_v)],
            );
            let j = jl * jm / (jl + jm);
            2.0 * c.gear_damping_ratio * (c.gear_stiffness * j).sqrt()
        })
        .collect())
}

/// Index of the first pivot of the Cholesky factorisation of `m` that is not positive (relative
/// to the largest diagonal entry), `None` if every pivot is.
fn first_vanishing_pivot(m: &nalgebra::DMatrix<f64>) -> Option<usize> {
    let n = m.nrows();
    let tol = 1e-12 * m.diagonal().amax();
    let mut l = nalgebra::DMatrix::<f64>::zeros(n, n);
    for k in 0..n {
        let d = m[(k, k)] - (0..k).map(|j| l[(k, j)] * l[(k, j)]).sum::<f64>();
        if d.is_nan() || d <= tol {
            return Some(k);
        }
        l[(k, k)] = d.sqrt();
        for i in k + 1..n {
            let s = m[(i, k)] - (0..k).map(|j| l[(i, j)] * l[(k, j)]).sum::<f64>();
            l[(i, k)] = s / l[(k, k)];
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::first_vanishing_pivot;
    use nalgebra::DMatrix;

    #[test]
    fn vanishing_pivot_is_found_in_coordinate_order() {
        let good = DMatrix::from_row_slice(3, 3, &[4.0, 1.0, 0.0, 1.0, 3.0, 1.0, 0.0, 1.0, 2.0]);
        assert_eq!(first_vanishing_pivot(&good), None);
        // Coordinate 2 moves exactly what coordinate 0 moves: its pivot vanishes.
        let b = DMatrix::from_row_slice(3, 2, &[1.0, 0.0, 0.0, 1.0, 1.0, 0.0]);
        let singular = &b * b.transpose();
        assert_eq!(first_vanishing_pivot(&singular), Some(2));
        let zero_row = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, 0.0]);
        assert_eq!(first_vanishing_pivot(&zero_row), Some(1));
    }
}
