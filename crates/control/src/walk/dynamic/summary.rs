//! Time series and summary (verdict) of a dynamic walk.

use super::reference::JointReference;
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
    /// Vertical contact force on `[left, right]` foot \[N].
    pub foot_fz: Vec<[f64; 2]>,
    /// Vertical ground torque on `[left, right]` foot about its sole point \[N m] (the foot
    /// F/T sensor's wrench, world axes).
    pub tau_z: Vec<[f64; 2]>,
    /// Largest joint tracking error `max_j |q_ref - q|` \[rad].
    pub tracking_error: Vec<f64>,
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
            tracking_error: Vec::with_capacity(n),
        }
    }
}

/// Summary of a dynamic walk (the `"dynamic"` entry of `summary.json`; SI units).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
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
}

impl DynamicWalkSummary {
    /// Summary of series `s` against reference `r` with the criteria of `p`.
    pub fn evaluate(
        s: &DynamicWalkSeries,
        r: &JointReference,
        p: &DynamicWalkParams,
        (wall_time, rhs_evaluations): (f64, u64),
        fell_at: Option<f64>,
    ) -> Self {
        let first_last = |v: &[f64]| match (v.first(), v.last()) {
            (Some(a), Some(b)) => b - a,
            _ => 0.0,
        };
        let xs: Vec<f64> = s.base.iter().map(|b| b[0]).collect();
        let planned: Vec<f64> = r.base.iter().map(|b| b.x).collect();
        let (distance, planned_distance) = (first_last(&xs), first_last(&planned));
        let progress = if planned_distance.abs() > 1e-9 {
            distance / planned_distance
        } else {
            1.0
        };
        let max = |v: &mut dyn Iterator<Item = f64>| v.fold(0.0_f64, f64::max);
        let sim_time = s.t.last().copied().unwrap_or(0.0);
        let peak_tau = s
            .tau_z
            .iter()
            .flatten()
            .zip(s.foot_fz.iter().flatten())
            .filter(|(_, fz)| **fz > 1.0)
            .map(|(t, _)| t.abs());
        Self {
            walked: fell_at.is_none() && progress >= p.min_progress,
            fell_at,
            distance,
            planned_distance,
            progress,
            max_tilt: max(&mut s.tilt.iter().copied()),
            min_base_height: s.base.iter().map(|b| b[2]).fold(f64::INFINITY, f64::min),
            max_tracking_error: max(&mut s.tracking_error.iter().copied()),
            peak_abs_tau_z: max(&mut peak_tau.into_iter()),
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
        }
    }
}
