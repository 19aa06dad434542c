//! Which branch of the fast O(n) path ([`crate::forward_dynamics`] with
//! [`crate::Algorithm::On`]) each sub-system member takes, so that tests comparing the
//! reference against it can state which member kinds they covered.

use crate::subsystem::axial::AxialKind;
use crate::{Data, Model};

/// How the fast O(n) path treats one sub-system member.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum MemberKind {
    /// Rigid member (no children outside the sub-system): `M-hat_j = M_j` (2.77a), compact.
    Rigid,
    /// Rigid member whose inertia is axisymmetric about its z axis ((2.76) in 12 flops).
    Axisymmetric,
    /// Member with children outside the sub-system: general `M-hat_j` (2.77a).
    General,
    /// Harmonic Drive rotor in its parent's frame, constant ratio (3.1)-(3.2).
    AxialGeared,
    /// Roller-screw rotor in its parent's frame, spin rate `N dl/dq` (3.22), (3.32)-(3.33).
    AxialScrew,
    /// Roller-screw nut sliding along an axis fixed in its parent (3.29).
    AxialSlider,
    /// Member carrying riders (the knee's screw housing with its rotor and nut), lumped (2.76).
    Carrier,
    /// Rider lumped into its carrier's terms of (2.76).
    Rider,
    /// The link of a one-DoF link-with-rotors sub-system: the body step (2.67)-(2.72) plus rotors.
    Link,
}

/// `(body, kind)` of every sub-system member of `model`, in sub-system and member order.
pub fn fast_member_kinds(model: &Model) -> Vec<(usize, MemberKind)> {
    let data = Data::new(model);
    let mut out = Vec::new();
    for (s, sub) in model.subsystems.iter().enumerate() {
        let link = data.link_rotors[s].is_some();
        let flags = sub.rigid_member.iter().zip(&sub.axisymmetric_member);
        for (&j, (&rigid, &axisymmetric)) in sub.members.iter().zip(flags) {
            let kind = match (&data.axial_member[j], &data.carried[j]) {
                (Some(rc), _) if rc.rider => MemberKind::Rider,
                (Some(rc), _) => match rc.kind {
                    AxialKind::Geared => MemberKind::AxialGeared,
                    AxialKind::Screw => MemberKind::AxialScrew,
                    AxialKind::Slider => MemberKind::AxialSlider,
                },
                (None, _) if link => MemberKind::Link,
                (None, Some(_)) => MemberKind::Carrier,
                (None, None) if axisymmetric => MemberKind::Axisymmetric,
                (None, None) if rigid => MemberKind::Rigid,
                (None, None) => MemberKind::General,
            };
            out.push((j, kind));
        }
    }
    out
}
