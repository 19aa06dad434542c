//! Time series and summary (verdict) of a dynamic walk.

use super::flight::Flight;
use super::margins::SimulatedMargins;
use super::reference::JointReference;
use super::slip::{SideSample, SlipTracker};
use super::DynamicWalkParams;
use serde::Serialize;

/// Signals of a dynamic walk, one row per control cycle.
#[derive(Debug, Clone, Default)]
pub struct DynamicWalkSeries {
    /// Time \[s].
    pub t: Vec<f64>,
    /// Base (floating-joint origin) position \[m].
    pub base: Vec<[f64; 3]>,
    /// Planned base x of the kinematic walk \[m].
    pub planned_base_x: Vec<f64>,
    /// Trunk (base) tilt: angle between its z axis and the vertical \[rad].
    pub tilt: Vec<f64>,
    /// Vertical contact force on the `[left, right]` side (foot and toe) \[N].
    pub foot_fz: Vec<[f64; 2]>,
    /// Vertical ground torque on the `[left, right]` side (foot and toe) about the foot's sole
    /// point \[N m] (world axes).
    pub tau_z: Vec<[f64; 2]>,
    /// Vertical contact force on the `[left, right]` toe segment \[N].
    pub toe_fz: Vec<[f64; 2]>,
    /// Heel lift (pitch) of the `[left, right]` foot \[rad].
    pub heel_lift: Vec<[f64; 2]>,
    /// Friction use of the `[left, right]` side ([`super::slip`]).
    pub friction_usage: Vec<[f64; 2]>,
    /// Slip speed of the `[left, right]` side ([`super::slip`]) \[m/s].
    pub slip_speed: Vec<[f64; 2]>,
    /// Contact points of the `[left, right]` side touching the ground.
    pub points_in_contact: Vec<[usize; 2]>,
    /// Largest joint tracking error `max_j |q_ref - q|` \[rad].
    pub tracking_error: Vec<f64>,
    /// Names of the plant's position coordinates (`Model::q_names`).
    pub q_names: Vec<String>,
    /// The plant's positions, `q_names.len()` per cycle.
    pub q: Vec<f64>,
}

impl DynamicWalkSeries {
    /// Empty series with room for `n` cycles.
    pub fn with_capacity(n: usize) -> Self {
        Self {
            t: Vec::with_capacity(n),
            base: Vec::with_capacity(n),
            planned_base_x: Vec::with_capacity(n),
            tilt: Vec::with_capacity(n),
            foot_fz: Vec::with_capacity(n),
            tau_z: Vec::with_capacity(n),
            toe_fz: Vec::with_capacity(n),
            heel_lift: Vec::with_capacity(n),
            friction_usage: Vec::with_capacity(n),
            slip_speed: Vec::with_capacity(n),
            points_in_contact: Vec::with_capacity(n),
            tracking_error: Vec::with_capacity(n),
            q_names: Vec::new(),
            q: Vec::new(),
        }
    }
}

/// Summary of a dynamic walk (the `"dynamic"` entry of `summary.json`; SI units).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DynamicWalkSummary {
    /// No fall and enough progress.
    pub walked: bool,
    /// Time of the fall, if any \[s].
    pub fell_at: Option<f64>,
    /// Base x travelled (last minus first sample) \[m].
    pub distance: f64,
    /// Base x travel of the kinematic walk \[m].
    pub planned_distance: f64,
    /// `distance / planned_distance`.
    pub progress: f64,
    /// Largest trunk tilt \[rad].
    pub max_tilt: f64,
    /// Smallest base height \[m].
    pub min_base_height: f64,
    /// Largest joint tracking error \[rad].
    pub max_tracking_error: f64,
    /// Largest `|tau_z|` of a foot in contact \[N m].
    pub peak_abs_tau_z: f64,
    /// Simulated time \[s].
    pub sim_time: f64,
    /// Wall time of the simulation \[s].
    pub wall_time: f64,
    /// `sim_time / wall_time`.
    pub realtime_factor: f64,
    /// Right-hand-side evaluations of the plant.
    pub rhs_evaluations: u64,
    /// Reference samples with a joint clamped into its limits.
    pub clamped_samples: usize,
    /// Largest clamp of a reference angle \[rad].
    pub max_clamp: f64,
    /// Largest excess of a reference angle beyond its joint range \[rad] (the end stops hold
    /// the joint at the range, so the tracking error includes it).
    pub limit_excess: f64,
    /// The plant had end stops at the joint ranges ([`DynamicWalkParams::end_stops`]).
    pub end_stops: bool,
    /// The simulation diverged numerically (non-finite state, a mass matrix or mechanism loop
    /// that broke down, [`biped_sim::SimError::is_divergence`]); then `fell_at` is the time of
    /// the last finite sample and the series end there.
    pub diverged: bool,
    /// Largest friction use `|F_t| / (mu F_n)` of a side in contact ([`super::slip`]).
    pub max_friction_usage: f64,
    /// Largest slip speed (load-weighted sliding speed) of a side in contact \[m/s]
    /// ([`super::slip`]).
    pub max_slip_speed: f64,
    /// Largest sliding distance of a side within one contact \[m].
    pub max_slip_distance: f64,
    /// First time a side slid [`super::slip::SLIP_DISTANCE`] within one contact \[s].
    pub slip_at: Option<f64>,
    /// No side slipped (`slip_at` is `None`); independent of `walked`.
    pub friction_kept: bool,
    /// Time with both feet off the ground ([`super::flight`]) \[s].
    pub flight_time: f64,
    /// Longest phase with both feet off the ground \[s].
    pub longest_flight: f64,
    /// Start of the longest flight phase \[s].
    pub longest_flight_at: Option<f64>,
    /// Largest total vertical ground force \[N].
    pub peak_ground_force: f64,
    /// Mean total vertical ground force (the weight, over a whole walk) \[N].
    pub mean_ground_force: f64,
    /// No phase with both feet off the ground lasted longer than
    /// [`DynamicWalkParams::max_flight`] (the robot walked, it did not hop); independent of
    /// `walked`.
    pub contact_kept: bool,
    /// Smallest joint-limit margin of the simulated motion ([`super::margins`]) \[rad or m].
    pub min_joint_margin: f64,
    /// The joint of `min_joint_margin`.
    pub min_joint_margin_at: String,
    /// No joint left its range in the simulation (`min_joint_margin >= 0`).
    pub limits_kept: bool,
    /// Smallest SSV distance of the simulated poses ([`super::margins`]) \[m].
    pub min_distance: f64,
    /// The segment pair of `min_distance`.
    pub min_distance_at: String,
    /// No segments interpenetrated in the simulation (`min_distance > 0`).
    pub collision_free: bool,
}

impl DynamicWalkSummary {
    /// Summary of series `s` against reference `r` with the criteria of `p`.
    pub fn evaluate(
        s: &DynamicWalkSeries,
        r: &JointReference,
        p: &DynamicWalkParams,
        (wall_time, rhs_evaluations): (f64, u64),
        (fell_at, diverged): (Option<f64>, bool),
        margins: SimulatedMargins,
    ) -> Self {
        let (distance, planned_distance, progress) = progress(s, r);
        let max = |v: &mut dyn Iterator<Item = f64>| v.fold(0.0_f64, f64::max);
        let sim_time = s.t.last().copied().unwrap_or(0.0);
        let slip = slip_of(s, r);
        let flight = Flight::of(&s.t, r.dt, &s.points_in_contact, &s.foot_fz);
        Self {
            walked: fell_at.is_none() && progress >= p.min_progress,
            fell_at,
            distance,
            planned_distance,
            progress,
            max_tilt: max(&mut s.tilt.iter().copied()),
            min_base_height: s.base.iter().map(|b| b[2]).fold(f64::INFINITY, f64::min),
            max_tracking_error: max(&mut s.tracking_error.iter().copied()),
            peak_abs_tau_z: peak_tau(s),
            sim_time,
            wall_time,
            realtime_factor: if wall_time > 0.0 {
                sim_time / wall_time
            } else {
                0.0
            },
            rhs_evaluations,
            clamped_samples: r.clamped_samples,
            max_clamp: r.max_clamp,
            limit_excess: r.max_excess,
            end_stops: p.end_stops,
            diverged,
            max_friction_usage: max(&mut s.friction_usage.iter().flatten().copied()),
            max_slip_speed: slip.max_speed,
            max_slip_distance: slip.max_distance,
            slip_at: slip.slip_at,
            friction_kept: slip.slip_at.is_none(),
            flight_time: flight.total,
            longest_flight: flight.longest,
            longest_flight_at: flight.longest_at,
            peak_ground_force: flight.peak_force,
            mean_ground_force: flight.mean_force,
            contact_kept: flight.longest <= p.max_flight,
            limits_kept: margins.joint_margin >= 0.0,
            min_joint_margin: margins.joint_margin,
            min_joint_margin_at: margins.joint,
            collision_free: margins.distance > 0.0,
            min_distance: margins.distance,
            min_distance_at: margins.pair,
        }
    }
}

/// Distance walked, distance planned (base x, first to last sample) and their ratio.
fn progress(s: &DynamicWalkSeries, r: &JointReference) -> (f64, f64, f64) {
    let first_last = |v: &mut dyn Iterator<Item = f64>| {
        let first = v.next();
        match (first, v.last().or(first)) {
            (Some(a), Some(b)) => b - a,
            _ => 0.0,
        }
    };
    let distance = first_last(&mut s.base.iter().map(|b| b[0]));
    let planned = first_last(&mut r.base.iter().map(|b| b.x));
    let progress = match planned.abs() > 1e-9 {
        true => distance / planned,
        false => 1.0,
    };
    (distance, planned, progress)
}

/// Largest `|tau_z|` of a loaded foot (vertical force over 1 N).
fn peak_tau(s: &DynamicWalkSeries) -> f64 {
    let loaded = s.tau_z.iter().flatten().zip(s.foot_fz.iter().flatten());
    (loaded.filter(|(_, fz)| **fz > 1.0))
        .map(|(t, _)| t.abs())
        .fold(0.0_f64, f64::max)
}

/// The slip verdict over the series' sliding speeds and contact points.
fn slip_of(s: &DynamicWalkSeries, r: &JointReference) -> SlipTracker {
    let mut slip = SlipTracker::default();
    let samples = s.slip_speed.iter().zip(&s.points_in_contact);
    for (&t, (v, n)) in s.t.iter().zip(samples) {
        let side = |i: usize| SideSample {
            slip_speed: v[i],
            points: n[i],
            ..SideSample::default()
        };
        slip.add(t, r.dt, &[side(0), side(1)]);
    }
    slip
}
