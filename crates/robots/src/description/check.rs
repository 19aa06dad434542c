//! Checks of the description's names and values against the loaded URDF (and SRDF).

use super::error::{DescriptionError, Locator};
use super::raw::{Names, RawDescription, RawFoot};
use super::Foot;
use biped_dynamics::urdf::srdf::Srdf;
use biped_dynamics::urdf::UrdfModel;
use nalgebra::{DVector, Vector3};
use toml::Spanned;

type Res<T> = Result<T, DescriptionError>;

/// Name checks against one URDF.
pub(super) struct Checker<'a> {
    pub loc: &'a Locator<'a>,
    pub urdf: &'a UrdfModel,
}

impl Checker<'_> {
    /// Errors unless `name` is a movable joint of the URDF.
    pub(super) fn joint(&self, name: &Spanned<String>, field: &str) -> Res<String> {
        let n = name.get_ref();
        if self.urdf.joints.iter().any(|j| &j.name == n) {
            Ok(n.clone())
        } else {
            let reason = format!("`{n}` is not a movable joint of the URDF");
            Err(self.loc.invalid(name.span(), field, reason))
        }
    }

    /// A list of joints (non-empty unless `may_be_empty`).
    pub(super) fn joints(&self, list: &Names, field: &str, may_be_empty: bool) -> Res<Vec<String>> {
        if list.get_ref().is_empty() && !may_be_empty {
            return Err(self
                .loc
                .invalid(list.span(), field, "must list at least one joint"));
        }
        list.get_ref()
            .iter()
            .map(|n| self.joint(n, field))
            .collect()
    }

    /// The producing list: joints, none of them reducing.
    pub(super) fn producing(&self, list: &Names, reducing: &[String]) -> Res<Vec<String>> {
        let field = "momentum.producing";
        for n in list.get_ref() {
            if reducing.contains(n.get_ref()) {
                let reason = format!("`{}` is also in momentum.reducing", n.get_ref());
                return Err(self.loc.invalid(n.span(), field, reason));
            }
        }
        self.joints(list, field, true)
    }

    /// A foot: link frame, finite sole centre, positive sole size, toe joint.
    pub(super) fn foot(&self, raw: &RawFoot, field: &str) -> Res<Foot> {
        let frame = raw.frame.get_ref();
        if !self.urdf.links.iter().any(|l| &l.link == frame) {
            let reason = format!("`{frame}` is not a link of the URDF");
            return Err(self
                .loc
                .invalid(raw.frame.span(), format!("{field}.frame"), reason));
        }
        let c = *raw.sole_center.get_ref();
        if c.iter().any(|v| !v.is_finite()) {
            let f = format!("{field}.sole_center");
            return Err(self
                .loc
                .invalid(raw.sole_center.span(), f, "must be finite"));
        }
        let s = *raw.sole_size.get_ref();
        if s.iter().any(|v| !(*v > 0.0 && v.is_finite())) {
            let f = format!("{field}.sole_size");
            return Err(self
                .loc
                .invalid(raw.sole_size.span(), f, "length and width must be > 0"));
        }
        let toe = raw.toe_joint.as_ref();
        let toe_joint = toe.map(|t| self.joint(t, &format!("{field}.toe_joint")));
        Ok(Foot {
            frame: frame.clone(),
            sole_center: Vector3::from(c),
            sole_size: s,
            toe_joint: toe_joint.transpose()?,
        })
    }

    /// The comfort configuration: 0 clamped into each range, then the SRDF state, then the
    /// listed joints (which must lie inside their ranges).
    pub(super) fn comfort(&self, raw: &RawDescription, srdf: Option<&Srdf>) -> Res<DVector<f64>> {
        let model = &self.urdf.model;
        let mut q = model.neutral();
        let index = |name: &str| {
            let j = self.urdf.joints.iter().find(|j| j.name == name)?;
            Some((model.body(j.body)?.q_index(), j.range))
        };
        for j in &self.urdf.joints {
            if let (Some(b), Some([lo, hi])) = (model.body(j.body), j.range) {
                q[b.q_index()] = 0.0_f64.clamp(lo, hi);
            }
        }
        if let Some(state) = &raw.comfort.srdf_state {
            let field = "comfort.srdf_state";
            let found = srdf.and_then(|s| s.state(state.get_ref()));
            let found = found.ok_or_else(|| {
                let reason = format!("no SRDF group_state `{}` (drives.srdf)", state.get_ref());
                self.loc.invalid(state.span(), field, reason)
            })?;
            for (name, values) in &found.joints {
                if let (Some((qi, _)), [value]) = (index(name), values.as_slice()) {
                    q[qi] = *value;
                }
            }
        }
        for (name, value) in &raw.comfort.joints {
            let field = format!("comfort.joints.{name}");
            let Some((qi, range)) = index(name) else {
                let reason = format!("`{name}` is not a movable joint of the URDF");
                return Err(self.loc.invalid(value.span(), field, reason));
            };
            let v = *value.get_ref();
            if let Some([lo, hi]) = range.filter(|[lo, hi]| !(v >= *lo && v <= *hi)) {
                let reason = format!("{v} is outside the joint range [{lo}, {hi}]");
                return Err(self.loc.invalid(value.span(), field, reason));
            }
            q[qi] = v;
        }
        Ok(q)
    }

    /// Armature entries in file order: patterns that match a joint, inertias finite, >= 0.
    pub(super) fn armature(&self, raw: &RawDescription) -> Res<Vec<(String, f64)>> {
        let mut out = Vec::new();
        for (k, entry) in raw.drives.armature.iter().enumerate() {
            let field = format!("drives.armature[{k}]");
            let (pattern, v) = (&entry.get_ref().joints, entry.get_ref().inertia);
            if !self
                .urdf
                .joints
                .iter()
                .any(|j| glob_match(pattern, &j.name))
            {
                let reason = format!("`{pattern}` matches no movable joint of the URDF");
                return Err(self.loc.invalid(entry.span(), field, reason));
            }
            if !(v >= 0.0 && v.is_finite()) {
                let reason = "inertia must be finite and >= 0";
                return Err(self.loc.invalid(entry.span(), field, reason));
            }
            out.push((pattern.clone(), v));
        }
        Ok(out)
    }
}

/// True if `name` matches `pattern`, where `*` stands for any run of characters.
pub(super) fn glob_match(pattern: &str, name: &str) -> bool {
    match pattern.split_once('*') {
        None => pattern == name,
        Some((head, tail)) => {
            let Some(rest) = name.strip_prefix(head) else {
                return false;
            };
            // `*` takes 0, 1, ... characters; the rest of the pattern matches what is left
            (0..=rest.len())
                .filter(|&i| rest.is_char_boundary(i))
                .any(|i| glob_match(tail, &rest[i..]))
        }
    }
}
