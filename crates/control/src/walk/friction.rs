//! Friction check of a planned walk: can the ground supply the wrench the motion needs?
//!
//! The ground wrench (force `f`, moment `m` about a point on the ground) of a cycle comes from
//! the inverse dynamics ([`super::evaluate`]). Its centre of pressure (the ZMP) is the ground
//! point about which the horizontal moment vanishes; about it the ground must supply the
//! tangential force `f_t = (f_x, f_y)` and the free moment `tau_n` about the vertical. For a
//! support area with uniform pressure and Coulomb coefficient `mu`, pure sliding needs
//! `|f_t| = mu f_z` and pure spinning `|tau_n| = mu f_z rho` with `rho` the mean distance of
//! the support from the centre of rotation. Combined loads are checked against the ellipsoid
//! through both (the usual approximation of the limit surface of a planar contact):
//!
//! `usage = sqrt((|f_t| / (mu f_z))^2 + (tau_n / (mu f_z rho))^2)`, kept while `usage <= 1`.
//!
//! The support is sampled per foot from the pattern's contact state: the flat sole rectangle
//! with its toe segment, the toe segment alone in toe-off, the heel edge at heel strike.

use crate::pattern::{Contact, FootGeometry, FootState};
use nalgebra::{Vector2, Vector3};

/// Sample points per support rectangle along x and y (midpoint rule).
const GRID: (usize, usize) = (10, 6);

/// What the ground must supply in one cycle and how much of the friction it uses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionLoad {
    /// Normal force `f_z` \[N] (negative: the motion would need the ground to pull).
    pub normal: f64,
    /// Tangential force `|f_t|` \[N].
    pub tangential: f64,
    /// Free moment about the vertical through the centre of pressure \[N m].
    pub free_moment: f64,
    /// Centre of pressure (ZMP) on the ground \[m].
    pub cop: Vector2<f64>,
    /// Mean distance of the support from the centre of pressure \[m].
    pub radius: f64,
    /// Share of the friction limit used (see the module docs); infinite without support or
    /// with `f_z <= 0`.
    pub usage: f64,
}

/// The ground support of a cycle, sampled as points on the ground (world x, y).
#[derive(Debug, Clone, Default)]
pub struct Support {
    points: Vec<Vector2<f64>>,
}

impl Support {
    /// Empty support with room for two feet.
    pub fn new() -> Self {
        Self {
            points: Vec::with_capacity(2 * GRID.0 * GRID.1),
        }
    }

    /// Resamples the support of `feet` (planned sole frames) with sole geometry `g`.
    pub fn update(&mut self, feet: &[FootState; 2], g: &FootGeometry) {
        self.points.clear();
        for foot in feet {
            self.add_foot(foot, g);
        }
    }

    /// The sample points.
    pub fn points(&self) -> &[Vector2<f64>] {
        &self.points
    }

    /// Adds the part of one foot that touches the ground in its contact state.
    fn add_foot(&mut self, foot: &FootState, g: &FootGeometry) {
        let origin = foot.pose.translation.vector;
        let forward = foot.pose.rotation * Vector3::x();
        let heading = Vector2::new(forward.x, forward.y);
        let heading = match heading.try_normalize(1e-9) {
            Some(h) => h,
            None => return,
        };
        let left = Vector2::new(-heading.y, heading.x);
        let base = Vector2::new(origin.x, origin.y);
        let (x0, x1) = match foot.contact {
            // The toe segment lies flat ahead of the sole's front edge.
            Contact::Flat => (-g.back, g.front + g.toe_length),
            // The toe segment lies flat ahead of the toe axis, whose ground point is where the
            // sole's front edge would be with the foot flat.
            Contact::Toe => (0.0, g.toe_length),
            Contact::Heel => (-g.back, -g.back),
            Contact::Swing => return,
        };
        // Toe-off: the sole frame is pitched about the toe axis; its ground point lies
        // `front` ahead of the sole origin along the heading, measured on the ground.
        let start = match foot.contact {
            Contact::Toe => toe_axis_ground(foot, g),
            _ => base,
        };
        let nx = if x0 == x1 { 1 } else { GRID.0 };
        for i in 0..nx {
            let x = x0 + (x1 - x0) * (i as f64 + 0.5) / nx as f64;
            for j in 0..GRID.1 {
                let y = g.half_width * (2.0 * (j as f64 + 0.5) / GRID.1 as f64 - 1.0);
                self.points.push(start + heading * x + left * y);
            }
        }
    }

    /// Friction usage of the ground wrench `(f, m)` (world axes, moment about `point`) with
    /// Coulomb coefficient `mu`; the ground is the plane `z = 0` of the pattern.
    pub fn load(
        &self,
        f: &Vector3<f64>,
        m: &Vector3<f64>,
        point: &Vector3<f64>,
        mu: f64,
    ) -> FrictionLoad {
        let normal = f.z;
        let tangential = f.xy().norm();
        // Moment about the ground point below `point`, then the centre of pressure: the
        // ground point c with (m + (point - c) x f)_xy = 0.
        let m = m + Vector3::new(0.0, 0.0, point.z).cross(f);
        let cop = match normal.abs() > 1e-9 {
            true => Vector2::new(point.x - m.y / normal, point.y + m.x / normal),
            false => point.xy(),
        };
        let d = Vector3::new(point.x - cop.x, point.y - cop.y, 0.0);
        let free_moment = m.z + d.cross(f).z;
        let radius = match self.points.is_empty() {
            true => 0.0,
            false => {
                self.points.iter().map(|p| (p - cop).norm()).sum::<f64>() / self.points.len() as f64
            }
        };
        let usage = match normal > 0.0 && radius > 0.0 && mu > 0.0 {
            true => {
                let slide = tangential / (mu * normal);
                let spin = free_moment / (mu * normal * radius);
                slide.hypot(spin)
            }
            false => f64::INFINITY,
        };
        FrictionLoad {
            normal,
            tangential,
            free_moment,
            cop,
            radius,
            usage,
        }
    }
}

/// Ground point of the toe axis of a foot in toe-off (x, y).
fn toe_axis_ground(foot: &FootState, g: &FootGeometry) -> Vector2<f64> {
    let axis = foot.pose * nalgebra::Point3::new(g.front, 0.0, g.toe_height);
    Vector2::new(axis.x, axis.y)
}
