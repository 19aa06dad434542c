//! Sub-systems (thesis 2.6-2.9): groups of bodies whose index sets (2.26) overlap, treated as
//! one node of the body list so that the O(n) algorithm keeps its three passes.
//!
//! A sub-system `S` holds its member bodies `N_S` (ascending body order), the common parent
//! `p_S` outside the group, and the index set `q_S` (union of the members' index sets). The
//! children outside `C_S` and their parents `P_S` (Fig. 2.11) follow from the body links.
//! Member kinematics are expressed relative to the parent (2.77)-(2.79):
//! `a_j = C-hat_j a_p + J-hat_j qddot_S + b-hat_j`.

pub(crate) mod axial;
mod chol;
mod generate;
pub(crate) mod link;
pub(crate) mod on;
pub(crate) mod rigid;

pub(crate) use generate::generate;

use crate::BodyId;

/// Largest number of coordinates `N_DoF,S` a sub-system may span.
pub const MAX_SUBSYSTEM_DOF: usize = 8;

/// One sub-system node `S` (Fig. 2.10-2.11).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Subsystem {
    /// Member bodies `N_S` in ascending body order.
    pub(crate) members: Vec<BodyId>,
    /// Common parent `p_S` (`None` = world).
    pub(crate) parent: Option<BodyId>,
    /// Index set `q_S` into `v`, ascending.
    pub(crate) v_set: Vec<usize>,
    /// Per member: the column of `q_S` of each column of its own `J_j`.
    pub(crate) columns: Vec<[usize; crate::model::MAX_INDEX_SET]>,
    /// Members with children outside the sub-system, `P_S` (Fig. 2.11).
    pub(crate) with_outside_children: Vec<BodyId>,
    /// Per member: true if it has no child outside the sub-system, so that its `M-bar_j` in
    /// the backward pass is still its rigid-body inertia `M_j` (cheaper congruence).
    pub(crate) rigid_member: Vec<bool>,
    /// Per member: rigid and axisymmetric about its z axis (`super::rigid::is_axisymmetric`), so
    /// that `M-hat_j` is applied in 12 flops.
    pub(crate) axisymmetric_member: Vec<bool>,
}

impl Subsystem {
    /// Member bodies `N_S` in ascending body order.
    pub fn members(&self) -> &[BodyId] {
        &self.members
    }
    /// Common parent `p_S` of the sub-system (`None` = the world frame).
    pub fn parent(&self) -> Option<BodyId> {
        self.parent
    }
    /// Velocity coordinates `q_S` spanned by the sub-system, ascending.
    pub fn v_set(&self) -> &[usize] {
        &self.v_set
    }
    /// Members with children outside the sub-system, the set `P_S` of Fig. 2.11.
    pub fn outside_parents(&self) -> &[BodyId] {
        &self.with_outside_children
    }
}

/// What a node of the rewired body list stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NodeKind {
    /// A body outside every sub-system.
    Body(BodyId),
    /// A sub-system, by index into [`crate::Model::subsystems`].
    Subsystem(usize),
}

/// One entry of the rewired body list (Fig. 2.14) with its pointer links (Fig. 2.7).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Node {
    /// Body or sub-system.
    pub kind: NodeKind,
    /// Parent node (`None` = world).
    pub parent: Option<usize>,
    /// First child node.
    pub first_child: Option<usize>,
    /// Next node with the same parent (continuous brother sequence, Algorithm 2.5).
    pub brother: Option<usize>,
}
