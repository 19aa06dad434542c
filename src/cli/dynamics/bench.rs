//! `biped bench dynamics`: median time of one forward-dynamics call per algorithm and per O(n)
//! pass (thesis 2.10, Figs. 2.19 and 2.21), on one model or over a range of Dill levels.

use super::source::{Loaded, ModelSource};
use super::CliResult;
use crate::cli::out::{errln, outln};
use biped_dynamics::dill::{dill, dill_test_state};
use biped_dynamics::{forward_dynamics, nearby_state, on, Algorithm, Data, Model};
use biped_robots::lola::{self, LolaType};
use nalgebra::DVector;
use rand::{Rng, SeedableRng};
use serde::Serialize;
use std::hint::black_box;
use std::process::ExitCode;
use std::time::{Duration, Instant};

/// Target duration of one timed batch.
const BATCH: Duration = Duration::from_millis(2);
/// Number of batches whose median is reported.
const BATCHES: usize = 31;
/// Upper bound of the time spent per measured function (slow models get fewer batches).
const BUDGET: Duration = Duration::from_millis(400);

/// Median run times of one model, in nanoseconds per call.
#[derive(Serialize)]
pub struct Timings {
    /// Dill level (range runs only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub n: Option<u32>,
    /// Number of velocity coordinates.
    pub nv: usize,
    /// O(n) algorithm, whole call.
    pub on: f64,
    /// CRBA + dense Cholesky.
    pub crba: f64,
    /// CRBA + sparse LTL.
    pub sparse: f64,
    /// O(n) first forward pass (kinematics).
    pub fw1: f64,
    /// O(n) backward pass (articulated inertias).
    pub bw: f64,
    /// O(n) second forward pass (accelerations).
    pub fw2: f64,
    /// Relative run time `eta(O(n^3)) = t_crba / t_on` (thesis 2.10.2, Table 2.6).
    pub eta_crba: f64,
    /// Relative run time `eta(sparse) = t_sparse / t_on`.
    pub eta_sparse: f64,
}

/// Median nanoseconds per call of `f`, after a warm-up that also sizes the batches.
pub fn median_ns(mut f: impl FnMut()) -> f64 {
    median_pair_ns(&mut f, &mut || {}).0
}

/// Times `f` and `f` followed by `g` in alternating batches (so both see the same machine
/// load) and returns the medians of `f` and of the per-pair difference, i.e. the time of `g`.
pub fn median_pair_ns(f: &mut dyn FnMut(), g: &mut dyn FnMut()) -> (f64, f64) {
    let mut reps: u32 = 1;
    let per_batch = loop {
        let e = batch(reps, f, g);
        if e >= BATCH || reps >= 1 << 24 {
            break e;
        }
        reps *= 2;
    };
    let batches = (BUDGET.as_secs_f64() / (2.0 * per_batch.as_secs_f64()).max(1e-9))
        .clamp(3.0, BATCHES as f64) as usize;
    let per_call = |d: Duration| d.as_nanos() as f64 / f64::from(reps);
    let (mut first, mut second): (Vec<f64>, Vec<f64>) = (0..batches)
        .map(|_| {
            let a = per_call(batch(reps, f, &mut || {}));
            let ab = per_call(batch(reps, f, g));
            (a, ab - a)
        })
        .unzip();
    (median(&mut first), median(&mut second).max(0.0))
}

/// Wall time of `reps` repetitions of `f` followed by `g`.
fn batch(reps: u32, f: &mut dyn FnMut(), g: &mut dyn FnMut()) -> Duration {
    let t = Instant::now();
    for _ in 0..reps {
        f();
        g();
    }
    t.elapsed()
}

/// Median of a non-empty sample.
fn median(samples: &mut [f64]) -> f64 {
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2]
}

/// A reproducible random state: uniform joint values in [-1, 1], unit quaternions for free joints.
pub fn random_state(model: &Model, seed: u64) -> (DVector<f64>, DVector<f64>, DVector<f64>) {
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let mut q = DVector::from_fn(model.nq(), |_, _| rng.random_range(-1.0..1.0));
    for j in model.joints().iter().filter(|j| j.nq == 7) {
        let mut quat = q.rows_mut(j.q_index + 3, 4);
        let norm = quat.norm();
        quat /= norm;
    }
    let v = DVector::from_fn(model.nv(), |_, _| rng.random_range(-1.0..1.0));
    let tau = DVector::from_fn(model.nv(), |_, _| rng.random_range(-1.0..1.0));
    (q, v, tau)
}

/// Times every algorithm and O(n) pass on one model, alternating between the state and a
/// [`nearby_state`] so that every call does the whole work (a repeated state would reuse the
/// forward-dynamics kinematics).
pub fn time_model(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
    tau: &DVector<f64>,
) -> Result<Timings, Box<dyn std::error::Error>> {
    let states = two_states(model, q, v)?;
    let mut data = Data::new(model);
    let mut algo = |a: Algorithm| -> Result<f64, Box<dyn std::error::Error>> {
        forward_dynamics(model, &mut data, q, v, tau, None, a)?;
        let mut k = 0;
        Ok(median_ns(|| {
            k ^= 1;
            let (q, v) = &states[k];
            black_box(forward_dynamics(model, &mut data, q, v, tau, None, a).is_ok());
        }))
    };
    let (on_ns, crba, sparse) = (
        algo(Algorithm::On)?,
        algo(Algorithm::Crba)?,
        algo(Algorithm::Sparse)?,
    );
    let (fw1, bw, fw2) = time_passes(model, &states, tau)?;
    Ok(Timings {
        n: None,
        nv: model.nv(),
        on: on_ns,
        crba,
        sparse,
        fw1,
        bw,
        fw2,
        eta_crba: crba / on_ns,
        eta_sparse: sparse / on_ns,
    })
}

/// Two `(q, v)` states that timing loops alternate between.
type States = [(DVector<f64>, DVector<f64>); 2];

/// `(q, v)` and a [`nearby_state`] to alternate between in timing loops.
fn two_states(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> Result<States, Box<dyn std::error::Error>> {
    Ok([(q.clone(), v.clone()), nearby_state(model, q, v)?])
}

/// Times the three passes of the O(n) algorithm separately (alternating `states`). The
/// backward pass accumulates into the articulated inertias that the first pass resets, so it
/// is timed as the difference of `FW1 + BW` and `FW1` in alternating batches; the second
/// forward pass only reads the backward results and is timed alone.
fn time_passes(
    model: &Model,
    states: &States,
    tau: &DVector<f64>,
) -> Result<(f64, f64, f64), Box<dyn std::error::Error>> {
    let data = std::cell::RefCell::new(Data::new(model));
    let (q, v) = &states[0];
    forward_dynamics(
        model,
        &mut data.borrow_mut(),
        q,
        v,
        tau,
        None,
        Algorithm::On,
    )?;
    let mut k = 0;
    let (fw1, bw) = median_pair_ns(
        &mut || {
            k ^= 1;
            let (q, v) = &states[k];
            black_box(on::forward_pass_1(model, &mut data.borrow_mut(), q, v, None).is_ok());
        },
        &mut || {
            black_box(on::backward_pass(model, &mut data.borrow_mut(), tau).is_ok());
        },
    );
    let fw2 = median_ns(|| {
        black_box(on::forward_pass_2(model, &mut data.borrow_mut()).len());
    });
    Ok((fw1, bw, fw2))
}

/// `biped bench dynamics --urdf/--dill`: one model.
pub fn run_one(source: &ModelSource, json: bool) -> CliResult {
    let Loaded { model, label } = source.load()?;
    let (q, v, tau) = match source {
        ModelSource::Dill(_) => {
            let (q, v) = dill_test_state(&model);
            (q, v, DVector::zeros(model.nv()))
        }
        ModelSource::Lola(t) => lola_state(*t, 1)?,
        _ => random_state(&model, 1),
    };
    let t = time_model(&model, &q, &v, &tau)?;
    if json {
        outln!("{}", serde_json::to_string(&t)?)?;
    } else {
        outln!("{label}: nv = {}", t.nv)?;
        print_table(std::slice::from_ref(&t))?;
        if let ModelSource::Lola(kind) = source {
            print_lola(&model, *kind, &t)?;
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// A state `(q, v, tau)`.
type State = (DVector<f64>, DVector<f64>, DVector<f64>);

/// A reproducible Lola state with joints inside their (mechanism) ranges, random torques.
fn lola_state(kind: LolaType, seed: u64) -> Result<State, Box<dyn std::error::Error>> {
    let lm = lola::build(kind)?;
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let (q, v) = lm.random_state(&mut |a, b| rng.random_range(a..b));
    let tau = DVector::from_fn(lm.model.nv(), |_, _| rng.random_range(-1.0..1.0));
    Ok((q, v, tau))
}

/// The Lola lines of Table 2.6 / Table 2.4: sub-systems, sparsity, relative run times.
fn print_lola(model: &Model, kind: LolaType, t: &Timings) -> std::io::Result<()> {
    let s = lola::sparsity(model);
    let thesis = match kind {
        LolaType::Type2 => "0.94-1.16 / 0.90-1.13",
        LolaType::Type3 => "1.41-1.67 / 1.24-1.48",
    };
    outln!(
        "sub-systems {}, mass-matrix non-zeros {} of {} (alpha {:.3}, Table 2.4)",
        model.subsystems().len(),
        s.nonzero,
        s.dense,
        s.alpha
    )?;
    outln!(
        "eta(O(n^3)) = {:.3}, eta(sparse) = {:.3} (thesis Table 2.6: {thesis})",
        t.eta_crba,
        t.eta_sparse
    )?;
    Ok(())
}

/// `biped bench dynamics --dill-range A..B`: every level, a table or JSON array, and an SVG plot.
/// The range was validated when the option was parsed (`A <= B <= MAX_DILL_LEVEL`).
pub fn run_range(a: u32, b: u32, json: bool) -> CliResult {
    let mut rows = Vec::new();
    for n in a..=b {
        let model = dill(n)?;
        let (q, v) = dill_test_state(&model);
        let mut t = time_model(&model, &q, &v, &DVector::zeros(model.nv()))?;
        t.n = Some(n);
        rows.push(t);
    }
    let path = std::path::PathBuf::from(format!("out/dill_fd_runtime_{a}-{b}.svg"));
    super::plot::runtime_svg(&path, &rows)?;
    if json {
        outln!("{}", serde_json::to_string(&rows)?)?;
    } else {
        print_table(&rows)?;
    }
    errln!("plot: {}", path.display());
    Ok(ExitCode::SUCCESS)
}

/// Human-readable table, times in microseconds.
fn print_table(rows: &[Timings]) -> std::io::Result<()> {
    outln!(
        "{:>4} {:>6} {:>12} {:>12} {:>12} {:>10} {:>10} {:>10}",
        "n",
        "nv",
        "O(n) µs",
        "CRBA µs",
        "sparse µs",
        "FW1 µs",
        "BW µs",
        "FW2 µs"
    )?;
    for t in rows {
        let n = t.n.map_or("-".to_string(), |n| n.to_string());
        outln!(
            "{:>4} {:>6} {:>12.3} {:>12.3} {:>12.3} {:>10.3} {:>10.3} {:>10.3}",
            n,
            t.nv,
            t.on / 1e3,
            t.crba / 1e3,
            t.sparse / 1e3,
            t.fw1 / 1e3,
            t.bw / 1e3,
            t.fw2 / 1e3
        )?;
    }
    Ok(())
}
