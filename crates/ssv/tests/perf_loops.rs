//! Fixed-input loops for instruction counting under `valgrind --tool=callgrind` (the machine
//! load makes wall-clock medians noisy). Ignored by default; run e.g.
//! `PERF_FN=tt PERF_N=10000 valgrind --tool=callgrind <test binary> --ignored --exact perf_loop`
//! and subtract the count of a `PERF_N=0` run: the difference / N is instructions per call.
//! Build the binary with the bench settings (`cargo test --release -p biped_ssv --test
//! perf_loops --no-run`; the test profile is not LTO-optimised) and use N >= 10000.
//! `PERF_FN=model_closest|model_within` times the humanoid model update instead.

use biped_ssv::distance::{ll, lt, pl, pp, pt, tt};
use biped_ssv::{format, DistanceResult, Lss, PairQuery, Pss, Tss};
use nalgebra::Point3;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use std::hint::black_box;

const POOL: usize = 1024;

fn point(rng: &mut StdRng) -> Point3<f64> {
    Point3::new(rng.random(), rng.random(), rng.random())
}

fn radius(rng: &mut StdRng) -> f64 {
    rng.random_range(0.01..0.1)
}

fn pss(rng: &mut StdRng) -> Pss {
    Pss::new(point(rng), radius(rng)).unwrap()
}

fn lss(rng: &mut StdRng) -> Lss {
    Lss::new(point(rng), point(rng), radius(rng)).unwrap()
}

fn tss(rng: &mut StdRng) -> Tss {
    Tss::new(point(rng), point(rng), point(rng), radius(rng)).unwrap()
}

/// Runs `f` over `n` queries of a fixed random pool.
fn run<A, B>(
    n: usize,
    make_a: fn(&mut StdRng) -> A,
    make_b: fn(&mut StdRng) -> B,
    f: fn(&A, &B) -> DistanceResult,
) -> f64 {
    let mut rng = StdRng::seed_from_u64(69);
    let pool: Vec<(A, B)> = (0..POOL)
        .map(|_| (make_a(&mut rng), make_b(&mut rng)))
        .collect();
    let mut sum = 0.0;
    for k in 0..n {
        let (a, b) = &pool[k % POOL];
        sum += black_box(f(black_box(a), black_box(b))).distance;
    }
    sum
}

/// Runs `n` updates of the humanoid model in its first posture with the given policy.
fn run_model(n: usize, query: PairQuery) -> f64 {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/humanoid.toml");
    let loaded = format::load(path).unwrap();
    let mut model = loaded.model;
    model.set_pair_query(query);
    let poses = loaded.poses.into_iter().next().unwrap().1;
    let mut sum = 0.0;
    for _ in 0..n {
        model.update(black_box(&poses)).unwrap();
        sum += model
            .results()
            .iter()
            .filter_map(|r| r.distance())
            .sum::<f64>();
    }
    sum
}

#[test]
#[ignore = "instruction-count harness for callgrind"]
fn perf_loop() {
    let f = std::env::var("PERF_FN").unwrap_or_else(|_| "tt".into());
    let n: usize = std::env::var("PERF_N").map_or(1000, |s| s.parse().unwrap());
    let sum = match f.as_str() {
        "pp" => run(n, pss, pss, pp),
        "pl" => run(n, pss, lss, pl),
        "pt" => run(n, pss, tss, pt),
        "ll" => run(n, lss, lss, ll),
        "lt" => run(n, lss, tss, lt),
        "tt" => run(n, tss, tss, tt),
        "model_closest" => run_model(n, PairQuery::Closest),
        "model_within" => run_model(n, PairQuery::WithinActivation),
        other => panic!("unknown PERF_FN {other}"),
    };
    println!("{f} {n} {sum}");
}
