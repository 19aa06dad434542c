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

fn parse_plane(plane: &Spanned<String>, field: &str, loc: &Locator) -> Res<MirrorPlane> {
    plane
        .get_ref()
        .parse::<MirrorPlane>()
        .map_err(|e| loc.at(plane.span(), field.to_string(), e))
}

fn build_indices(keep: &Spanned<Vec<Spanned<i64>>>, field: &str, loc: &Locator) -> Res<Vec<usize>> {
    keep.get_ref()
        .iter()
        .enumerate()
        .map(|(j, i)| {
            usize::try_from(*i.get_ref()).map_err(|_| {
                let kind = FormatErrorKind::NegativeIndex(*i.get_ref());
                loc.at(i.span(), format!("{field}[{j}]"), kind)
            })
        })
        .collect()
}

/// The SSV list; an entry with `mirror_copy` adds its mirror image right after it.
fn build_ssvs(list: &[Spanned<RawSsv>], field: &str, loc: &Locator) -> Res<Vec<Ssv>> {
    let mut out = Vec::with_capacity(list.len());
    for (j, entry) in list.iter().enumerate() {
        let f = format!("{field}.ssvs[{j}]");
        let ssv = build_ssv(entry, &f, loc)?;
        out.push(ssv);
        if let Some(plane) = &entry.get_ref().mirror_copy {
            let plane = parse_plane(plane, &format!("{f}.mirror_copy"), loc)?;
            out.push(plane.reflect_ssv(&ssv));
        }
    }
    Ok(out)
}

fn build_ssv(entry: &Spanned<RawSsv>, field: &str, loc: &Locator) -> Res<Ssv> {
    let raw = entry.get_ref();
    let r = *raw.radius.get_ref();
    let p = |a: &Point| Point3::from(a.0);
    let (result, key, span) = match (&raw.point, &raw.line, &raw.triangle) {
        (Some(v), None, None) => (
            Pss::new(p(v.get_ref()), r).map(Ssv::from),
            "point",
            v.span(),
        ),
        (None, Some(v), None) => {
            let [a, b] = &v.get_ref().0;
            (Lss::new(p(a), p(b), r).map(Ssv::from), "line", v.span())
        }
        (None, None, Some(v)) => {
            let [a, b, c] = &v.get_ref().0;
            (
                Tss::new(p(a), p(b), p(c), r).map(Ssv::from),
                "triangle",
                v.span(),
            )
        }
        _ => return Err(loc.at(entry.span(), field.to_string(), FormatErrorKind::SsvShape)),
    };
    result.map_err(|e| {
        let radius_fault = !r.is_finite() || r < 0.0;
        if radius_fault {
            loc.at(raw.radius.span(), format!("{field}.radius"), e)
        } else {
            loc.at(span, format!("{field}.{key}"), e)
        }
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

/// One pose per body, in body order; every body must be listed.
fn build_pose(
    model: &CollisionModel,
    name: &str,
    table: &Spanned<BTreeMap<String, Spanned<RawPose>>>,
    loc: &Locator,
) -> Res<Vec<Isometry3<f64>>> {
    let field = format!("pose.{name}");
    let mut poses = vec![None; model.bodies().len()];
    for (body, raw) in table.get_ref() {
        let f = format!("{field}.{body}");
        let index = model.body_index(body).ok_or_else(|| {
            loc.at(
                raw.span(),
                f.clone(),
                FormatErrorKind::UnknownBody(body.clone()),
            )
        })?;
        poses[index] = Some(body_pose(raw.get_ref(), &f, loc)?);
    }
    poses
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            p.ok_or_else(|| {
                let kind = FormatErrorKind::PoseLacksBody(model.bodies()[i].clone());
                loc.at(table.span(), field.clone(), kind)
            })
        })
        .collect()
}

fn body_pose(raw: &RawPose, field: &str, loc: &Locator) -> Res<Isometry3<f64>> {
    let check = |v: &Spanned<Point>, key: &str| -> Res<[f64; 3]> {
        match v.get_ref().0.iter().find(|x| !x.is_finite()) {
            Some(&x) => Err(loc.at(
                v.span(),
                format!("{field}.{key}"),
                FormatErrorKind::NonFinitePose(x),
            )),
            None => Ok(v.get_ref().0),
        }
    };
    let [x, y, z] = check(&raw.position, "position")?;
    let [roll, pitch, yaw] = match &raw.rpy {
        Some(rpy) => check(rpy, "rpy")?,
        None => [0.0; 3],
    };
    Ok(Isometry3::from_parts(
        Translation3::new(x, y, z),
        UnitQuaternion::from_euler_angles(roll, pitch, yaw),
    ))
}
