//! The markers a recording shows besides the robot: centre of mass, ZMP and ground forces,
//! from the columns `biped walk` and `biped simulate` write.

use crate::recording::Recording;
use serde::Serialize;
use std::ops::Range;

/// A force drawn as an arrow, per frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ForceJson {
    /// Column prefix, e.g. `ground` (walk) or `left` / `right` (simulate).
    pub name: String,
    /// Point of application per frame (world, ground at z = 0).
    pub origin: Vec<[f64; 3]>,
    /// Force in N per frame (world axes).
    pub force: Vec<[f64; 3]>,
}

/// The markers of some frames.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Markers {
    /// `com.x/y/z` per frame.
    pub com: Option<Vec<[f64; 3]>>,
    /// `zmp.x/y` per frame, on the ground.
    pub zmp: Option<Vec<[f64; 3]>>,
    /// `P.fx/fy/fz` at `P.cop_x/cop_y` (simulate) or at the ZMP (the walk's `ground`).
    pub forces: Vec<ForceJson>,
}

fn columns<const N: usize>(rec: &Recording, names: [String; N]) -> Option<[usize; N]> {
    let mut out = [0; N];
    for (o, n) in out.iter_mut().zip(&names) {
        *o = rec.columns.iter().position(|c| c == n)?;
    }
    Some(out)
}

fn points<const N: usize>(
    rec: &Recording,
    cols: [usize; N],
    frames: &Range<usize>,
) -> Vec<[f64; 3]> {
    let rows = &rec.values[frames.clone()];
    rows.iter()
        .map(|r| {
            let mut p = [0.0; 3];
            for (x, &c) in p.iter_mut().zip(&cols) {
                *x = r[c];
            }
            p
        })
        .collect()
}

/// The markers of `frames` of `rec` (those whose columns it has).
pub fn markers(rec: &Recording, frames: Range<usize>) -> Markers {
    let named = |p: &str, k: &[&str]| k.iter().map(|k| format!("{p}.{k}")).collect::<Vec<_>>();
    let com = columns(rec, ["com.x", "com.y", "com.z"].map(String::from));
    let zmp = columns(rec, ["zmp.x", "zmp.y"].map(String::from));
    let mut m = Markers {
        com: com.map(|c| points(rec, c, &frames)),
        zmp: zmp.map(|c| points(rec, c, &frames)),
        forces: Vec::new(),
    };
    let prefixes = rec.columns.iter().filter_map(|c| c.strip_suffix(".fz"));
    for p in prefixes {
        let f = named(p, &["fx", "fy", "fz"]);
        let Some(fc) = columns(rec, [f[0].clone(), f[1].clone(), f[2].clone()]) else {
            continue;
        };
        let cop = named(p, &["cop_x", "cop_y"]);
        let origin = match columns(rec, [cop[0].clone(), cop[1].clone()]) {
            Some(c) => points(rec, c, &frames),
            None => match &m.zmp {
                Some(z) => z.clone(),
                None => continue,
            },
        };
        m.forces.push(ForceJson {
            name: p.to_string(),
            origin,
            force: points(rec, fc, &frames),
        });
    }
    m
}
