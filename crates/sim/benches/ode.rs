//! Criterion benchmarks of the integrators on a 100-dimensional linear system `z' = A z`
//! (dense `A`, one 100x100 mat-vec per evaluation) and on the cheap decay `z' = -z`, which
//! exposes the integrator's own overhead per step.

use biped_sim::ode::{Integrator, Method, OdeSystem, Settings};
use criterion::{criterion_group, criterion_main, Criterion};
use std::convert::Infallible;
use std::hint::black_box;

/// State dimension.
const N: usize = 100;

/// `z' = A z` with a fixed, stable, dense `A` (row-major).
struct Linear {
    a: Vec<f64>,
}

impl Linear {
    /// `A = -I + 0.05 * (S - S^T) + 0.001 * C` with deterministic pseudo-random `S`, `C`.
    fn new() -> Self {
        let r = |i: usize, j: usize| (((i * 7919 + j * 104729) % 1000) as f64) / 1000.0 - 0.5;
        let mut a = vec![0.0; N * N];
        for i in 0..N {
            for j in 0..N {
                let d = if i == j { -1.0 } else { 0.0 };
                a[i * N + j] = d + 0.05 * (r(i, j) - r(j, i)) + 0.001 * r(i + 3, j);
            }
        }
        Linear { a }
    }
}

impl OdeSystem for Linear {
    type Error = Infallible;
    fn dim(&self) -> usize {
        N
    }
    fn rhs(&mut self, _t: f64, z: &[f64], zd: &mut [f64]) -> Result<(), Infallible> {
        for (row, o) in self.a.chunks_exact(N).zip(zd.iter_mut()) {
            *o = row.iter().zip(z).map(|(a, x)| a * x).sum();
        }
        Ok(())
    }
}

/// `z' = -z`: negligible evaluation cost.
struct Decay;

impl OdeSystem for Decay {
    type Error = Infallible;
    fn dim(&self) -> usize {
        N
    }
    fn rhs(&mut self, _t: f64, z: &[f64], zd: &mut [f64]) -> Result<(), Infallible> {
        zd.iter_mut().zip(z).for_each(|(o, x)| *o = -x);
        Ok(())
    }
}

/// Benchmarks one step of `h` with `method` (Dopri5 forced to exactly one step).
fn one_step<S: OdeSystem>(c: &mut Criterion, name: &str, sys: &mut S, method: Method) {
    let h = 1e-3;
    let s = Settings {
        h,
        h_init: h,
        h_max: h,
        rtol: 1e3,
        atol: 1e3,
        ..Settings::default()
    };
    let mut integ = Integrator::new(method, N, s).expect("settings");
    let z0: Vec<f64> = (0..N).map(|i| (i as f64 * 0.37).sin()).collect();
    let mut z = z0.clone();
    c.bench_function(&format!("{method}_step/{name}{N}"), |b| {
        b.iter(|| {
            z.copy_from_slice(&z0);
            black_box(
                integ
                    .advance(sys, 0.0, h, black_box(&mut z))
                    .expect("integrates"),
            )
        })
    });
}

/// Benchmarks an adaptive Dopri5 control period of 10 ms at rtol = atol = 1e-6.
fn control_period<S: OdeSystem>(c: &mut Criterion, name: &str, sys: &mut S) {
    let mut integ =
        Integrator::new(Method::Dopri5, N, Settings::tolerances(1e-6, 1e-6)).expect("settings");
    let z0: Vec<f64> = (0..N).map(|i| (i as f64 * 0.37).sin()).collect();
    let mut z = z0.clone();
    let st = integ.advance(sys, 0.0, 0.01, &mut z).expect("warm-up");
    println!("dopri5 10 ms on {name}{N}: {st:?}");
    c.bench_function(&format!("dopri5_period_10ms/{name}{N}"), |b| {
        b.iter(|| {
            z.copy_from_slice(&z0);
            black_box(
                integ
                    .advance(sys, 0.0, 0.01, black_box(&mut z))
                    .expect("integrates"),
            )
        })
    });
}

fn benches(c: &mut Criterion) {
    for method in [Method::Euler, Method::Rk4, Method::Dopri5] {
        one_step(c, "linear", &mut Linear::new(), method);
        one_step(c, "decay", &mut Decay, method);
    }
    control_period(c, "linear", &mut Linear::new());
}

criterion_group!(ode, benches);
criterion_main!(ode);
