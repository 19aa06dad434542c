//! Writing a model back to TOML (explicit SSVs for every segment).

use super::exact::Exact;
use super::raw::{Point, RawFile, RawPose, RawSegment, RawSsv};
use crate::model::CollisionModel;
use crate::primitives::Ssv;
use nalgebra::{Isometry3, Point3};
use std::collections::BTreeMap;
use toml::Spanned;

fn sp<T>(value: T) -> Spanned<T> {
    Spanned::new(0..0, value)
}

fn arr(p: &Point3<f64>) -> Point {
    Exact([p.x, p.y, p.z])
}

fn raw_ssv(ssv: &Ssv) -> RawSsv {
    let v = ssv.vertices();
    let mut raw = RawSsv {
        point: None,
        line: None,
        triangle: None,
        radius: sp(ssv.radius()),
        mirror_copy: None,
    };
    match ssv {
        Ssv::Point(_) => raw.point = Some(sp(arr(&v[0]))),
        Ssv::Line(_) => raw.line = Some(sp(Exact([arr(&v[0]), arr(&v[1])]))),
        Ssv::Triangle(_) => raw.triangle = Some(sp(Exact([arr(&v[0]), arr(&v[1]), arr(&v[2])]))),
    }
    raw
}

fn raw_pose(pose: &Isometry3<f64>) -> RawPose {
    let t = pose.translation.vector;
    let (roll, pitch, yaw) = pose.rotation.euler_angles();
    RawPose {
        position: sp(Exact([t.x, t.y, t.z])),
        rpy: Some(sp(Exact([roll, pitch, yaw]))),
    }
}

/// The file image of `model` and named body poses.
pub(super) fn raw_file(
    model: &CollisionModel,
    poses: &BTreeMap<String, Vec<Isometry3<f64>>>,
) -> RawFile {
    let bodies = model.bodies();
    let segment = model
        .segments()
        .iter()
        .zip(model.segment_bodies())
        .map(|(s, &b)| {
            sp(RawSegment {
                name: sp(s.name().to_string()),
                body: sp(bodies[b].clone()),
                ssvs: Some(sp(s.ssvs().iter().map(|x| sp(raw_ssv(x))).collect())),
                mirror_of: None,
                plane: None,
                version_of: None,
                keep: None,
            })
        })
        .collect();
    let name = |i: usize| sp(model.segments()[i].name().to_string());
    let pairs = model
        .pairs()
        .iter()
        .map(|p| sp(Exact([name(p.a), name(p.b)])))
        .collect();
    let pose = poses
        .iter()
        .map(|(n, list)| {
            let table = bodies
                .iter()
                .zip(list)
                .map(|(b, p)| (b.clone(), sp(raw_pose(p))))
                .collect();
            (n.clone(), sp(table))
        })
        .collect();
    RawFile {
        activation_distance: sp(model.activation_distance()),
        bodies: bodies.iter().map(|b| sp(b.clone())).collect(),
        pairs,
        pair: Vec::new(),
        segment,
        pose,
    }
}
