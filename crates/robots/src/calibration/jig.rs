//! Jig-closure constraints: the known relative pose of two robot frames in a calibration jig
//! (thesis 3.5, Fig. 3.5-3.6) and its residual with analytic Jacobian.

use super::CalibrationError;
use biped_dynamics::{JacobianFrame, Jacobians};
use nalgebra::{DMatrix, Isometry3, Matrix3, Rotation3, Vector3};

/// A frame fixed in a body: body index and the frame's pose in the body frame.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyFrame {
    /// Body the frame is fixed in (`None`: the world / a link welded to it).
    pub body: Option<usize>,
    /// Pose of the frame in the body frame (world frame if `body` is `None`).
    pub pose: Isometry3<f64>,
}

/// Which parts of the relative pose the jig fixes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Components {
    /// Position and orientation (6 residual rows).
    #[default]
    Pose,
    /// Position of frame b's origin in frame a only (3 rows), e.g. a pin in a hole.
    Position,
}

impl Components {
    /// Number of residual rows.
    pub fn rows(self) -> usize {
        match self {
            Components::Pose => 6,
            Components::Position => 3,
        }
    }
}

/// A jig constraint: frame `b` must sit at `target` relative to frame `a`.
#[derive(Debug, Clone, PartialEq)]
pub struct JigConstraint {
    /// Constraint name (for reports).
    pub name: String,
    /// Reference frame.
    pub a: BodyFrame,
    /// Constrained frame.
    pub b: BodyFrame,
    /// Constrained components.
    pub components: Components,
    /// Weight of the position rows \[1/m].
    pub position_weight: f64,
    /// Weight of the orientation rows \[1/rad].
    pub orientation_weight: f64,
}

/// Unweighted closure error of one constraint: position \[m] and orientation angle \[rad].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosureError {
    /// Position error `R_a^T (p_b - p_a) - p_target` (frame-a axes) \[m].
    pub position: Vector3<f64>,
    /// Orientation error `log(R_target^T R_a^T R_b)` (angle-axis, Appendix C) \[rad].
    pub orientation: Vector3<f64>,
}

/// World pose `(R, p)` of a body frame from computed Jacobians.
pub(crate) fn world_frame(
    jac: &Jacobians,
    f: &BodyFrame,
) -> Result<(Matrix3<f64>, Vector3<f64>), CalibrationError> {
    let Some(body) = f.body else {
        let r = f.pose.rotation.to_rotation_matrix();
        return Ok((*r.matrix(), f.pose.translation.vector));
    };
    let (rot, pos) = jac
        .body_pose(body)
        .ok_or_else(|| CalibrationError::Invalid(format!("body index {body} out of range")))?;
    let r = rot * f.pose.rotation.to_rotation_matrix().matrix();
    Ok((r, pos + rot * f.pose.translation.vector))
}

/// Logarithm of a rotation matrix as a rotation vector (angle-axis, Appendix C), accurate
/// near zero (`atan2`, no `acos`) and near pi (axis from the symmetric part).
pub fn so3_log(r: &Matrix3<f64>) -> Vector3<f64> {
    let v = 0.5
        * Vector3::new(
            r[(2, 1)] - r[(1, 2)],
            r[(0, 2)] - r[(2, 0)],
            r[(1, 0)] - r[(0, 1)],
        );
    let c = 0.5 * (r.trace() - 1.0);
    let s = v.norm();
    let theta = s.atan2(c);
    if c > -0.9 {
        let f = if s < 1e-8 {
            1.0 + theta * theta / 6.0
        } else {
            theta / s
        };
        return v * f;
    }
    // Near pi: R + I - ... = 2 cos^2 terms; take the axis from the largest column of R + R^T
    // - (tr - 1) I = 2 (1 - c) u u^T, signed by the skew part.
    let b = r + r.transpose() - (r.trace() - 1.0) * Matrix3::identity();
    let k = (0..3)
        .max_by(|&i, &j| b[(i, i)].total_cmp(&b[(j, j)]))
        .unwrap_or(0);
    let mut u = b.column(k).into_owned();
    u /= u.norm().max(1e-300);
    if u.dot(&v) < 0.0 {
        u = -u;
    }
    u * theta
}

/// Inverse right Jacobian of SO(3) at `phi`: `d log(R exp(w)) / dw` at `w = 0`.
pub fn so3_right_jacobian_inv(phi: &Vector3<f64>) -> Matrix3<f64> {
    let theta = phi.norm();
    let k = biped_dynamics::spatial::skew(phi);
    let c = if theta < 1e-4 {
        1.0 / 12.0 + theta * theta / 720.0
    } else {
        1.0 / (theta * theta) - (1.0 + theta.cos()) / (2.0 * theta * theta.sin())
    };
    Matrix3::identity() + 0.5 * k + c * k * k
}

/// World-aligned 6 x nv Jacobian of a body frame (zero for a world-fixed frame).
fn frame_jacobian(
    jac: &Jacobians,
    f: &BodyFrame,
    out: &mut DMatrix<f64>,
) -> Result<(), CalibrationError> {
    match f.body {
        Some(b) => {
            let p = f.pose.translation.vector;
            jac.frame_jacobian(b, &p, JacobianFrame::WorldAligned, out)?
        }
        None => out.fill(0.0),
    }
    Ok(())
}

impl JigConstraint {
    /// Pose of frame `b` in frame `a` at the kinematic state held by `jac`.
    pub fn relative_pose(&self, jac: &Jacobians) -> Result<Isometry3<f64>, CalibrationError> {
        let (ra, pa) = world_frame(jac, &self.a)?;
        let (rb, pb) = world_frame(jac, &self.b)?;
        let rot = Rotation3::from_matrix_unchecked(ra.transpose() * rb);
        Ok(Isometry3::from_parts(
            (ra.transpose() * (pb - pa)).into(),
            nalgebra::UnitQuaternion::from_rotation_matrix(&rot),
        ))
    }

    /// Closure error at the kinematic state held by `jac`, relative to `target`.
    pub fn error(
        &self,
        jac: &Jacobians,
        target: &Isometry3<f64>,
    ) -> Result<ClosureError, CalibrationError> {
        let (ra, pa) = world_frame(jac, &self.a)?;
        let (rb, pb) = world_frame(jac, &self.b)?;
        let position = ra.transpose() * (pb - pa) - target.translation.vector;
        let rt = target.rotation.to_rotation_matrix();
        let e = rt.matrix().transpose() * ra.transpose() * rb;
        let orientation = so3_log(&e);
        Ok(ClosureError {
            position,
            orientation,
        })
    }

    /// Weighted residual rows into `r` and their Jacobian w.r.t. all velocity coordinates into
    /// `jr` (rows x nv); `ja`, `jb` are 6 x nv scratch matrices.
    pub fn residual(
        &self,
        jac: &Jacobians,
        target: &Isometry3<f64>,
        r: &mut [f64],
        jr: &mut DMatrix<f64>,
        scratch: (&mut DMatrix<f64>, &mut DMatrix<f64>),
    ) -> Result<ClosureError, CalibrationError> {
        let (ja, jb) = scratch;
        let err = self.error(jac, target)?;
        let (ra, pa) = world_frame(jac, &self.a)?;
        let (rb, pb) = world_frame(jac, &self.b)?;
        frame_jacobian(jac, &self.a, ja)?;
        frame_jacobian(jac, &self.b, jb)?;
        let rat = ra.transpose();
        // d/dt R_a^T d = R_a^T (d_dot + d x omega_a), d = p_b - p_a.
        let sd = biped_dynamics::spatial::skew(&(pb - pa));
        let jp =
            rat * ((jb.fixed_rows::<3>(3) - ja.fixed_rows::<3>(3)) + sd * ja.fixed_rows::<3>(0));
        let wp = self.position_weight;
        for (ri, e) in r.iter_mut().zip(err.position.iter()) {
            *ri = wp * e;
        }
        jr.rows_mut(0, 3).copy_from(&(jp * wp));
        if self.components == Components::Pose {
            // d log(E) = Jr^-1(phi) R_b^T (omega_b - omega_a).
            let m = so3_right_jacobian_inv(&err.orientation) * rb.transpose();
            let jo = m * (jb.fixed_rows::<3>(0) - ja.fixed_rows::<3>(0));
            let wo = self.orientation_weight;
            for (ri, e) in r[3..].iter_mut().zip(err.orientation.iter()) {
                *ri = wo * e;
            }
            jr.rows_mut(3, 3).copy_from(&(jo * wo));
        }
        Ok(err)
    }
}
