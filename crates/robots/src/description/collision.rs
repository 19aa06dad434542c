//! The SSV collision model of a description: loaded, bound to the URDF's bodies, with the
//! description's pair list and exclusions applied.

use super::error::{DescriptionError, Locator};
use super::raw::RawCollision;
use super::RobotCollision;
use biped_dynamics::urdf::UrdfModel;
use biped_ssv::CollisionModel;
use std::path::Path;
use toml::Spanned;

type Res<T> = Result<T, DescriptionError>;

/// Loads the SSV model, binds its bodies to the URDF's, and applies the pair list.
pub(super) fn collision(
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
