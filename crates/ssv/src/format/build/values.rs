//! Values of a model file: SSVs (with mirror copies), index lists, mirror planes and poses.

use super::*;

pub(super) fn parse_plane(plane: &Spanned<String>, field: &str, loc: &Locator) -> Res<MirrorPlane> {
    plane
        .get_ref()
        .parse::<MirrorPlane>()
        .map_err(|e| loc.at(plane.span(), field.to_string(), e))
}

pub(super) fn build_indices(
    keep: &Spanned<Vec<Spanned<i64>>>,
    field: &str,
    loc: &Locator,
) -> Res<Vec<usize>> {
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
pub(super) fn build_ssvs(list: &[Spanned<RawSsv>], field: &str, loc: &Locator) -> Res<Vec<Ssv>> {
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

pub(super) fn build_ssv(entry: &Spanned<RawSsv>, field: &str, loc: &Locator) -> Res<Ssv> {
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

/// One pose per body, in body order; every body must be listed.
pub(super) fn build_pose(
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

pub(super) fn body_pose(raw: &RawPose, field: &str, loc: &Locator) -> Res<Isometry3<f64>> {
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
