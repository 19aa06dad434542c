//! Collision cost `H_C` and its gradient (5.4)-(5.9) from the SSV segment distances.

use super::error::AvoidanceError;
use super::law::RepulsiveLaw;
use biped_dynamics::{Data, Jacobians, Model};
use biped_ssv::segment::closest_ssv_pair;
use biped_ssv::{ClosestPair, CollisionModel, DistanceResult, PairQuery};
use nalgebra::{DVector, Isometry3, Vector3};

/// Parameters of the collision avoidance (the activation distance `d_a` is the model's).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AvoidanceParams {
    /// Repulsive law `g(d)` (5.11), (5.12) or (5.15).
    pub law: RepulsiveLaw,
}

/// What one gradient evaluation saw.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AvoidanceSummary {
    /// Smallest signed distance among the active pairs (`None`: every pair is at `>= d_a`;
    /// see [`CollisionAvoidance::global_minimum`] for the exact minimum).
    pub min_distance: Option<f64>,
    /// Index of that pair in the collision model's pair list.
    pub min_pair: Option<usize>,
    /// Number of pairs closer than `d_a` (those that contribute to the gradient).
    pub active: usize,
}

/// Self-collision avoidance: the cost `H_C = sum_k H(d_k)` over the segment pairs and its
/// gradient (5.9), evaluated with preallocated buffers (no allocation per call).
#[derive(Debug, Clone)]
pub struct CollisionAvoidance {
    collision: CollisionModel,
    /// Multibody body index of every collision-model body.
    bodies: Vec<usize>,
    /// Collision-model body poses of the last update.
    poses: Vec<Isometry3<f64>>,
    law: RepulsiveLaw,
    d_a: f64,
    nv: usize,
    nbodies: usize,
}

impl CollisionAvoidance {
    /// Binds `collision` (bodies by name) to `model`; switches it to
    /// [`PairQuery::WithinActivation`] so that only active pairs are computed.
    pub fn new(
        model: &Model,
        mut collision: CollisionModel,
        params: AvoidanceParams,
    ) -> Result<Self, AvoidanceError> {
        params.law.validate()?;
        let d_a = collision.activation_distance();
        if !(d_a.is_finite() && d_a > 0.0) {
            return Err(AvoidanceError::BadActivationDistance(d_a));
        }
        let bodies = collision
            .bodies()
            .iter()
            .map(|n| {
                model
                    .body_id(n)
                    .ok_or(AvoidanceError::UnknownBody(n.clone()))
            })
            .collect::<Result<Vec<_>, _>>()?;
        collision.set_pair_query(PairQuery::WithinActivation);
        Ok(Self {
            poses: vec![Isometry3::identity(); bodies.len()],
            bodies,
            collision,
            law: params.law,
            d_a,
            nv: model.nv(),
            nbodies: model.nbodies(),
        })
    }

    /// The collision model (segments at the last update, pairs, `d_a`).
    pub fn collision_model(&self) -> &CollisionModel {
        &self.collision
    }
    /// The repulsive law.
    pub fn law(&self) -> RepulsiveLaw {
        self.law
    }
    /// Activation distance `d_a`.
    pub fn activation_distance(&self) -> f64 {
        self.d_a
    }

    /// Moves the segments to the body poses in `data` and evaluates the pairs within `d_a`.
    pub fn update(&mut self, data: &Data) -> Result<(), AvoidanceError> {
        if data.nbodies() != self.nbodies {
            return Err(AvoidanceError::SizeMismatch {
                what: "data bodies",
                expected: self.nbodies,
                got: data.nbodies(),
            });
        }
        for (pose, &b) in self.poses.iter_mut().zip(&self.bodies) {
            *pose = data.body_pose(b);
        }
        self.collision.update(&self.poses)?;
        Ok(())
    }

    /// Cost `H_C = sum_k H(d_k)` at the body poses in `data` (updates the model first).
    pub fn cost(&mut self, data: &Data) -> Result<f64, AvoidanceError> {
        self.update(data)?;
        let (law, d_a) = (self.law, self.d_a);
        Ok(self
            .collision
            .results()
            .iter()
            .filter_map(|r| r.distance())
            .map(|d| law.potential(d, d_a))
            .sum())
    }

    /// Adds `grad_q H_C` (5.5)-(5.9), length `nv`, to `grad`. `data` and `jacobians` must hold
    /// the same configuration (e.g. after [`Jacobians::compute`], which also fills `data`).
    ///
    /// Per active pair (segments F = `a`, T = `b`): `dd/dq = (J_T^{p_T} - J_F^{p_F})^T n` at
    /// the closest points of the underlying primitives (5.4), with `n` the SSV result's unit
    /// normal from F to T. This equals (5.6) for `d > 0` and stays defined for touching or
    /// intersecting primitives (the SSV normal rule). Then `grad += -g(d) dd/dq`.
    pub fn gradient(
        &mut self,
        model: &Model,
        data: &Data,
        jacobians: &Jacobians,
        grad: &mut DVector<f64>,
    ) -> Result<AvoidanceSummary, AvoidanceError> {
        self.check_sizes(model, grad)?;
        self.update(data)?;
        let mut summary = AvoidanceSummary {
            min_distance: None,
            min_pair: None,
            active: 0,
        };
        for (k, (pair, result)) in self.collision.distances().enumerate() {
            let Some(c) = result.computed() else { continue };
            let r = &c.result;
            if r.distance >= self.d_a {
                continue;
            }
            summary.active += 1;
            let closer = match summary.min_distance {
                Some(m) => r.distance < m,
                None => true,
            };
            if closer {
                summary.min_distance = Some(r.distance);
                summary.min_pair = Some(k);
            }
            let g = self.law.g(r.distance, self.d_a);
            let segment_bodies = self.collision.segment_bodies();
            let body_f = self.bodies[segment_bodies[pair.a]];
            let body_t = self.bodies[segment_bodies[pair.b]];
            add_pair_gradient(data, jacobians, (body_f, body_t), r, g, grad)?;
        }
        Ok(summary)
    }

    /// The exact closest SSV pair over all segment pairs (regardless of `d_a`) at the poses of
    /// the last update: `(pair index, closest pair)`. For reporting, not for the 1 kHz loop.
    pub fn global_minimum(&self) -> Option<(usize, ClosestPair)> {
        let segments = self.collision.segments();
        self.collision
            .pairs()
            .iter()
            .map(|p| closest_ssv_pair(&segments[p.a], &segments[p.b]))
            .enumerate()
            .min_by(|x, y| x.1.result.distance.total_cmp(&y.1.result.distance))
    }

    fn check_sizes(&self, model: &Model, grad: &DVector<f64>) -> Result<(), AvoidanceError> {
        for (what, expected, got) in [
            ("model nv", self.nv, model.nv()),
            ("model bodies", self.nbodies, model.nbodies()),
            ("gradient length", self.nv, grad.len()),
        ] {
            if expected != got {
                return Err(AvoidanceError::SizeMismatch {
                    what,
                    expected,
                    got,
                });
            }
        }
        Ok(())
    }
}

/// `grad += -g (J_T^T n - J_F^T n)` for one pair, via `J^T f` products (no Jacobian formed).
fn add_pair_gradient(
    data: &Data,
    jacobians: &Jacobians,
    (body_f, body_t): (usize, usize),
    r: &DistanceResult,
    g: f64,
    grad: &mut DVector<f64>,
) -> Result<(), AvoidanceError> {
    let f = r.normal * g;
    let p_f = in_body(data, body_f, &r.closest_a.coords);
    let p_t = in_body(data, body_t, &r.closest_b.coords);
    jacobians.point_jacobian_tr_mul_add(body_f, &p_f, &f, grad)?;
    jacobians.point_jacobian_tr_mul_add(body_t, &p_t, &(-f), grad)?;
    Ok(())
}

/// World point `p` in the coordinates of body `body` (pose from `data`).
#[inline]
fn in_body(data: &Data, body: usize, p: &Vector3<f64>) -> Vector3<f64> {
    data.world_rot[body].tr_mul(&(p - data.world_pos[body]))
}
