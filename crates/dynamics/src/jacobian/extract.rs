//! Body and point Jacobians (5.7) and their time derivatives, read from the world columns of
//! [`Jacobians`]: only the columns of the body's ancestors (its path to the root) are visited.

use super::columns::Jacobians;
use super::error::{shape, JacobianError};
use crate::spatial::Motion;
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};

/// Coordinates in which a body Jacobian `v_i = J v` expresses the body velocity `[omega; rdot]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum JacobianFrame {
    /// Body-fixed frame `k` of the body (the frame of (2.33)), linear part at the body origin.
    Body,
    /// World axes, linear part = velocity of the body origin (world-aligned at the origin).
    WorldAligned,
    /// World axes about the world origin (spatial velocity of the point at the world origin).
    World,
}

impl Jacobians {
    /// Calls `f(k, v_index)` for every column of body `body` and its ancestors (the non-zero
    /// columns), walking the path to the root.
    #[inline]
    fn for_chain(&self, body: usize, mut f: impl FnMut(usize, usize)) {
        let mut j = Some(body);
        while let Some(b) = j {
            for k in self.offset[b]..self.offset[b + 1] {
                f(k, self.index[k]);
            }
            j = self.parent[b];
        }
    }

    /// Errors unless `body` exists and the requested quantities are computed.
    fn ready(&self, body: usize, derivatives: bool) -> Result<(), JacobianError> {
        if body >= self.nbodies() {
            return Err(JacobianError::UnknownBody {
                body,
                nbodies: self.nbodies(),
            });
        }
        if !self.have_columns {
            return Err(JacobianError::NotComputed("Jacobian columns"));
        }
        if derivatives && !self.have_derivatives {
            return Err(JacobianError::NotComputed("Jacobian derivatives"));
        }
        Ok(())
    }

    /// World position of a point given in body `body`'s coordinates, and its world velocity.
    fn point_state(&self, body: usize, point: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        let r = self.rot[body] * point;
        (
            self.pos[body] + r,
            self.pos_dot[body] + self.omega[body].cross(&r),
        )
    }

    /// World pose `(A_Ik, r_O)` of body `body` at the state of the last `compute` call.
    pub fn body_pose(&self, body: usize) -> Option<(Matrix3<f64>, Vector3<f64>)> {
        Some((*self.rot.get(body)?, *self.pos.get(body)?))
    }

    /// Body Jacobian `J_i` (6 x nv, rows `[omega; rdot]`) with `v_i = J_i v` (2.33), in `frame`.
    pub fn body_jacobian(
        &self,
        body: usize,
        frame: JacobianFrame,
        out: &mut DMatrix<f64>,
    ) -> Result<(), JacobianError> {
        self.frame_jacobian(body, &Vector3::zeros(), frame, out)
    }

    /// Time derivative `Jdot_i` of [`Self::body_jacobian`]: `d/dt (J_i v) = J_i vdot + Jdot_i v`.
    ///
    /// For [`JacobianFrame::WorldAligned`] this is the conventional acceleration
    /// `[omegadot; rddot_O]` of (2.34) in world axes; for [`JacobianFrame::Body`] it is the rate
    /// of the body-coordinate components, `[omegadot; rddot_O - omega x rdot_O]` (body axes).
    pub fn body_jacobian_derivative(
        &self,
        body: usize,
        frame: JacobianFrame,
        out: &mut DMatrix<f64>,
    ) -> Result<(), JacobianError> {
        self.frame_jacobian_derivative(body, &Vector3::zeros(), frame, out)
    }

    /// Jacobian (6 x nv) of a frame fixed in body `body` with origin `point` (body
    /// coordinates) and the body's axes, e.g. a sole frame; the linear rows are the velocity of
    /// `point` ([`JacobianFrame::World`] does not depend on `point`).
    pub fn frame_jacobian(
        &self,
        body: usize,
        point: &Vector3<f64>,
        frame: JacobianFrame,
        out: &mut DMatrix<f64>,
    ) -> Result<(), JacobianError> {
        self.ready(body, false)?;
        finite_point(point)?;
        shape("out", out, 6, self.nv)?;
        out.as_mut_slice().fill(0.0);
        let rot_t = self.rot[body].transpose();
        let (p, _) = self.point_state(body, point);
        self.for_chain(body, |k, idx| {
            add_column6(out, idx, &in_frame(frame, &self.col[k], &rot_t, &p))
        });
        Ok(())
    }

    /// Time derivative of [`Self::frame_jacobian`] (see [`Self::body_jacobian_derivative`]).
    pub fn frame_jacobian_derivative(
        &self,
        body: usize,
        point: &Vector3<f64>,
        frame: JacobianFrame,
        out: &mut DMatrix<f64>,
    ) -> Result<(), JacobianError> {
        self.ready(body, true)?;
        finite_point(point)?;
        shape("out", out, 6, self.nv)?;
        out.as_mut_slice().fill(0.0);
        let rot_t = self.rot[body].transpose();
        let (p, p_dot) = self.point_state(body, point);
        let state = (&rot_t, &p, &self.omega[body], &p_dot);
        self.for_chain(body, |k, idx| {
            add_column6(
                out,
                idx,
                &rate_in_frame(frame, &self.col[k], &self.dcol[k], state),
            )
        });
        Ok(())
    }

    /// Point Jacobian `J_T^p = J_T^O + J_R x r_Op` (5.7): 3 x nv, world velocity of the point
    /// `point` (body coordinates) fixed in body `body`.
    pub fn point_jacobian(
        &self,
        body: usize,
        point: &Vector3<f64>,
        out: &mut DMatrix<f64>,
    ) -> Result<(), JacobianError> {
        self.ready(body, false)?;
        finite_point(point)?;
        shape("out", out, 3, self.nv)?;
        out.as_mut_slice().fill(0.0);
        let (p, _) = self.point_state(body, point);
        self.for_chain(body, |k, idx| {
            let c = &self.col[k];
            add_column3(out, idx, &(c.lin + c.ang.cross(&p)))
        });
        Ok(())
    }

    /// Time derivative of [`Self::point_jacobian`]: point acceleration `= J a + Jdot v`.
    pub fn point_jacobian_derivative(
        &self,
        body: usize,
        point: &Vector3<f64>,
        out: &mut DMatrix<f64>,
    ) -> Result<(), JacobianError> {
        self.ready(body, true)?;
        finite_point(point)?;
        shape("out", out, 3, self.nv)?;
        out.as_mut_slice().fill(0.0);
        let (p, p_dot) = self.point_state(body, point);
        self.for_chain(body, |k, idx| {
            let (c, d) = (&self.col[k], &self.dcol[k]);
            add_column3(out, idx, &(d.lin + d.ang.cross(&p) + c.ang.cross(&p_dot)))
        });
        Ok(())
    }

    /// Accumulates `J_T^p^T f` into `out` for a world vector `f` at a point fixed in `body`:
    /// the gradient term of (5.6)/(5.8) without forming the Jacobian.
    pub fn point_jacobian_tr_mul_add(
        &self,
        body: usize,
        point: &Vector3<f64>,
        f: &Vector3<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), JacobianError> {
        self.ready(body, false)?;
        finite_point(point)?;
        finite_point(f)?;
        if out.len() != self.nv {
            return Err(JacobianError::OutputShape {
                argument: "out",
                rows: self.nv,
                cols: 1,
                got_rows: out.len(),
                got_cols: 1,
            });
        }
        let (p, _) = self.point_state(body, point);
        let moment = p.cross(f);
        let out = out.as_mut_slice();
        self.for_chain(body, |k, idx| {
            let c = &self.col[k];
            out[idx] += c.lin.dot(f) + c.ang.dot(&moment);
        });
        Ok(())
    }
}

/// A world column (about the world origin) expressed in `frame` for a frame at `pos` whose
/// world rotation is `rot_t^T`.
#[inline]
fn in_frame(frame: JacobianFrame, c: &Motion, rot_t: &Matrix3<f64>, pos: &Vector3<f64>) -> Motion {
    match frame {
        JacobianFrame::World => *c,
        JacobianFrame::WorldAligned => Motion::new(c.ang, c.lin + c.ang.cross(pos)),
        JacobianFrame::Body => Motion::new(rot_t * c.ang, rot_t * (c.lin + c.ang.cross(pos))),
    }
}

/// Frame pose and velocity `(A_Ik^T, r_P, omega, rdot_P)`, vectors in world coordinates.
type BodyState<'a> = (
    &'a Matrix3<f64>,
    &'a Vector3<f64>,
    &'a Vector3<f64>,
    &'a Vector3<f64>,
);

/// Time derivative of [`in_frame`] for a column `c` with rate `d` at a moving frame.
#[inline]
fn rate_in_frame(frame: JacobianFrame, c: &Motion, d: &Motion, s: BodyState<'_>) -> Motion {
    let (rot_t, pos, omega, pos_dot) = s;
    if frame == JacobianFrame::World {
        return *d;
    }
    let lin = c.lin + c.ang.cross(pos);
    let lin_dot = d.lin + d.ang.cross(pos) + c.ang.cross(pos_dot);
    match frame {
        JacobianFrame::Body => Motion::new(
            rot_t * (d.ang - omega.cross(&c.ang)),
            rot_t * (lin_dot - omega.cross(&lin)),
        ),
        _ => Motion::new(d.ang, lin_dot),
    }
}

/// Adds a 6-D column `[ang; lin]` to column `idx` of a 6 x nv matrix.
#[inline]
fn add_column6(out: &mut DMatrix<f64>, idx: usize, m: &Motion) {
    let col = &mut out.as_mut_slice()[6 * idx..6 * idx + 6];
    for r in 0..3 {
        col[r] += m.ang[r];
        col[r + 3] += m.lin[r];
    }
}

/// Adds a 3-D column to column `idx` of a 3 x nv matrix.
#[inline]
fn add_column3(out: &mut DMatrix<f64>, idx: usize, v: &Vector3<f64>) {
    let col = &mut out.as_mut_slice()[3 * idx..3 * idx + 3];
    for r in 0..3 {
        col[r] += v[r];
    }
}

/// Errors on a non-finite point or vector argument.
#[inline]
fn finite_point(p: &Vector3<f64>) -> Result<(), JacobianError> {
    if p.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(JacobianError::NonFinitePoint)
    }
}
