//! Per-state computations behind the `Model` methods: each reads its arguments from a
//! [`Work`] and writes one state's result, row-major, into a flat slice. They only call the
//! library (`biped_dynamics`); nothing here is an algorithm of its own.

use biped_dynamics::{
    center_of_mass, centroidal_momentum, forward_dynamics, inverse_dynamics, mass_matrix,
    update_placements, Algorithm, Centroidal, Data, JacobianFrame, Jacobians, Model, Wrench,
};
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};

/// One thread's workspace: the library's preallocated data plus the current arguments.
pub struct Work {
    data: Data,
    jac: Jacobians,
    cen: Centroidal,
    /// Current state's arguments, in the order the method declared them.
    args: Vec<DVector<f64>>,
    fext: Vec<Wrench>,
    mat: DMatrix<f64>,
}

impl Work {
    /// Workspace for `model`.
    pub fn new(model: &Model) -> Self {
        Self {
            data: Data::new(model),
            jac: Jacobians::new(model),
            cen: Centroidal::new(model),
            args: Vec::new(),
            fext: Vec::new(),
            mat: DMatrix::zeros(0, 0),
        }
    }

    /// Copies one state's arguments in.
    pub fn load<'a>(&mut self, state: impl Iterator<Item = &'a [f64]>) {
        let mut k = 0;
        for values in state {
            if k == self.args.len() {
                self.args.push(DVector::zeros(0));
            }
            let arg = &mut self.args[k];
            if arg.len() != values.len() {
                *arg = DVector::zeros(values.len());
            }
            arg.as_mut_slice().copy_from_slice(values);
            k += 1;
        }
        self.args.truncate(k);
    }

    /// External wrenches from argument `k` (rows `[torque; force]` per body), if given.
    fn wrenches(&mut self, k: usize) -> Option<&[Wrench]> {
        let flat = self.args.get(k)?;
        self.fext.clear();
        for row in flat.as_slice().chunks_exact(6) {
            let (t, f) = (
                Vector3::from_column_slice(&row[..3]),
                Vector3::from_column_slice(&row[3..]),
            );
            self.fext.push(Wrench::new(t, f));
        }
        Some(&self.fext)
    }
}

/// Result type of a kernel: the library's message on failure.
pub type KernelResult = Result<(), String>;

/// `mat`, reallocated as zeros if it is not `rows x cols`.
fn sized(mat: &mut DMatrix<f64>, rows: usize, cols: usize) -> &mut DMatrix<f64> {
    if mat.shape() != (rows, cols) {
        *mat = DMatrix::zeros(rows, cols);
    }
    mat
}

/// Writes `m` row by row into `out`.
fn write_rows(m: &DMatrix<f64>, out: &mut [f64]) {
    let cols = m.ncols();
    for (r, row) in m.row_iter().enumerate() {
        for (c, x) in row.iter().enumerate() {
            out[r * cols + c] = *x;
        }
    }
}

/// Writes the 4x4 homogeneous transform of `(rot, pos)` into `out`.
fn write_pose(rot: &Matrix3<f64>, pos: &Vector3<f64>, out: &mut [f64]) {
    for r in 0..3 {
        for c in 0..3 {
            out[4 * r + c] = rot[(r, c)];
        }
        out[4 * r + 3] = pos[r];
    }
    out[12..16].copy_from_slice(&[0.0, 0.0, 0.0, 1.0]);
}

/// `qdd` from `(q, v, tau[, fext])`.
pub fn forward(model: &Model, w: &mut Work, algo: Algorithm, out: &mut [f64]) -> KernelResult {
    w.wrenches(3);
    let fext = (w.args.len() > 3).then_some(w.fext.as_slice());
    let (q, v, tau) = (&w.args[0], &w.args[1], &w.args[2]);
    let qdd = forward_dynamics(model, &mut w.data, q, v, tau, fext, algo);
    out.copy_from_slice(qdd.map_err(|e| e.to_string())?.as_slice());
    Ok(())
}

/// `tau` from `(q, v, a[, fext])` (RNEA).
pub fn inverse(model: &Model, w: &mut Work, out: &mut [f64]) -> KernelResult {
    w.wrenches(3);
    let fext = (w.args.len() > 3).then_some(w.fext.as_slice());
    let (q, v, a) = (&w.args[0], &w.args[1], &w.args[2]);
    let tau = inverse_dynamics(model, &mut w.data, q, v, a, fext);
    out.copy_from_slice(tau.map_err(|e| e.to_string())?.as_slice());
    Ok(())
}

/// `M(q)` (CRBA).
pub fn mass(model: &Model, w: &mut Work, out: &mut [f64]) -> KernelResult {
    let m = mass_matrix(model, &mut w.data, &w.args[0]).map_err(|e| e.to_string())?;
    write_rows(m, out);
    Ok(())
}

/// World pose (4x4) of the frame at `point` (body coordinates) on body `body`.
pub fn pose(
    model: &Model,
    w: &mut Work,
    body: usize,
    point: &Vector3<f64>,
    out: &mut [f64],
) -> KernelResult {
    update_placements(model, &mut w.data, &w.args[0]).map_err(|e| e.to_string())?;
    let rot = &w.data.world_rot[body];
    write_pose(rot, &(w.data.world_pos[body] + rot * point), out);
    Ok(())
}

/// World poses (4x4) of all bodies.
pub fn all_poses(model: &Model, w: &mut Work, out: &mut [f64]) -> KernelResult {
    update_placements(model, &mut w.data, &w.args[0]).map_err(|e| e.to_string())?;
    for (i, slot) in out.chunks_exact_mut(16).enumerate() {
        write_pose(&w.data.world_rot[i], &w.data.world_pos[i], slot);
    }
    Ok(())
}

/// Frame Jacobian (6 x nv, rows `[omega; velocity]`) of the frame at `point` on `body`.
pub fn jacobian(
    model: &Model,
    w: &mut Work,
    (body, point, frame): (usize, &Vector3<f64>, JacobianFrame),
    out: &mut [f64],
) -> KernelResult {
    w.jac
        .compute(model, &mut w.data, &w.args[0])
        .map_err(|e| e.to_string())?;
    let nv = model.nv();
    let mat = sized(&mut w.mat, 6, nv);
    w.jac
        .frame_jacobian(body, point, frame, mat)
        .map_err(|e| e.to_string())?;
    write_rows(mat, out);
    Ok(())
}

/// Centre of mass (world).
pub fn com(model: &Model, w: &mut Work, out: &mut [f64]) -> KernelResult {
    let c = center_of_mass(model, &mut w.data, &w.args[0], None).map_err(|e| e.to_string())?;
    out.copy_from_slice(c.position.as_slice());
    Ok(())
}

/// Centroidal momentum `h_G = [L_G; p]` (world axes, about the CoM).
pub fn momentum(model: &Model, w: &mut Work, out: &mut [f64]) -> KernelResult {
    let (q, v) = (&w.args[0], &w.args[1]);
    let h = centroidal_momentum(model, &mut w.data, q, v).map_err(|e| e.to_string())?;
    out[..3].copy_from_slice(h.momentum.ang.as_slice());
    out[3..].copy_from_slice(h.momentum.lin.as_slice());
    Ok(())
}

/// Which centroidal matrix [`centroidal`] writes.
#[derive(Clone, Copy)]
pub enum CentroidalMatrix {
    /// `A_G` (6 x nv).
    Full,
    /// `J_L`, the angular rows of `A_G` (3 x nv).
    Angular,
    /// CoM Jacobian `J_C` (3 x nv).
    Com,
}

/// `A_G`, `J_L` or `J_C` at `q`.
pub fn centroidal(
    model: &Model,
    w: &mut Work,
    which: CentroidalMatrix,
    out: &mut [f64],
) -> KernelResult {
    let nv = model.nv();
    let q = &w.args[0];
    match which {
        CentroidalMatrix::Full => {
            w.cen
                .compute_matrix(model, &mut w.data, q)
                .map_err(|e| e.to_string())?;
            write_rows(w.cen.ag().map_err(|e| e.to_string())?, out);
            return Ok(());
        }
        CentroidalMatrix::Angular => {
            w.cen
                .compute_matrix(model, &mut w.data, q)
                .map_err(|e| e.to_string())?;
            let mat = sized(&mut w.mat, 3, nv);
            w.cen
                .angular_momentum_jacobian(mat)
                .map_err(|e| e.to_string())?;
        }
        CentroidalMatrix::Com => {
            let mat = sized(&mut w.mat, 3, nv);
            w.cen
                .com_jacobian(model, &mut w.data, &w.args[0], mat)
                .map_err(|e| e.to_string())?;
        }
    }
    write_rows(&w.mat, out);
    Ok(())
}
