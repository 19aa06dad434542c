//! From the file text to a [`Robot`]: parse, resolve and load the referenced files, then check
//! every name and value against the URDF (errors located at the entry at fault).

use super::error::{DescriptionError, Locator, ReferencedError};
use super::raw::{Names, RawCollision, RawDescription, RawFoot};
use super::{Foot, Robot, RobotCollision, RobotDescription};
use biped_dynamics::urdf::srdf::{load_srdf_file, Srdf};
use biped_dynamics::urdf::{load_file, PackagePath, ResolveError, UrdfModel, UrdfOptions};
use biped_ssv::CollisionModel;
use nalgebra::{DVector, Vector3};
use std::path::{Path, PathBuf};
use toml::Spanned;

type Res<T> = Result<T, DescriptionError>;

/// What to do when a package cannot be found.
const INSTALL_HINT: &str = "; install example-robot-data (`source scripts/fetch_robots.sh` \
    exports ROBOTS) or add its robots folder to ROS_PACKAGE_PATH";

/// Parses `text` (the file `file` in folder `base`) and loads the robot.
pub(super) fn load_text(text: &str, file: &str, base: &Path, packages: &PackagePath) -> Res<Robot> {
    let loc = Locator { file, text };
    let raw: RawDescription = toml::from_str(text).map_err(|e| loc.toml(e))?;
    let find = |r: &Spanned<String>, field: &str| resolve(&loc, r, field, base, packages);
    let urdf_path = find(&raw.urdf, "urdf")?;
    let options = UrdfOptions {
        floating: raw.floating,
        ..UrdfOptions::default()
    };
    let urdf =
        load_file(&urdf_path, &options).map_err(|e| loc.referenced(raw.urdf.span(), "urdf", e))?;
    let srdf_path = raw.drives.srdf.as_ref().map(|s| find(s, "drives.srdf"));
    let srdf_path = srdf_path.transpose()?;
    let srdf = match (&srdf_path, &raw.drives.srdf) {
        (Some(p), Some(s)) => {
            Some(load_srdf_file(p).map_err(|e| loc.referenced(s.span(), "drives.srdf", e))?)
        }
        _ => None,
    };
    let names = Checker {
        loc: &loc,
        urdf: &urdf,
    };
    let feet = [
        names.foot(&raw.feet.left, "feet.left")?,
        names.foot(&raw.feet.right, "feet.right")?,
    ];
    let g = &raw.groups;
    let legs = [
        names.joints(&g.left_leg, "groups.left_leg", false)?,
        names.joints(&g.right_leg, "groups.right_leg", false)?,
    ];
    let arms = [
        names.joints(&g.left_arm, "groups.left_arm", false)?,
        names.joints(&g.right_arm, "groups.right_arm", false)?,
    ];
    let reducing = names.joints(&raw.momentum.reducing, "momentum.reducing", false)?;
    let producing = match &raw.momentum.producing {
        Some(p) => names.producing(p, &reducing)?,
        None => urdf
            .joints
            .iter()
            .map(|j| j.name.clone())
            .filter(|n| !reducing.contains(n))
            .collect(),
    };
    let comfort = names.comfort(&raw, srdf.as_ref())?;
    let collision_path = raw
        .collision
        .as_ref()
        .map(|c| find(&c.model, "collision.model"));
    let collision_path = collision_path.transpose()?;
    let collision = match (&raw.collision, &collision_path) {
        (Some(c), Some(path)) => Some(collision(&loc, c, path, &urdf)?),
        _ => None,
    };
    let description = RobotDescription {
        file: file.to_string(),
        name: raw.name.get_ref().clone(),
        urdf: urdf_path,
        floating: raw.floating,
        feet,
        legs,
        arms,
        reducing,
        producing,
        comfort_state: raw.comfort.srdf_state.as_ref().map(|s| s.get_ref().clone()),
        comfort_joints: (raw.comfort.joints.iter())
            .map(|(k, v)| (k.clone(), *v.get_ref()))
            .collect(),
        collision_model: collision_path,
        collision_pairs: collision_pairs(&raw.collision),
        collision_exclude: (raw.collision.iter())
            .flat_map(|c| c.exclude.iter().map(|p| p.get_ref().clone()))
            .collect(),
        srdf: srdf_path,
        armature: names.armature(&raw)?,
    };
    Ok(Robot {
        description,
        urdf,
        srdf,
        collision,
        comfort,
    })
}

/// The file a reference names (relative to `base`, or `package://` through `packages`).
fn resolve(
    loc: &Locator,
    reference: &Spanned<String>,
    field: &str,
    base: &Path,
    packages: &PackagePath,
) -> Res<PathBuf> {
    packages
        .resolve(reference.get_ref(), base)
        .map_err(|source| {
            let hint = match source {
                ResolveError::PackageNotFound { .. } => INSTALL_HINT.to_string(),
                _ => String::new(),
            };
            loc.referenced(
                reference.span(),
                field,
                ReferencedError::Resolve { source, hint },
            )
        })
}

/// The explicit pair list of `[collision]`, if any.
fn collision_pairs(c: &Option<RawCollision>) -> Option<Vec<[String; 2]>> {
    let pairs = c.as_ref()?.pairs.as_ref()?;
    Some(
        pairs
            .get_ref()
            .iter()
            .map(|p| p.get_ref().clone())
            .collect(),
    )
}

/// Loads the SSV model, binds its bodies to the URDF's, and applies the pair list.
fn collision(
    loc: &Locator,
    raw: &RawCollision,
    path: &Path,
    urdf: &UrdfModel,
) -> Res<RobotCollision> {
    let span = raw.model.span();
    let loaded = biped_ssv::format::load(path)
        .map_err(|e| loc.referenced(span.clone(), "collision.model", e))?;
    let mut model = loaded.model;
    let root = urdf.links.first().map(|l| l.link.as_str());
    let mut model_bodies = Vec::new();
    for name in model.bodies() {
        match urdf.model.body_id(name) {
            Some(b) => model_bodies.push(Some(b)),
            None if Some(name.as_str()) == root => model_bodies.push(None),
            None => {
                let reason = format!("collision-model body `{name}` is not a body of the URDF");
                return Err(loc.invalid(span, "collision.model", reason));
            }
        }
    }
    if raw.pairs.is_some() || !raw.exclude.is_empty() {
        model = with_pairs(loc, &model, raw)?;
    }
    Ok(RobotCollision {
        model,
        model_bodies,
    })
}

/// `model` with the pairs of `raw.pairs` (default: the model's own) less those of
/// `raw.exclude` (each of which must be among them).
fn with_pairs(loc: &Locator, model: &CollisionModel, raw: &RawCollision) -> Res<CollisionModel> {
    type Listed<'a> = Vec<((usize, usize), Option<&'a Spanned<[String; 2]>>)>;
    let segment = |pair: &Spanned<[String; 2]>, field: &str| -> Res<(usize, usize)> {
        let find = |name: &String| {
            model.segment_index(name).ok_or_else(|| {
                let reason = format!("`{name}` is not a segment of the collision model");
                loc.invalid(pair.span(), field, reason)
            })
        };
        let [a, b] = pair.get_ref();
        Ok((find(a)?, find(b)?))
    };
    let mut pairs: Listed = match &raw.pairs {
        Some(list) => (list.get_ref().iter())
            .map(|p| Ok((segment(p, "collision.pairs")?, Some(p))))
            .collect::<Res<_>>()?,
        None => model.pairs().iter().map(|p| ((p.a, p.b), None)).collect(),
    };
    for ex in &raw.exclude {
        let (a, b) = segment(ex, "collision.exclude")?;
        let before = pairs.len();
        pairs.retain(|&(p, _)| p != (a, b) && p != (b, a));
        if pairs.len() == before {
            let reason = "not a pair of the collision model (nothing to exclude)";
            return Err(loc.invalid(ex.span(), "collision.exclude", reason));
        }
    }
    let field = "collision.model";
    let rebuild = |e: biped_ssv::ModelError| loc.invalid(raw.model.span(), field, e.to_string());
    let mut out = CollisionModel::new(model.bodies().to_vec(), model.activation_distance())
        .map_err(rebuild)?;
    for (seg, &body) in model.segments().iter().zip(model.segment_bodies()) {
        out.add_segment(seg.clone(), body).map_err(rebuild)?;
    }
    for ((a, b), listed) in pairs {
        out.add_pair(a, b).map_err(|e| match listed {
            Some(p) => loc.invalid(p.span(), "collision.pairs", e.to_string()),
            None => rebuild(e),
        })?;
    }
    Ok(out)
}

/// Name checks against one URDF.
struct Checker<'a> {
    loc: &'a Locator<'a>,
    urdf: &'a UrdfModel,
}

impl Checker<'_> {
    /// Errors unless `name` is a movable joint of the URDF.
    fn joint(&self, name: &Spanned<String>, field: &str) -> Res<String> {
        let n = name.get_ref();
        if self.urdf.joints.iter().any(|j| &j.name == n) {
            Ok(n.clone())
        } else {
            let reason = format!("`{n}` is not a movable joint of the URDF");
            Err(self.loc.invalid(name.span(), field, reason))
        }
    }

    /// A list of joints (non-empty unless `may_be_empty`).
    fn joints(&self, list: &Names, field: &str, may_be_empty: bool) -> Res<Vec<String>> {
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
    fn producing(&self, list: &Names, reducing: &[String]) -> Res<Vec<String>> {
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
    fn foot(&self, raw: &RawFoot, field: &str) -> Res<Foot> {
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
    fn comfort(&self, raw: &RawDescription, srdf: Option<&Srdf>) -> Res<DVector<f64>> {
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
    fn armature(&self, raw: &RawDescription) -> Res<Vec<(String, f64)>> {
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
