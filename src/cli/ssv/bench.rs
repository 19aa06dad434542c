//! `biped ssv bench`: median time of the six distance functions (thesis Table 6.9).

use crate::cli::out::outln;
use crate::cli::CliResult;
use biped_ssv::distance::{ll, lt, pl, pp, pt, tt};
use biped_ssv::{DistanceResult, Lss, Pss, Tss};
use nalgebra::Point3;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use std::hint::black_box;
use std::process::ExitCode;
use std::time::Instant;

/// Random queries per pool; the pool is cycled so inputs come from cache like in a control loop.
const POOL: usize = 1024;
/// Timed batches per function; the median batch is reported.
const BATCHES: usize = 301;

/// Relative run-times t_rel of thesis Table 6.9 (Lola's on-board PC), for comparison.
const THESIS_REL: [(&str, f64); 6] = [
    ("PP", 1.00),
    ("PL", 1.42),
    ("PT", 1.57),
    ("LL", 1.76),
    ("LT", 4.08),
    ("TT", 10.03),
];

fn point(rng: &mut StdRng) -> Point3<f64> {
    Point3::new(rng.random(), rng.random(), rng.random())
}

fn radius(rng: &mut StdRng) -> f64 {
    rng.random_range(0.01..0.1)
}

fn pss(rng: &mut StdRng) -> Pss {
    Pss::new(point(rng), radius(rng)).expect("finite random input")
}

fn lss(rng: &mut StdRng) -> Lss {
    Lss::new(point(rng), point(rng), radius(rng)).expect("finite random input")
}

fn tss(rng: &mut StdRng) -> Tss {
    Tss::new(point(rng), point(rng), point(rng), radius(rng)).expect("finite random input")
}

/// Median ns per call of `f` over a pool of random input pairs.
fn time_pairs<A, B>(
    rng: &mut StdRng,
    make_a: fn(&mut StdRng) -> A,
    make_b: fn(&mut StdRng) -> B,
    f: fn(&A, &B) -> DistanceResult,
) -> f64 {
    let pool: Vec<(A, B)> = (0..POOL).map(|_| (make_a(rng), make_b(rng))).collect();
    let batch = || {
        let start = Instant::now();
        for (a, b) in &pool {
            black_box(f(black_box(a), black_box(b)));
        }
        start.elapsed().as_nanos() as f64 / POOL as f64
    };
    for _ in 0..BATCHES / 10 {
        batch();
    }
    let mut times: Vec<f64> = (0..BATCHES).map(|_| batch()).collect();
    times.sort_by(f64::total_cmp);
    times[BATCHES / 2]
}

/// Median ns per query of PP, PL, PT, LL, LT, TT, in that order.
fn measure() -> [(&'static str, f64); 6] {
    let mut rng = StdRng::seed_from_u64(6_9);
    [
        ("PP", time_pairs(&mut rng, pss, pss, pp)),
        ("PL", time_pairs(&mut rng, pss, lss, pl)),
        ("PT", time_pairs(&mut rng, pss, tss, pt)),
        ("LL", time_pairs(&mut rng, lss, lss, ll)),
        ("LT", time_pairs(&mut rng, lss, tss, lt)),
        ("TT", time_pairs(&mut rng, tss, tss, tt)),
    ]
}

/// Run the benchmark and print the table (or JSON).
pub fn run(json: bool) -> CliResult {
    let rows = measure();
    if json {
        let obj: serde_json::Map<String, serde_json::Value> = rows
            .iter()
            .map(|(name, ns)| (name.to_string(), serde_json::json!(ns)))
            .collect();
        outln!("{}", serde_json::Value::Object(obj))?;
        return Ok(ExitCode::SUCCESS);
    }
    let pp_ns = rows[0].1;
    outln!("SSV distance functions: median over {BATCHES} batches of {POOL} random queries")?;
    outln!(
        "{:<6} {:>12} {:>10} {:>16}",
        "func",
        "abs [ns]",
        "rel [-]",
        "thesis rel [-]"
    )?;
    for ((name, ns), (_, thesis)) in rows.iter().zip(THESIS_REL) {
        outln!("{name:<6} {ns:>12.1} {:>10.2} {thesis:>16.2}", ns / pp_ns)?;
    }
    Ok(ExitCode::SUCCESS)
}
