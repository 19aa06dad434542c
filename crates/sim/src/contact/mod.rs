//! Foot-ground contact (the contact layer of Table 2.3): compliant point contacts on
//! each foot sole against flat ground, a nonlinear spring-damper normal law and regularised
//! Coulomb friction with two elastic tangential states per point ([`law`]).
//!
//! Entries and sides: each entry of the set ([`FootSpec`]) is one body with its points, so its
//! wrench is the exact ground wrench on that body. A foot whose toe segment is a body of its
//! own has two entries, the toe a part of the foot (`part_of`); the side wrench
//! ([`ContactOutput::sides`], [`FootWrench::with_part`]) sums the toe into the foot about the
//! foot's sole reference point: what a consumer asking for "the wrench on the left foot" wants.
//!
//! Deviation from Table 2.3, documented: the thesis counts 3 contact-layer states per point
//! (48 for 16 points). Our normal law is algebraic in the penetration and its rate, so only
//! the two tangential bristle deflections are states: 2 per point, 32 for the 16 sole points
//! (52 with Lola's toes, [`crate::plant::PlantConfig::toe_contacts`]: 5 points per foot, 8 per toe).
//!
//! Forces are computed between the two phases of forward dynamics from the foot poses and
//! velocities of its kinematics pass ([`ContactSet::evaluate_from`]), so a right-hand side
//! runs one kinematics pass; without a dynamics call (sensor outputs, energy, lowest point)
//! each foot's own joint chain ([`chain::BodyChain`]) gives them instead.
//!
//! Stiffness and the 1 ms RK4 step. RK4 is stable for `h lambda` on the
//! negative real axis down to -2.78 and for oscillations up to `h omega ~ 2.8`. The defaults
//! (per point 2e5 N/m, normal 400 N s/m, tangential 200 N s/m; 8 sole points per foot, or 5 and
//! 8 on the toe) give Lola's foot, whose joint-space inertia includes the reflected rotor inertias,
//! vertical and tilt modes with `h |lambda| <= ~1` at h = 1 ms; the bristle relaxation
//! `d_t / k_t = 1 ms` gives `h / tau = 1`. The fastest mode of the standing robot is the feet's
//! roll about the ankle adduction axes, damped by the bristles 9 cm below the axis and by the
//! drives' smoothed friction: its eigenvalue (of the right-hand side's Jacobian, by finite
//! differences) gives `h |lambda|` = 2.32 with the toe points and 2.10 without; a 400 N s/m
//! bristle damper would give 3.46 with toes (unstable at 1 ms) and 2.63 without. The static
//! penetration standing is ~0.1-0.2 mm. Lighter feet without rotor
//! inertia (URDF robots) need softer points: keep `8 d / m_foot` and `sqrt(8 k / m_foot)`
//! below ~2000 1/s (see `tests/sim_urdf.rs` for the G1: 5e4 N/m, 100 N s/m).
//! The normal damping fades in over `damping_depth` = 0.1 mm so the force is continuous at
//! touch-down and never pulls (clamped at 0).

pub mod chain;
mod forces;
pub mod law;
mod side;

pub use chain::{BodyChain, BodyState};
pub use law::ContactParams;

use crate::error::SimError;
use biped_dynamics::{BodyId, Model};
use nalgebra::Vector3;

/// One entry of the contact set: a foot, or a part of a foot on its own body (a toe
/// segment), with its contact points.
#[derive(Debug, Clone, PartialEq)]
pub struct FootSpec {
    /// Name used in signals ("left", "right", "left_toe", ...).
    pub name: String,
    /// Body the sole belongs to.
    pub body: String,
    /// Contact points in the body frame.
    pub points: Vec<Vector3<f64>>,
    /// Sole reference point in the body frame (foot wrench torques are about it).
    pub reference: Vector3<f64>,
    /// Name of the foot entry this entry is a part of (a toe: summed into that foot's side
    /// wrench, [`ContactOutput::sides`]); `None` for a foot.
    pub part_of: Option<String>,
}

/// 8 points of a rectangular sole: the 4 corners and the 4 edge midpoints of the rectangle of
/// `length` (body x) by `width` (body y) centred at `center` (body frame, sole height).
pub fn sole_rectangle(center: Vector3<f64>, length: f64, width: f64) -> Vec<Vector3<f64>> {
    let (a, b) = (0.5 * length, 0.5 * width);
    [
        (a, b),
        (a, 0.0),
        (a, -b),
        (0.0, -b),
        (-a, -b),
        (-a, 0.0),
        (-a, b),
        (0.0, b),
    ]
    .iter()
    .map(|&(x, y)| center + Vector3::new(x, y, 0.0))
    .collect()
}

/// Total ground wrench on one contact entry (or one side, [`ContactOutput::sides`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FootWrench {
    /// Total contact force (world).
    pub force: Vector3<f64>,
    /// Moment about the sole reference point (world axes); `torque.z` is the vertical torque.
    pub torque: Vector3<f64>,
    /// The sole reference point the moment is taken about (world).
    pub reference: Vector3<f64>,
    /// Centre of pressure of the normal forces on the ground (world), if any contact.
    pub cop: Option<Vector3<f64>>,
    /// Number of points in contact.
    pub points_in_contact: usize,
}

/// A contact entry with resolved body and chain.
#[derive(Debug, Clone)]
struct Foot {
    spec: FootSpec,
    body: BodyId,
    chain: BodyChain,
    /// First point index over all entries.
    first: usize,
}

/// Results of one contact evaluation (preallocated, overwritten each call).
#[derive(Debug, Clone, Default)]
pub struct ContactOutput {
    /// Force on each point (world), points of all entries in order.
    pub point_forces: Vec<Vector3<f64>>,
    /// Wrench per contact entry (feet and their parts, in the order of the specs; the exact
    /// per-body wrenches).
    pub feet: Vec<FootWrench>,
    /// Wrench per side: a foot with its parts summed in, torque about the foot's sole
    /// reference point ([`FootWrench::with_part`]); sides in the order of the feet
    /// ([`ContactSet::side_names`]).
    pub sides: Vec<FootWrench>,
    /// Pose and velocity of each entry's body.
    pub foot_states: Vec<BodyState>,
}

/// All contact entries with the contact law; state = 2 bristle deflections (world x, y) per
/// point.
#[derive(Debug, Clone)]
pub struct ContactSet {
    params: ContactParams,
    feet: Vec<Foot>,
    /// Per side (a foot entry with the entries that are parts of it): entry indices, the foot
    /// first.
    sides: Vec<Vec<usize>>,
    npoints: usize,
}

impl ContactSet {
    /// Resolves the bodies of `specs` in `model`, groups the parts with their feet and
    /// validates the parameters.
    pub fn new(model: &Model, params: ContactParams, specs: &[FootSpec]) -> Result<Self, SimError> {
        params.validate()?;
        let mut feet = Vec::with_capacity(specs.len());
        let mut first = 0;
        for spec in specs {
            let body = model.body_id(&spec.body).ok_or_else(|| SimError::Unknown {
                kind: "foot body",
                name: spec.body.clone(),
            })?;
            let finite = spec
                .points
                .iter()
                .chain([&spec.reference])
                .all(|p| p.iter().all(|x| x.is_finite()));
            if spec.points.is_empty() || !finite {
                return Err(SimError::InvalidParameter {
                    what: format!("foot `{}` points", spec.name),
                    reason: "need at least one point, all finite".into(),
                });
            }
            let chain = BodyChain::new(model, body)?;
            feet.push(Foot {
                spec: spec.clone(),
                body,
                chain,
                first,
            });
            first += spec.points.len();
        }
        let sides = side::group(specs)?;
        Ok(Self {
            params,
            feet,
            sides,
            npoints: first,
        })
    }

    /// The contact parameters.
    pub fn params(&self) -> &ContactParams {
        &self.params
    }

    /// The entry specifications (feet and their parts).
    pub fn specs(&self) -> impl Iterator<Item = &FootSpec> {
        self.feet.iter().map(|f| &f.spec)
    }

    /// Body ids of the entries (feet and their parts).
    pub fn bodies(&self) -> impl Iterator<Item = BodyId> + '_ {
        self.feet.iter().map(|f| f.body)
    }

    /// Number of contact entries (feet and their parts).
    pub fn nfeet(&self) -> usize {
        self.feet.len()
    }

    /// Total number of contact points.
    pub fn npoints(&self) -> usize {
        self.npoints
    }

    /// Number of contact-layer states (2 per point).
    pub fn nstates(&self) -> usize {
        2 * self.npoints
    }

    /// Output buffers sized for this set.
    pub fn output(&self) -> ContactOutput {
        ContactOutput {
            point_forces: vec![Vector3::zeros(); self.npoints],
            feet: vec![FootWrench::default(); self.feet.len()],
            sides: vec![FootWrench::default(); self.sides.len()],
            foot_states: vec![BodyState::identity(); self.feet.len()],
        }
    }
}

impl ContactSet {
    /// Elastic energy stored in the contact springs at `(q, v)` with bristle states `s`.
    pub fn potential(&self, q: &[f64], v: &[f64], s: &[f64]) -> f64 {
        let p = &self.params;
        let mut e = 0.5 * p.tangential_stiffness * s.iter().map(|x| x * x).sum::<f64>();
        for foot in &self.feet {
            let st = foot.chain.eval(q, v);
            for c in &foot.spec.points {
                let delta = p.ground_height - (st.pos + st.rot * c).z;
                if delta > 0.0 {
                    e += p.stiffness * delta.powf(p.exponent + 1.0) / (p.exponent + 1.0);
                }
            }
        }
        e
    }
}

impl ContactSet {
    /// Height of the lowest contact point at `q` (`nv` = length of the velocity vector).
    pub fn lowest_point(&self, q: &[f64], nv: usize) -> f64 {
        let v = vec![0.0; nv];
        let mut low = f64::INFINITY;
        for foot in &self.feet {
            let st = foot.chain.eval(q, &v);
            for c in &foot.spec.points {
                low = low.min(st.point(c).0.z);
            }
        }
        low
    }
}
