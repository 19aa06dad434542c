//! Axial members: rigid leaves of a sub-system that spin about or slide along an axis fixed in
//! the sub-system's parent (motor rotors and roller-screw nuts), treated in the parent's frame
//! by the O(n) passes without any kinematics of their own (2.76).
//!
//! A Harmonic Drive rotor (3.1)-(3.2) attached directly to its sub-system's parent has
//! `C-hat = C`, a rotation by the spin angle about the z axis of a constant frame. When the
//! rotor's inertia is axisymmetric about that axis (CoM on the axis, `I_xx = I_yy`, no products
//! of inertia), its term `K = C^T M C` of (2.76) does not depend on the spin angle and is
//! computed once per model. So are its contributions to `B_S` and `M_S`: with the rotor column
//! `J = [0, 0, N, 0, 0, 0]` (3.1) and its parent-frame image `s = C^-1 J` (the spin axis,
//! constant), `C^T M J = K s` and `J^T M J = s^T K s`.
//!
//! Such a rotor's CoM is fixed in the parent frame and its inertia there is constant, so the
//! O(n) forward dynamics need no rotor kinematics at all (no spin angle, no rotor pose): its
//! velocity-product and gravity force `C^T (M b - f)` is formed in the parent frame from the
//! parent's angular velocity and gravity ([`parent_frame_bias`]). The kinematics of these
//! rotors are therefore skipped by [`crate::forward_dynamics_kinematics`] and completed only
//! where another algorithm needs them.
//!
//! The ankle's roller-screw rotors (3.22) spin the same way about an axis fixed in the shank,
//! but at the configuration-dependent rate `phi_dot = rho(q) qdot` with `rho = N_screw dl/dq`
//! (3.32). With the unit spin twist `s`, their column `c` of `J-hat` is `s rho_c`, so they add
//! `rho_r rho_c s^T K s` to `M_S`, `rho_c K s` to `B_S`, and the spin acceleration at zero
//! `qddot`, `sigma = qdot^T (d rho / d q) qdot` (3.33), adds `K s sigma` to their bias force
//! ([`AxialKind::Screw`]). Their nuts (3.29) keep the screw frame's orientation and slide along
//! its axis `e` by the travel `l`: with `s = [0; e]` and `rho = dl/dq` the same sums hold, with
//! `K` the nut's rigid inertia at its current CoM `c_0 + e l` (no rotation: cheaper than a
//! congruence) and `s^T K s = m` ([`AxialKind::Slider`]). The kinematics pass records the spin or
//! travel, `rho`, its rate and `sigma` from the loop the drive's rod closes anyway.

use super::on::add_rigid_congruence;
use super::rigid::is_axisymmetric;
use super::Subsystem;
use crate::mechanism::{AxialRole, Coupling};
use crate::model::coupling::Mechanism;
use crate::model::JointModel;
use crate::spatial::{
    sym_congruence, ArticulatedInertia, Force, Motion, RigidInertia, SpatialTransform,
};
use crate::Model;
use nalgebra::{Matrix3, Vector3};

/// How an axial member moves about or along its axis fixed in the sub-system's parent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum AxialKind {
    /// Harmonic Drive rotor (3.1): spins at a constant ratio `N` of one coordinate, folded
    /// into `s`.
    Geared,
    /// Ankle roller-screw rotor (3.22), (3.32)-(3.33): spins about the unit twist `s` at the
    /// configuration-dependent rate of each kinematics pass (`Data::axial_motion`).
    Screw,
    /// Ankle roller-screw nut (3.29), (3.32)-(3.33): translates along the unit axis `s.lin`
    /// with a fixed orientation, travel and rate from each kinematics pass.
    Slider,
}

/// Parent-frame data of one axial member of a sub-system (see the module doc).
#[derive(Clone, Copy, Debug)]
pub(crate) struct AxialMember {
    /// How the member follows the coordinates (and what `s` is per unit of).
    pub(crate) kind: AxialKind,
    /// `K = C^T M C` in the sub-system parent's frame (rotors; a slider's varies with its
    /// travel: [`crate::subsystem::rigid::RigidSum::at`] its CoM from [`Self::state`]).
    pub(crate) congruence: ArticulatedInertia,
    /// Column of the rotor's coordinate within the sub-system ([`AxialKind::Geared`]).
    pub(crate) column: usize,
    /// `C^T M J = K s`, the contribution to the member's row of `B_S` (constant, also for a
    /// slider).
    pub(crate) ks: Force,
    /// `J^T M J = s^T K s`, the contribution to the diagonal of `M_S`.
    pub(crate) sks: f64,
    /// `s = C^-1 J`: the member's column in the parent frame (`s.ang = N` times the spin axis
    /// for [`AxialKind::Geared`], the unit spin twist or unit translation otherwise).
    pub(crate) s: Motion,
    /// Mass `m`.
    pub(crate) mass: f64,
    /// CoM in parent coordinates (a slider's at zero travel).
    pub(crate) com: Vector3<f64>,
    /// Rotational inertia about the CoM in parent axes (constant).
    pub(crate) inertia_com: Matrix3<f64>,
    /// `u = I_c s.ang`, the spin's angular momentum per unit of `qd` (parent axes).
    pub(crate) spin_momentum: Vector3<f64>,
    /// Velocity index of the driving coordinate (the first input's for a coupled part).
    pub(crate) v_index: usize,
    /// The body whose frame carries the axis: the sub-system's parent, or for a rider the
    /// sibling member it rides on ([`Carried`]).
    pub(crate) carrier: usize,
    /// True for a rider: its terms are lumped into its carrier member's.
    pub(crate) rider: bool,
    /// Constants of its load on its own coordinate ([`AxialMember::spin_load`]).
    pub(crate) load: LoadForm,
}

/// Constants of an axial member's load `s . h` on its own coordinate, `h = C^T (M b - f)` of
/// [`parent_frame_bias`] for a CoM fixed in the carrier: `w^T Q w + qd (u x s_ang) . w +
/// sigma s_ang . u + g_s . g` (triple products of (2.56) rearranged about the constants).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct LoadForm {
    /// Symmetric `Q = sym(s_ang~^T I_O) + sym(s_lin h^T) - (s_lin . h) E`: velocity products.
    q: Matrix3<f64>,
    /// `u x s_ang`: the gyroscopic part per unit of speed.
    gyro: Vector3<f64>,
    /// `s_ang . u`: the part per unit of spin acceleration.
    su: f64,
    /// `g_s = -(s_ang x h) - m s_lin`: the gravity part.
    grav: Vector3<f64>,
}

impl LoadForm {
    /// The constants for the column `s`, mass `m`, first moment `h`, rotational inertia `I_O`
    /// about the carrier origin and spin momentum `u` (carrier frame).
    fn new(
        s: &Motion,
        m: f64,
        h: &Vector3<f64>,
        inertia_origin: &Matrix3<f64>,
        u: &Vector3<f64>,
    ) -> Self {
        let sym = |a: Matrix3<f64>| (a + a.transpose()) * 0.5;
        let sl_h = s.lin.dot(h);
        Self {
            q: sym(s.ang.cross_matrix().transpose() * inertia_origin) + sym(s.lin * h.transpose())
                - Matrix3::identity() * sl_h,
            gyro: u.cross(&s.ang),
            su: s.ang.dot(u),
            grav: -s.ang.cross(h) - s.lin * m,
        }
    }
}

/// A rigid sub-system member that carries riders (the knee's screw housing with its rotor and
/// nut): its inertia plus the spin-invariant riders' (constant in its frame), and the riders
/// as (body, member index). The O(n) passes treat carrier and riders as one body of the
/// carrier's motion plus the riders' columns `s rho` (see the module doc).
#[derive(Clone, Debug)]
pub(crate) struct Carried {
    /// Carrier inertia plus its spin-invariant riders' (carrier frame).
    pub(crate) base: RigidInertia,
    /// The lumped inertia is axisymmetric about the carrier's z axis at every travel.
    pub(crate) axisymmetric: bool,
    /// Riders: (body, member index in the sub-system).
    pub(crate) riders: Vec<(usize, usize)>,
    /// The sub-system of carrier and riders.
    pub(crate) subsystem: usize,
}

impl Carried {
    /// Carrier plus riders at the travel of the last kinematics pass (carrier frame).
    #[inline]
    pub(crate) fn lumped(&self, model: &Model, data: &crate::Data) -> RigidInertia {
        let mut m = self.base;
        for &(r, _) in &self.riders {
            if let Some(rc) = data.axial_member[r].filter(|rc| rc.kind == AxialKind::Slider) {
                let offset = rc.s.lin * data.axial_motion[r].travel;
                m = m.add_shifted(&model.bodies[r].inertia, &offset);
            }
        }
        m
    }
}

impl AxialMember {
    /// True if the member's CoM and inertia are constant in its carrier's frame and it is not
    /// a rider (Harmonic Drive and ankle screw rotors): its `K` is in the carrier's
    /// `Data::mbar_init` and its rigid-body forces in the carrier's `Data::force_inertia`, so
    /// that the O(n) passes see only its [`Self::spin_load`].
    #[inline(always)]
    pub(crate) fn lumped(&self) -> bool {
        !self.rider && self.kind != AxialKind::Slider
    }

    /// A lumped member's ([`Self::lumped`]) share of [`parent_frame_bias`] beyond its rigid-body
    /// forces (2.56), the angular `w_p x u qd + u sigma`, and its load `s . h` on its own
    /// coordinate for the whole `h` ([`LoadForm`]); `w_p`, `g_p` of the carrier.
    #[inline(always)]
    pub(crate) fn spin_load(
        &self,
        w_p: &Vector3<f64>,
        g_p: &Vector3<f64>,
        (qd, sigma): (f64, f64),
    ) -> (Vector3<f64>, f64) {
        let (u, f) = (&self.spin_momentum, &self.load);
        let torque = w_p.cross(&(u * qd)) + u * sigma;
        let load = w_p.dot(&(f.q * w_p + f.gyro * qd)) + f.su * sigma + f.grav.dot(g_p);
        (torque, load)
    }

    /// CoM (parent coordinates), speed per unit of `s` and acceleration at zero `qddot` of
    /// member `i` at the state of the last forward-dynamics kinematics pass on `data`.
    #[inline(always)]
    pub(crate) fn state(&self, data: &crate::Data, i: usize) -> (Vector3<f64>, f64, f64) {
        let m = &data.axial_motion[i];
        match self.kind {
            AxialKind::Geared => (self.com, data.fd_v.as_slice()[self.v_index], 0.0),
            AxialKind::Screw => (self.com, m.speed, m.bias),
            AxialKind::Slider => (self.com + self.s.lin * m.travel, m.speed, m.bias),
        }
    }
}

/// `C^T (M b - f_g + h)` of an axial member in its parent's frame (moment about the parent
/// origin): the wrench that gives it its motion at zero parent acceleration and zero `qddot`
/// against gravity, (2.56) with (2.37) moved to the parent. With the parent's angular velocity
/// `w_p` and gravity `g_p` (parent axes), the CoM `c`, speed `qd` and acceleration `sigma` from
/// [`AxialMember::state`]: a rotor's CoM is fixed in the parent and its rate is
/// `w_R = w_p + s.ang qd`, so `F = m (w_p x (w_p x c) - g_p)`, and its inertia `I_c` is constant
/// in parent axes, so `dL/dt = I_c s.ang sigma + w_p x (I_c w_R)` (the derivative of
/// `L = I_c w_R` in the parent's rotating axes); the moment about the parent origin adds
/// `c x F`, which with the constant `I_O = I_c + m (|c|^2 E - c c^T)` (the angular block of
/// `K`), `h = m c` and `u = I_c s.ang` sums to `w_p x (I_O w_p + qd u) + sigma u - h x g_p`
/// (the body force (2.56) about the parent origin plus the spin terms). A slider moving along
/// `e = s.lin` adds the Coriolis and travel terms `m (2 w_p x e qd + e sigma)` to `F` and turns
/// with the parent (`w_R = w_p`).
#[inline]
pub(crate) fn parent_frame_bias(
    rc: &AxialMember,
    w_p: &Vector3<f64>,
    g_p: &Vector3<f64>,
    (c, qd, sigma): (Vector3<f64>, f64, f64),
) -> Force {
    let m = rc.mass;
    if rc.kind == AxialKind::Slider {
        let e = &rc.s.lin;
        let a = w_p.cross(&w_p.cross(&c)) - g_p + w_p.cross(e) * (2.0 * qd) + e * sigma;
        let f = a * m;
        return Force::new(w_p.cross(&(rc.inertia_com * w_p)) + c.cross(&f), f);
    }
    let (h, u) = (c * m, &rc.spin_momentum);
    let l = rc.congruence.ang * w_p + u * qd;
    let n = w_p.cross(&l) + u * sigma - h.cross(g_p);
    Force::new(n, w_p.cross(&w_p.cross(&h)) - g_p * m)
}

/// Per body: the parent-frame data of an axial member (see the module doc), `None` for every
/// other body. `frames` are the members' constant frames (spin angle and travel zero).
pub(crate) fn axial_members(
    model: &Model,
    frames: &[SpatialTransform],
) -> Vec<Option<AxialMember>> {
    let mut out = vec![None; model.nbodies()];
    let leaf = |j: usize| model.bodies.iter().all(|b| b.parent != Some(j));
    for sub in &model.subsystems {
        for (mi, &j) in sub.members.iter().enumerate() {
            let body = &model.bodies[j];
            let unit = |lin: bool| match lin {
                false => Motion::new(Vector3::z(), Vector3::zeros()),
                true => Motion::new(Vector3::zeros(), Vector3::z()),
            };
            let spin = || (unit(false), AxialKind::Screw);
            let slide = || (unit(true), AxialKind::Slider);
            let mut carrier = sub.parent;
            let mut frame = frames[j];
            let JointModel::Coupled { mechanism, inputs } = &body.joint_model else {
                continue;
            };
            let (column, kind) = match mechanism.axial_role() {
                AxialRole::Geared(column) if body.v_set.len() == 1 => (column, AxialKind::Geared),
                AxialRole::Spins => spin(),
                AxialRole::Slides => slide(),
                AxialRole::Rides { slides } => {
                    // Riders of a carrier part: their frames are the carrier's, spun about
                    // or moved along its z axis.
                    carrier = drive_carrier(model, sub, mechanism, inputs, leaf);
                    frame = SpatialTransform::identity();
                    match (slides, carrier) {
                        (_, None) => continue,
                        (false, _) => spin(),
                        (true, _) => slide(),
                    }
                }
                _ => continue,
            };
            if !(leaf(j) && sub.rigid_member[mi] && body.parent == sub.parent) {
                continue;
            }
            let Some(carrier) = carrier else { continue };
            let congruence = match kind {
                AxialKind::Slider => Some(ArticulatedInertia::zero()),
                _ => spin_invariant(&body.inertia, &frame),
            };
            out[j] = congruence.map(|congruence| {
                let s = frame.inv_apply_motion(&column);
                let com = frame.rot.tr_mul(&body.inertia.com()) + frame.trans;
                let inertia_com = sym_congruence(&body.inertia.inertia_about_com(), &frame.rot);
                let mass = body.inertia.mass();
                // A slider's `K s = [h x e; m e]` does not change with its travel `l` along
                // `e`: `h = m (c + e l)` and `e x e = 0`.
                let ks = match kind {
                    AxialKind::Slider => Force::new((com * mass).cross(&s.lin), s.lin * mass),
                    _ => congruence.apply(&s),
                };
                AxialMember {
                    kind,
                    congruence,
                    column: sub.columns[mi][0],
                    ks,
                    sks: match kind {
                        AxialKind::Slider => body.inertia.mass(),
                        _ => s.dot(&ks),
                    },
                    s,
                    mass,
                    com,
                    inertia_com,
                    spin_momentum: inertia_com * s.ang,
                    v_index: body.v_set.as_slice()[0],
                    rider: Some(carrier) != sub.parent,
                    carrier,
                    load: LoadForm::new(
                        &s,
                        mass,
                        &(com * mass),
                        &congruence.ang,
                        &(inertia_com * s.ang),
                    ),
                }
            });
        }
    }
    out
}

/// The rigid leaf member of sub-system `sub` that carries the riders of `part`'s drive
/// ([`AxialRole::Carries`], the same drive and inputs).
fn drive_carrier(
    model: &Model,
    sub: &Subsystem,
    part: &Mechanism,
    inputs: &[usize],
    leaf: impl Fn(usize) -> bool,
) -> Option<usize> {
    let mut members = sub.members.iter().zip(&sub.rigid_member);
    members.find_map(|(&h, &rigid)| match &model.bodies[h].joint_model {
        JointModel::Coupled {
            mechanism,
            inputs: hin,
        } if mechanism.axial_role() == AxialRole::Carries
            && mechanism.same_drive(part)
            && hin.as_slice() == inputs
            && rigid
            && leaf(h) =>
        {
            Some(h)
        }
        _ => None,
    })
}

/// Per body: the riders it carries ([`Carried`]), from the axial members.
pub(crate) fn carriers(model: &Model, axial: &[Option<AxialMember>]) -> Vec<Option<Carried>> {
    let mut out: Vec<Option<Carried>> = vec![None; model.nbodies()];
    for (subsystem, sub) in model.subsystems.iter().enumerate() {
        for (mi, &r) in sub.members.iter().enumerate() {
            let Some(rc) = axial[r].filter(|rc| rc.rider) else {
                continue;
            };
            let c = rc.carrier;
            let carried = out[c].get_or_insert_with(|| Carried {
                base: model.bodies[c].inertia,
                axisymmetric: true,
                riders: Vec::new(),
                subsystem,
            });
            let inertia = &model.bodies[r].inertia;
            if rc.kind != AxialKind::Slider {
                carried.base = carried.base.add_shifted(inertia, &Vector3::zeros());
            }
            let on_axis = is_axisymmetric(&inertia.com(), &inertia.inertia_about_com());
            carried.axisymmetric &= on_axis && rc.s.lin.x == 0.0 && rc.s.lin.y == 0.0;
            carried.riders.push((r, mi));
        }
    }
    for carried in out.iter_mut().flatten() {
        let b = &carried.base;
        carried.axisymmetric &= is_axisymmetric(&b.com(), &b.inertia_about_com());
    }
    out
}

/// `C^T M C` at spin angle zero if `M` is axisymmetric about the body z axis (to rounding).
pub(crate) fn spin_invariant(
    inertia: &RigidInertia,
    frame: &SpatialTransform,
) -> Option<ArticulatedInertia> {
    let (c, i) = (inertia.com(), inertia.inertia_about_com());
    let scale = i.amax();
    let axisymmetric = c.x == 0.0
        && c.y == 0.0
        && i[(0, 1)] == 0.0
        && i[(0, 2)] == 0.0
        && i[(1, 2)] == 0.0
        && (i[(0, 0)] - i[(1, 1)]).abs() <= 1e-14 * scale;
    axisymmetric.then(|| {
        let mut k = ArticulatedInertia::zero();
        add_rigid_congruence(inertia, frame, &mut k);
        k
    })
}

#[cfg(test)]
mod tests;
