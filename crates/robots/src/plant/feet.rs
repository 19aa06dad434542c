//! The contact entries of the Lola plant. Feet: the bodies `l_foot` / `r_foot` with 8 sole
//! points on the rectangle of the foot box, at the height of the sole markers `l_sole` /
//! `r_sole`; with [`biped_sim::plant::PlantConfig::toe_contacts`] (default) the toe segments `l_toe` /
//! `r_toe` are entries `left_toe` / `right_toe` of their own, parts of their feet, with the 8
//! points of the toe box's rectangle at the sole's height; the 3 points of the toe joint line
//! (the foot's front edge, the toe's rear edge) belong to the toe, so the foot keeps 5. The
//! boxes' edge lengths are recovered from their inertia (`a^2 = 6 (I_yy + I_zz - I_xx) / m`,
//! etc.), so they follow the parameter file.

use biped_dynamics::{BodyId, Model};
use biped_sim::contact::{sole_rectangle, FootSpec};
use biped_sim::SimError;
use nalgebra::{Point3, Vector3};

/// The feet `left`, `right` and, with `toes`, their toes `left_toe`, `right_toe`.
pub fn contact_entries(m: &Model, toes: bool) -> Result<Vec<FootSpec>, SimError> {
    let mut feet = [("left", "l_foot", "l_sole"), ("right", "r_foot", "r_sole")]
        .iter()
        .map(|(name, foot, sole)| lola_foot(m, name, foot, sole))
        .collect::<Result<Vec<_>, _>>()?;
    if toes {
        for (name, toe, k) in [("left_toe", "l_toe", 0), ("right_toe", "r_toe", 1)] {
            let toe = lola_toe(m, name, toe, &mut feet[k])?;
            feet.push(toe);
        }
    }
    Ok(feet)
}

/// Edge lengths of the solid box whose inertia the body carries.
fn box_size(m: &Model, body: BodyId) -> [f64; 3] {
    let Some(b) = m.body(body) else {
        return [0.0; 3];
    };
    let i = b.inertia().inertia_about_com();
    let mass = b.inertia().mass().max(1e-12);
    let (xx, yy, zz) = (i[(0, 0)], i[(1, 1)], i[(2, 2)]);
    [yy + zz - xx, xx + zz - yy, xx + yy - zz].map(|s| (6.0 * s / mass).max(0.0).sqrt())
}

/// A Lola foot: 8 points on the foot box's rectangle at the sole marker's height.
fn lola_foot(m: &Model, name: &str, foot: &str, sole: &str) -> Result<FootSpec, SimError> {
    let fb = m.body_id(foot).ok_or_else(|| unknown("foot body", foot))?;
    let sb = m
        .body_id(sole)
        .ok_or_else(|| unknown("sole marker", sole))?;
    let sole_z = m
        .body(sb)
        .map_or(0.0, |b| b.placement().translation.vector.z);
    let com = m.body(fb).map_or(Vector3::zeros(), |b| b.inertia().com());
    let [len, wid, _] = box_size(m, fb);
    let center = Vector3::new(com.x, com.y, sole_z);
    Ok(FootSpec {
        name: name.to_string(),
        body: foot.to_string(),
        points: sole_rectangle(center, len, wid),
        reference: center,
        part_of: None,
    })
}

/// A Lola toe segment, a part of `foot`: the 8 points of the toe box's rectangle at the height
/// of the foot's sole in the neutral pose (toe and sole flat together). The rectangle's rear
/// edge is the foot's front edge, the toe joint line: its points move from the foot to the toe
/// (no point twice). On the foot, 2 cm below the toe joint axis, they would sweep backwards
/// over the ground as the heel lifts about the axis in toe-off (a 3 mm scrape per step at
/// 0.1-0.35 m/s); on the toe, which stays flat, they stand still.
fn lola_toe(m: &Model, name: &str, toe: &str, foot: &mut FootSpec) -> Result<FootSpec, SimError> {
    let tb = m.body_id(toe).ok_or_else(|| unknown("toe body", toe))?;
    let b = m.body(tb).ok_or_else(|| unknown("toe body", toe))?;
    if b.parent().and_then(|p| m.body(p)).map(|p| p.name()) != Some(foot.body.as_str()) {
        return Err(SimError::InvalidParameter {
            what: format!("toe `{toe}`"),
            reason: format!("its parent is not the foot body `{}`", foot.body),
        });
    }
    // Toe frame <- foot frame at the neutral pose (joint angle 0).
    let placement = *b.placement();
    let to_toe = |p: &Vector3<f64>| (placement.inverse() * Point3::from(*p)).coords;
    let sole = to_toe(&foot.reference);
    let com = b.inertia().com();
    let [len, wid, _] = box_size(m, tb);
    let center = Vector3::new(com.x, com.y, sole.z);
    let points = sole_rectangle(center, len, wid);
    foot.points
        .retain(|c| points.iter().all(|p| (to_toe(c) - p).norm() > 1e-6));
    Ok(FootSpec {
        name: name.to_string(),
        body: toe.to_string(),
        points,
        reference: center,
        part_of: Some(foot.name.clone()),
    })
}

/// The error of a body `name` of kind `kind` the model lacks.
fn unknown(kind: &'static str, name: &str) -> SimError {
    SimError::Unknown {
        kind,
        name: name.to_string(),
    }
}
