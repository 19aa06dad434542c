//! Preallocated per-call workspace (model/data split): every recursion writes here.

use crate::centroidal::MomentumTable;
use crate::dynamics::on::OneDofStep;
use crate::dynamics::ColumnAncestors;
use crate::kinematics::{fd_step_kind, step_kind, StepKind};
use crate::mechanism::ankle::AnkleLoop;
use crate::mechanism::knee::KneeLoopCache;
use crate::mechanism::{AxialMotion, MechanismError};
use crate::model::coupling::Mechanism;
use crate::model::joint::{quaternion_jacobian, Joint};
use crate::model::{Body, JointModel};
use crate::spatial::{
    ArticulatedInertia, Axis, CompositeInertia, Force, Motion, RigidInertia, SpatialTransform,
};
use crate::subsystem::axial::{axial_members, carriers, AxialKind, AxialMember, Carried};
use crate::subsystem::link::{link_rotor_subsystems, LinkRotors};
use crate::subsystem::MAX_SUBSYSTEM_DOF;
use crate::Model;

mod dense;
use nalgebra::{
    DMatrix, DVector, Isometry3, Matrix3, Matrix6, Rotation3, Translation3, UnitQuaternion,
    Vector3, Vector6,
};

/// Mutable workspace for one model. Its memory is linear in the model size: the vectors are
/// sized once in [`Data::new`], the dense `nv x nv` matrices of the O(n^3) methods there too
/// for `nv <= EAGER_DENSE_MAX_NV` (256: at most 1 MiB, so robot-sized models allocate nothing
/// after `Data::new`), for larger models by the first call that needs them
/// ([`crate::mass_matrix`], CRBA or sparse forward dynamics), and kept.
///
/// Kinematic results are public: after any kinematics or dynamics call, `x[i]` is `C_i` (2.36),
/// `world_rot[i]` / `world_pos[i]` the pose of body `i` in the world, `vel[i]` its velocity
/// `[omega; rdot_O]` and `acc[i]` its conventional acceleration, both in body coordinates.
/// Exception: O(n) forward dynamics skips Harmonic Drive rotors whose inertia is axisymmetric
/// about their spin axis (their kinematics, and `acc` of sub-system members without children
/// outside, are left as they were; see [`crate::forward_dynamics_kinematics`]).
///
/// # Example
///
/// A double pendulum hanging along `-z` with joints about `y`: the elbow sits at
/// `l (-sin q1, 0, -cos q1)`, and the upper link turns at `(0, qd1, 0)`.
///
/// ```
/// use biped_dynamics::{forward_kinematics, BodySpec, Data, JointModel, ModelBuilder};
/// use biped_dynamics::RigidInertia;
/// use nalgebra::{DVector, Isometry3, Matrix3, Vector3};
///
/// let l = 0.4;
/// let rod = RigidInertia::new(1.0, Vector3::new(0.0, 0.0, -l / 2.0), Matrix3::identity() * 1e-3)?;
/// let hinge = JointModel::Revolute { axis: Vector3::y_axis() };
/// let mut b = ModelBuilder::new();
/// let upper = b.add_body(BodySpec::named("upper", None, hinge.clone(), Isometry3::identity(), rod))?;
/// let at_tip = Isometry3::translation(0.0, 0.0, -l);
/// b.add_body(BodySpec::named("lower", Some(upper), hinge, at_tip, rod))?;
/// let model = b.build()?;
///
/// let mut data = Data::new(&model);
/// let (q, v) = (DVector::from_vec(vec![0.5, -0.2]), DVector::from_vec(vec![1.5, 0.0]));
/// forward_kinematics(&model, &mut data, &q, &v, &DVector::zeros(2))?;
/// let elbow = Vector3::new(-l * 0.5_f64.sin(), 0.0, -l * 0.5_f64.cos());
/// assert!((data.world_pos[1] - elbow).norm() < 1e-15);
/// assert!((data.body_pose(1).translation.vector - elbow).norm() < 1e-15);
/// assert!((data.vel[0].ang - Vector3::new(0.0, 1.5, 0.0)).norm() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct Data {
    pub(crate) nq: usize,
    pub(crate) nv: usize,
    /// Spatial transforms `C_i = C_kp` from parent to body (2.36).
    pub x: Vec<SpatialTransform>,
    /// Rotation `A_Ik` of each body frame in the world (columns = body axes in world coordinates).
    pub world_rot: Vec<Matrix3<f64>>,
    /// Origin of each body frame in world coordinates.
    pub world_pos: Vec<Vector3<f64>>,
    /// Body velocities `v_i = [omega; rdot_O]` in body coordinates (2.33).
    pub vel: Vec<Motion>,
    /// Body accelerations `a_i = [omegadot; rddot_O]` in body coordinates (2.34); after forward
    /// dynamics they are the true accelerations (gravity enters as a force, not here).
    pub acc: Vec<Motion>,
    /// Velocity-dependent accelerations `b_i` of (2.34)/(2.37), body coordinates.
    pub bias_acc: Vec<Motion>,
    /// Gravity in each body's coordinates `g_i`.
    pub gravity_body: Vec<Vector3<f64>>,
    /// Relative Jacobians `J_i` of 6-DoF joints (child coordinates, rows `[ang; lin]`).
    pub jacobian6: Vec<Matrix6<f64>>,
    /// Body forces `f_i = f_ext + f_g - h_i` of (2.56), body coordinates.
    pub(crate) force: Vec<Force>,
    /// Projected mass matrices `M-bar_i` (2.69).
    pub(crate) mbar: Vec<ArticulatedInertia>,
    /// Projected forces `f-bar_i` (2.70).
    pub(crate) fbar: Vec<Force>,
    /// `U_i`, `D_i^-1` and `p_i` of one-DoF joints, one entry per body ([`OneDofStep`]).
    pub(crate) one_dof: Vec<OneDofStep>,
    /// `D^-1 U^T` of 6-DoF joints, so that `P_i = -pi6 C_i` (2.67).
    pub(crate) pi6: Vec<Matrix6<f64>>,
    /// Forward propagation quantity `p_i` (2.68) of 6-DoF joints.
    pub(crate) p6: Vec<Vector6<f64>>,
    /// Net body forces of the RNEA backward pass.
    pub(crate) fnet: Vec<Force>,
    /// Composite rigid-body inertias of CRBA (world axes, about the world origin).
    pub(crate) ic: Vec<CompositeInertia>,
    /// Jacobian columns `J_i` of all bodies in world axes about the world origin (CRBA).
    pub(crate) col_world: Vec<Motion>,
    /// Offset of each body's columns in `col_world`.
    pub(crate) col_offset: Vec<usize>,
    /// Ancestor columns of every body and the coordinate of every column (CRBA).
    pub(crate) column_ancestors: ColumnAncestors,
    /// Member transforms `C-hat_j` from the sub-system parent (2.77), per body; only for
    /// members not attached to the parent (the others' `C-hat_j = C_j` is read from `x`).
    pub(crate) cbar: Vec<SpatialTransform>,
    /// Member Jacobians `J-hat_j` over the sub-system's coordinates (2.78), per body.
    pub(crate) jbar: Vec<[Motion; MAX_SUBSYSTEM_DOF]>,
    /// Member bias accelerations `b-hat_j` (2.79), per body; only for members not attached
    /// to the sub-system parent (the others' `b-hat_j = b_j` is read from `bias_acc`).
    pub(crate) bbar: Vec<Motion>,
    /// Cholesky factor of `M_S` (2.76a), per sub-system.
    pub(crate) sub_l: Vec<[[f64; MAX_SUBSYSTEM_DOF]; MAX_SUBSYSTEM_DOF]>,
    /// Rows of `B_S` (2.76b) as parent-frame forces, per sub-system.
    pub(crate) sub_b: Vec<[Force; MAX_SUBSYSTEM_DOF]>,
    /// `p_S` (2.68 for sub-systems), per sub-system.
    pub(crate) sub_p: Vec<[f64; MAX_SUBSYSTEM_DOF]>,
    /// Per body: the constant frame of a Harmonic Drive rotor (placement times initial rotor
    /// pose) or of an ankle screw rotor or nut at zero spin and travel ([`crate::kinematics::rotor_frames`]).
    pub(crate) rotor_frame: Vec<SpatialTransform>,
    /// Per body: its parent-frame data if it is an axial member of its sub-system (an
    /// axisymmetric motor rotor or a roller-screw nut, `crate::subsystem::axial`, (2.76)).
    pub(crate) axial_member: Vec<Option<AxialMember>>,
    /// Per body: the riders it carries and their lumped inertia ([`Carried`]).
    pub(crate) carried: Vec<Option<Carried>>,
    /// Bodies with a [`Data::axial_member`], ascending, with a copy of it (the O(n) first
    /// pass walks this list: no per-body `Option` and bounds checks).
    pub(crate) axial_members: Vec<(usize, AxialMember)>,
    /// Per body: the spin or travel of a roller-screw rotor or nut with a
    /// [`Data::axial_member`] at the last forward-dynamics kinematics pass (unused otherwise).
    pub(crate) axial_motion: Vec<AxialMotion>,
    /// Per body: a fixed-joint leaf without inertia (a sole or tool frame): its `M-bar` stays
    /// zero, so the O(n) backward pass only propagates its force.
    pub(crate) massless_leaf: Vec<bool>,
    /// Per sub-system: the constants of a one-link-with-rotors sub-system ([`crate::subsystem::link`]).
    pub(crate) link_rotors: Vec<Option<LinkRotors>>,
    /// Per body: the start value of `mbar` in the O(n) passes, `M_i` plus the constant
    /// parent-frame `K` of the axial rotors of the sub-systems it is the parent of (their
    /// share of (2.76) added once here, not per call); `None` where the passes never read
    /// `mbar` (rigid sub-system members, whose `M-hat` is applied from the rigid-body inertia
    /// directly, and massless leaves).
    pub(crate) mbar_init: Vec<Option<ArticulatedInertia>>,
    /// Per body: the rigid-body inertia whose forces (2.56) the O(n) first pass forms, `M_i`
    /// plus the carried lumped axial members' ([`AxialMember::lumped`], constant in its frame).
    pub(crate) force_inertia: Vec<RigidInertia>,
    /// Per body: a lumped axial member's load `s . C^T (M b - f)` on its own coordinate, set
    /// by the O(n) first pass ([`AxialMember::spin_load`]).
    pub(crate) axial_load: Vec<f64>,
    /// Coordinate axis (0, 1, 2) of a revolute joint whose placement is a pure translation, so
    /// that `C_i` rotates about that axis ([`ArticulatedInertia::add_tr_transform_axis_to`]), per body.
    pub(crate) plane_axis: Vec<Option<usize>>,
    /// Per body: how the first forward recursion steps it ([`crate::kinematics::step_kind`]).
    pub(crate) step_kind: Vec<StepKind>,
    /// Per body: how the forward-dynamics kinematics pass steps it (axial members skipped or
    /// reduced to their spin or travel, [`crate::kinematics::fd_step_kind`]).
    pub(crate) fd_step_kind: Vec<StepKind>,
    /// Constants of the centroidal momentum sum ([`crate::centroidal_momentum_current`]).
    pub(crate) momentum_table: MomentumTable,
    /// Per body: the joint placement is the identity, so a coupled part's `C` is its relative
    /// pose alone (no placement products in the kinematics).
    pub(crate) unplaced: Vec<bool>,
    /// Last closed ankle slider-crank loop, reused by the actuator's other parts.
    pub(crate) ankle_loop: Option<AnkleLoop>,
    /// Last closed knee loop, reused by the drive's other parts.
    pub(crate) knee_loop: Option<KneeLoopCache>,
    /// Body whose mechanism failed in the last kinematics pass (reported as an error).
    pub(crate) mechanism_fault: Option<(usize, MechanismError)>,
    /// True while the kinematics of [`crate::forward_dynamics_kinematics`] are current (set by
    /// it, cleared by every other kinematics pass): [`crate::forward_dynamics_solve`] needs it.
    pub(crate) fd_kinematics: bool,
    /// `q` and `v` of the last [`crate::forward_dynamics_kinematics`], to complete the skipped
    /// kinematics of spin-invariant rotors when an algorithm needs them.
    pub(crate) fd_q: DVector<f64>,
    /// See [`Data::fd_q`].
    pub(crate) fd_v: DVector<f64>,
    /// Generalized accelerations (output of forward dynamics).
    pub ddq: DVector<f64>,
    /// Generalized forces (output of inverse dynamics).
    pub tau: DVector<f64>,
    /// Joint-space mass matrix (output of [`crate::mass_matrix`] and of CRBA forward dynamics;
    /// on large sparse trees, e.g. Dill(8) and up, sparse forward dynamics rewrites only the
    /// entries of the tree pattern, the others being zero by structure and never written by
    /// this crate); for `nv > 256` empty (0 x 0)
    /// until a call that computes it.
    pub mass: DMatrix<f64>,
    /// Velocity/gravity/external-force bias `RNEA(q, v, 0)` used by the O(n^3) methods.
    pub nle: DVector<f64>,
    /// Factorisation workspace (dense Cholesky or sparse LTL); sized like `mass`.
    pub(crate) factor: DMatrix<f64>,
}

/// [`Data::mbar_init`]: `None` for rigid sub-system members, except the link of a
/// link-with-rotors sub-system, whose step reads `mbar`, and for massless leaves.
fn mbar_init(
    model: &Model,
    axial_member: &[Option<AxialMember>],
    massless_leaf: &[bool],
) -> Vec<Option<ArticulatedInertia>> {
    let mut needed: Vec<bool> = massless_leaf.iter().map(|m| !m).collect();
    for sub in &model.subsystems {
        for (&j, &rigid) in sub.members.iter().zip(&sub.rigid_member) {
            needed[j] = !rigid;
        }
    }
    for lr in link_rotor_subsystems(model, axial_member).iter().flatten() {
        needed[lr.link] = true;
    }
    let mut init: Vec<Option<ArticulatedInertia>> = (model.bodies.iter().zip(needed))
        .map(|(b, needed)| needed.then(|| b.inertia.to_articulated()))
        .collect();
    for sub in &model.subsystems {
        let Some(p) = sub.parent else { continue };
        for &j in &sub.members {
            let constant = axial_member[j].filter(|rc| !rc.rider && rc.kind != AxialKind::Slider);
            if let (Some(rc), Some(m)) = (constant, init[p].as_mut()) {
                *m += rc.congruence;
            }
        }
    }
    init
}

/// [`Data::force_inertia`]: each body's inertia merged with its lumped axial members' at their
/// constant frames (spin-invariant, so any spin angle gives the same sum).
fn force_inertias(
    model: &Model,
    axial_member: &[Option<AxialMember>],
    frames: &[SpatialTransform],
) -> Vec<RigidInertia> {
    let mut out: Vec<RigidInertia> = model.bodies.iter().map(|b| b.inertia).collect();
    for (j, rc) in axial_member.iter().enumerate() {
        if let Some(rc) = rc.filter(AxialMember::lumped) {
            let merged = out[rc.carrier].merged(&model.bodies[j].inertia, &frames[j].to_pose());
            out[rc.carrier] = merged;
        }
    }
    out
}

/// Per body: fixed joint, zero inertia and no children (see [`Data::massless_leaf`]).
fn massless_leaves(model: &Model) -> Vec<bool> {
    let mut leaf = vec![true; model.nbodies()];
    for p in model.bodies.iter().filter_map(|b| b.parent) {
        leaf[p] = false;
    }
    let zero = |b: &Body| b.inertia.to_articulated() == ArticulatedInertia::zero();
    model
        .bodies
        .iter()
        .zip(leaf)
        .map(|(b, leaf)| leaf && matches!(b.joint, Joint::Fixed) && zero(b))
        .collect()
}

/// The coordinate axis of a revolute (or rotor) joint with an unrotated placement.
pub(crate) fn plane_axis(body: &Body) -> Option<usize> {
    match &body.joint {
        Joint::Revolute(ax) | Joint::Rotor(ax) if body.placement_x.rot == Matrix3::identity() => {
            match ax.axis {
                Axis::X => Some(0),
                Axis::Y => Some(1),
                Axis::Z => Some(2),
                Axis::General(_) => None,
            }
        }
        _ => None,
    }
}

impl Data {
    /// Workspace sized for `model`.
    pub fn new(model: &Model) -> Self {
        let n = model.nbodies();
        let nv = model.nv();
        let ns = model.subsystems.len();
        let mut jacobian6 = vec![Matrix6::zeros(); n];
        for (i, b) in model.bodies.iter().enumerate() {
            if matches!(b.joint, Joint::Quaternion) {
                jacobian6[i] = quaternion_jacobian();
            }
        }
        for (i, b) in model.bodies.iter().enumerate() {
            if let JointModel::Coupled {
                mechanism: Mechanism::HarmonicDrive(rotor),
                ..
            } = &b.joint_model
            {
                // Constant rotor Jacobian column [0, 0, N, 0, 0, 0] (3.1).
                jacobian6[i][(2, 0)] = rotor.params().ratio;
            }
        }
        let rotor_frames = crate::kinematics::rotor_frames(model);
        let axial_member = axial_members(model, &rotor_frames);
        let massless_leaf = massless_leaves(model);
        let plane_axes: Vec<Option<usize>> = model.bodies.iter().map(plane_axis).collect();
        let step_kinds: Vec<StepKind> = (model.bodies.iter().enumerate().zip(&plane_axes))
            .map(|(body, &axis)| step_kind(body, axis))
            .collect();
        let fd_step_kinds = (step_kinds.iter().zip(&axial_member))
            .map(|(&kind, rc)| fd_step_kind(kind, rc.map(|rc| rc.kind)))
            .collect();
        let mut col_offset = vec![0; n + 1];
        for (i, b) in model.bodies.iter().enumerate() {
            col_offset[i + 1] = col_offset[i] + b.v_set.len();
        }
        let mut data = Self {
            nq: model.nq(),
            nv,
            x: vec![SpatialTransform::identity(); n],
            world_rot: vec![Matrix3::identity(); n],
            world_pos: vec![Vector3::zeros(); n],
            vel: vec![Motion::zero(); n],
            acc: vec![Motion::zero(); n],
            bias_acc: vec![Motion::zero(); n],
            gravity_body: vec![Vector3::zeros(); n],
            jacobian6,
            force: vec![Force::zero(); n],
            mbar: vec![ArticulatedInertia::zero(); n],
            fbar: vec![Force::zero(); n],
            one_dof: vec![OneDofStep::default(); n],
            pi6: vec![Matrix6::zeros(); n],
            p6: vec![Vector6::zeros(); n],
            fnet: vec![Force::zero(); n],
            ic: vec![CompositeInertia::default(); n],
            col_world: vec![Motion::zero(); col_offset.last().copied().unwrap_or(0)],
            column_ancestors: ColumnAncestors::new(model, &col_offset),
            col_offset: col_offset[..n].to_vec(),
            cbar: vec![SpatialTransform::identity(); n],
            jbar: vec![[Motion::zero(); MAX_SUBSYSTEM_DOF]; n],
            bbar: vec![Motion::zero(); n],
            sub_l: vec![[[0.0; MAX_SUBSYSTEM_DOF]; MAX_SUBSYSTEM_DOF]; ns],
            sub_b: vec![[Force::zero(); MAX_SUBSYSTEM_DOF]; ns],
            sub_p: vec![[0.0; MAX_SUBSYSTEM_DOF]; ns],
            link_rotors: link_rotor_subsystems(model, &axial_member),
            momentum_table: MomentumTable::new(model, &axial_member),
            mbar_init: mbar_init(model, &axial_member, &massless_leaf),
            force_inertia: force_inertias(model, &axial_member, &rotor_frames),
            axial_load: vec![0.0; n],
            massless_leaf,
            axial_members: (axial_member.iter().enumerate())
                .filter_map(|(i, rc)| rc.map(|rc| (i, rc)))
                .collect(),
            carried: carriers(model, &axial_member),
            axial_motion: vec![AxialMotion::default(); n],
            axial_member,
            rotor_frame: rotor_frames,
            plane_axis: plane_axes,
            step_kind: step_kinds,
            fd_step_kind: fd_step_kinds,
            unplaced: crate::kinematics::identity_placements(model),
            ankle_loop: None,
            knee_loop: None,
            mechanism_fault: None,
            fd_kinematics: false,
            fd_q: DVector::zeros(model.nq()),
            fd_v: DVector::zeros(nv),
            ddq: DVector::zeros(nv),
            tau: DVector::zeros(nv),
            mass: DMatrix::zeros(0, 0),
            nle: DVector::zeros(nv),
            factor: DMatrix::zeros(0, 0),
        };
        data.dense_workspace_up_front();
        data
    }

    /// Number of bodies this workspace was sized for.
    pub fn nbodies(&self) -> usize {
        self.x.len()
    }

    /// World pose of body `i` (valid after a kinematics or dynamics call).
    pub fn body_pose(&self, i: usize) -> Isometry3<f64> {
        let r = Rotation3::from_matrix_unchecked(self.world_rot[i]);
        Isometry3::from_parts(
            Translation3::from(self.world_pos[i]),
            UnitQuaternion::from_rotation_matrix(&r),
        )
    }
}
