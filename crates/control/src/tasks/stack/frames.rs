//! Row writers of the frame tasks (position, orientation, relative position and orientation)
//! of a [`TaskStack`], from the kinematics of the last pass.

use super::{kin, TaskStack};
use crate::error::IkError;
use crate::ik::orientation::orientation_error;
use crate::tasks::rows::put_rows;
use crate::tasks::task::Frame;
use biped_dynamics::JacobianFrame;
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};

impl TaskStack {
    /// World rotation and origin of `frame` at the last kinematics pass.
    pub(super) fn frame_pose(&self, frame: &Frame) -> (Matrix3<f64>, Vector3<f64>) {
        let (rot, pos) = (
            self.data.world_rot[frame.body],
            self.data.world_pos[frame.body],
        );
        let off = &frame.offset;
        (
            rot * off.rotation.to_rotation_matrix().into_inner(),
            pos + rot * off.translation.vector,
        )
    }

    /// Angular rows (world-aligned `J_w`) of `frame`'s body into `j6` (`reference`: `j6r`).
    pub(super) fn angular(&mut self, frame: &Frame, reference: bool) -> Result<(), IkError> {
        let out = if reference {
            &mut self.j6r
        } else {
            &mut self.j6
        };
        let f = JacobianFrame::WorldAligned;
        self.jac.body_jacobian(frame.body, f, out).map_err(kin)
    }

    /// Rows of a position task at row `r`.
    pub(super) fn write_position(
        &mut self,
        frame: &Frame,
        target: &Vector3<f64>,
        r: usize,
        err: &mut DVector<f64>,
        out: &mut DMatrix<f64>,
    ) -> Result<(), IkError> {
        let t = frame.offset.translation.vector;
        self.jac
            .point_jacobian(frame.body, &t, &mut self.j3)
            .map_err(kin)?;
        put_rows(out, r, &Matrix3::identity(), &self.j3, 0, None, 0);
        let (_, p) = self.frame_pose(frame);
        err.fixed_rows_mut::<3>(r).copy_from(&(target - p));
        Ok(())
    }

    /// Rows of an orientation task at row `r`.
    pub(super) fn write_orientation(
        &mut self,
        frame: &Frame,
        target: &Matrix3<f64>,
        r: usize,
        err: &mut DVector<f64>,
        out: &mut DMatrix<f64>,
    ) -> Result<(), IkError> {
        self.angular(frame, false)?;
        put_rows(out, r, &Matrix3::identity(), &self.j6, 0, None, 0);
        let (a, _) = self.frame_pose(frame);
        err.fixed_rows_mut::<3>(r)
            .copy_from(&orientation_error(target, &a));
        Ok(())
    }

    /// Rows of a relative position task at row `r`: `A_r^T (J_p - J_p,r(p))`.
    pub(super) fn write_relative_position(
        &mut self,
        frame: &Frame,
        reference: &Frame,
        target: &Vector3<f64>,
        r: usize,
        err: &mut DVector<f64>,
        out: &mut DMatrix<f64>,
    ) -> Result<(), IkError> {
        let (ar, pr) = self.frame_pose(reference);
        let (_, p) = self.frame_pose(frame);
        let rb = self.data.world_rot[reference.body];
        // the point of the reference body that coincides with p, in its body coordinates
        let in_ref_body = rb.transpose() * (p - self.data.world_pos[reference.body]);
        let t = frame.offset.translation.vector;
        let jac = &self.jac;
        jac.point_jacobian(frame.body, &t, &mut self.j3)
            .map_err(kin)?;
        jac.point_jacobian(reference.body, &in_ref_body, &mut self.j3r)
            .map_err(kin)?;
        put_rows(out, r, &ar.transpose(), &self.j3, 0, Some(&self.j3r), 0);
        err.fixed_rows_mut::<3>(r)
            .copy_from(&(target - ar.transpose() * (p - pr)));
        Ok(())
    }

    /// Rows of a relative orientation task at row `r`: `A_r^T (J_w - J_w,r)`.
    pub(super) fn write_relative_orientation(
        &mut self,
        frame: &Frame,
        reference: &Frame,
        target: &Matrix3<f64>,
        r: usize,
        err: &mut DVector<f64>,
        out: &mut DMatrix<f64>,
    ) -> Result<(), IkError> {
        let (ar, _) = self.frame_pose(reference);
        let (a, _) = self.frame_pose(frame);
        self.angular(frame, false)?;
        self.angular(reference, true)?;
        put_rows(out, r, &ar.transpose(), &self.j6, 0, Some(&self.j6r), 0);
        let e = orientation_error(target, &(ar.transpose() * a));
        err.fixed_rows_mut::<3>(r).copy_from(&e);
        Ok(())
    }
}
