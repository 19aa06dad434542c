//! Semantic checks and construction of a [`CollisionModel`] from a parsed file.

use super::error::{FormatError, FormatErrorKind, Locator};
use super::raw::{Point, RawFile, RawPose, RawSegment, RawSsv};
use super::LoadedModel;
use crate::model::CollisionModel;
use crate::primitives::{Lss, Pss, Ssv, Tss};
use crate::segment::{MirrorPlane, Segment};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion};
use std::collections::BTreeMap;
use toml::Spanned;

mod values;

use values::{build_indices, build_pose, build_ssvs, parse_plane};

type Res<T> = Result<T, FormatError>;

/// Builds the model and poses, checking every reference and value.
pub(super) fn build(raw: RawFile, loc: &Locator) -> Res<LoadedModel> {
    let d_a = &raw.activation_distance;
    let bodies: Vec<String> = raw.bodies.iter().map(|b| b.get_ref().clone()).collect();
    let mut model = CollisionModel::new(bodies, *d_a.get_ref()).map_err(|e| {
        let span = duplicate_body_span(&raw).unwrap_or(d_a.span());
        loc.at(span, model_field(&e), e)
    })?;
    for (k, seg) in raw.segment.iter().enumerate() {
        add_segment(&mut model, seg, k, loc)?;
    }
    for (k, pair) in raw.pairs.iter().enumerate() {
        let [a, b] = &pair.get_ref().0;
        add_pair(&mut model, a, b, &format!("pairs[{k}]"), loc)?;
    }
    for (k, pair) in raw.pair.iter().enumerate() {
        let p = pair.get_ref();
        add_pair(&mut model, &p.a, &p.b, &format!("pair[{k}]"), loc)?;
    }
    let mut poses = BTreeMap::new();
    for (name, table) in &raw.pose {
        poses.insert(name.clone(), build_pose(&model, name, table, loc)?);
    }
    Ok(LoadedModel { model, poses })
}

fn model_field(e: &crate::model::ModelError) -> &'static str {
    match e {
        crate::model::ModelError::DuplicateName(_) => "bodies",
        _ => "activation_distance",
    }
}

fn duplicate_body_span(raw: &RawFile) -> Option<std::ops::Range<usize>> {
    let b = &raw.bodies;
    (1..b.len())
        .find(|&k| b[..k].iter().any(|x| x.get_ref() == b[k].get_ref()))
        .map(|k| b[k].span())
}

fn add_segment(
    model: &mut CollisionModel,
    seg: &Spanned<RawSegment>,
    k: usize,
    loc: &Locator,
) -> Res<()> {
    let raw = seg.get_ref();
    let field = format!("segment[{k}]");
    let body = model.body_index(raw.body.get_ref()).ok_or_else(|| {
        let kind = FormatErrorKind::UnknownBody(raw.body.get_ref().clone());
        loc.at(raw.body.span(), format!("{field}.body"), kind)
    })?;
    let segment = segment_geometry(model, raw, &field, seg.span(), loc)?;
    model
        .add_segment(segment, body)
        .map_err(|e| loc.at(raw.name.span(), format!("{field}.name"), e))?;
    Ok(())
}

/// The segment's SSVs from exactly one source: `ssvs`, `mirror_of`, or `version_of`.
fn segment_geometry(
    model: &CollisionModel,
    raw: &RawSegment,
    field: &str,
    span: std::ops::Range<usize>,
    loc: &Locator,
) -> Res<Segment> {
    check_sources(raw, field, span.clone(), loc)?;
    let name = raw.name.get_ref().clone();
    if let Some(ssvs) = &raw.ssvs {
        let list = build_ssvs(ssvs.get_ref(), field, loc)?;
        return Segment::new(name, list)
            .map_err(|e| loc.at(ssvs.span(), format!("{field}.ssvs"), e));
    }
    if let Some(base) = &raw.mirror_of {
        let base_seg = lookup(model, base, &format!("{field}.mirror_of"), loc)?;
        let plane = raw.plane.as_ref().ok_or_else(|| {
            loc.at(
                base.span(),
                format!("{field}.plane"),
                FormatErrorKind::Missing("plane"),
            )
        })?;
        let plane = parse_plane(plane, &format!("{field}.plane"), loc)?;
        return Ok(base_seg.mirrored(name, plane));
    }
    let base = raw.version_of.as_ref().ok_or_else(|| {
        loc.at(
            span.clone(),
            field.to_string(),
            FormatErrorKind::SegmentSource,
        )
    })?;
    let base_seg = lookup(model, base, &format!("{field}.version_of"), loc)?;
    let keep = raw.keep.as_ref().ok_or_else(|| {
        loc.at(
            base.span(),
            format!("{field}.keep"),
            FormatErrorKind::Missing("keep"),
        )
    })?;
    let indices = build_indices(keep, &format!("{field}.keep"), loc)?;
    base_seg
        .version(name, &indices)
        .map_err(|e| loc.at(keep.span(), format!("{field}.keep"), e))
}

/// Exactly one geometry source, and companion keys only with their source.
fn check_sources(
    raw: &RawSegment,
    field: &str,
    span: std::ops::Range<usize>,
    loc: &Locator,
) -> Res<()> {
    let sources = [
        ("ssvs", raw.ssvs.as_ref().map(|s| s.span())),
        ("mirror_of", raw.mirror_of.as_ref().map(|s| s.span())),
        ("version_of", raw.version_of.as_ref().map(|s| s.span())),
    ];
    let mut present: Vec<_> = sources
        .iter()
        .filter_map(|(k, s)| s.clone().map(|s| (k, s)))
        .collect();
    present.sort_by_key(|(_, s)| s.start);
    match present.as_slice() {
        [] => return Err(loc.at(span, field.to_string(), FormatErrorKind::SegmentSource)),
        [_] => {}
        [_, (key, s), ..] => {
            let kind = FormatErrorKind::SegmentSource;
            return Err(loc.at(s.clone(), format!("{field}.{key}"), kind));
        }
    }
    let companions = [
        (
            "plane",
            "mirror_of",
            raw.plane.as_ref().map(|s| s.span()),
            raw.mirror_of.is_some(),
        ),
        (
            "keep",
            "version_of",
            raw.keep.as_ref().map(|s| s.span()),
            raw.version_of.is_some(),
        ),
    ];
    for (key, owner, s, has_owner) in companions {
        if let (Some(s), false) = (s, has_owner) {
            return Err(loc.at(
                s,
                format!("{field}.{key}"),
                FormatErrorKind::Unexpected(key, owner),
            ));
        }
    }
    Ok(())
}

fn lookup<'m>(
    model: &'m CollisionModel,
    name: &Spanned<String>,
    field: &str,
    loc: &Locator,
) -> Res<&'m Segment> {
    model
        .segment_index(name.get_ref())
        .map(|i| &model.segments()[i])
        .ok_or_else(|| {
            let kind = FormatErrorKind::UnknownSegment(name.get_ref().clone());
            loc.at(name.span(), field.to_string(), kind)
        })
}

fn add_pair(
    model: &mut CollisionModel,
    a: &Spanned<String>,
    b: &Spanned<String>,
    field: &str,
    loc: &Locator,
) -> Res<()> {
    let find = |s: &Spanned<String>, f: String| {
        model.segment_index(s.get_ref()).ok_or_else(|| {
            loc.at(
                s.span(),
                f,
                FormatErrorKind::UnknownSegment(s.get_ref().clone()),
            )
        })
    };
    let ia = find(a, format!("{field}[0]"))?;
    let ib = find(b, format!("{field}[1]"))?;
    model
        .add_pair(ia, ib)
        .map_err(|e| loc.at(a.span(), field.to_string(), e))?;
    Ok(())
}
