//! Dopri5 step-size control: reaching the tolerance on van der Pol (mu = 5) and Kepler, never
//! stepping past `t1`, step-size memory across calls, projection.

mod ode_support;

use biped_sim::ode::{Integrator, Method, OdeSystem, Settings};
use ode_support::{slope, Kepler, Probe, VanDerPol};
use std::f64::consts::TAU;

/// Van der Pol state at `t1` from `[2, 0]` by RK4 with step `h` (independent reference).
fn vdp_rk4(h: f64, t1: f64) -> [f64; 2] {
    let mut integ = Integrator::new(Method::Rk4, 2, Settings::fixed(h)).expect("settings");
    let mut z = [2.0, 0.0];
    integ
        .advance(&mut VanDerPol { mu: 5.0 }, 0.0, t1, &mut z)
        .expect("integrates");
    z
}

#[test]
fn dopri5_reaches_the_tolerance_on_van_der_pol() {
    let t1 = 10.0;
    let reference = vdp_rk4(1e-4, t1);
    let check = vdp_rk4(2e-4, t1);
    let ref_err = (reference[0] - check[0]).hypot(reference[1] - check[1]);
    assert!(ref_err < 1e-9, "reference accuracy {ref_err}");
    // One call over [0, t1]: the global error follows the tolerance.
    let tols = [1e-5, 1e-6, 1e-7, 1e-8, 1e-9];
    let errs: Vec<f64> = tols
        .iter()
        .map(|&rtol| {
            let mut integ = Integrator::new(Method::Dopri5, 2, Settings::tolerances(rtol, rtol))
                .expect("settings");
            let mut z = [2.0, 0.0];
            let st = integ
                .advance(&mut VanDerPol { mu: 5.0 }, 0.0, t1, &mut z)
                .expect("integrates");
            let err = (z[0] - reference[0]).hypot(z[1] - reference[1]);
            eprintln!("van der Pol mu 5, one call, rtol {rtol:e}: error {err:.3e}, {st:?}");
            assert!(err < 100.0 * rtol, "rtol {rtol}: error {err}");
            err
        })
        .collect();
    let p = slope(&tols, &errs);
    assert!(p > 0.7 && p < 1.3, "error ~ tol^{p}");
    // One call per 10 ms control period, as in the simulation loop.
    let rtol = 1e-6;
    let mut integ =
        Integrator::new(Method::Dopri5, 2, Settings::tolerances(rtol, rtol)).expect("settings");
    let mut z = [2.0, 0.0];
    let mut stats = biped_sim::ode::StepStats::default();
    for k in 0..1000 {
        let (t0, t1) = (k as f64 * 0.01, (k + 1) as f64 * 0.01);
        stats += integ
            .advance(&mut VanDerPol { mu: 5.0 }, t0, t1, &mut z)
            .expect("integrates");
    }
    let err = (z[0] - reference[0]).hypot(z[1] - reference[1]);
    eprintln!("van der Pol mu 5, 1000 calls of 10 ms, rtol {rtol:e}: error {err:.3e}, {stats:?}");
    assert!(err < 100.0 * rtol, "chunked: error {err}");
}

#[test]
fn dopri5_reaches_the_tolerance_on_kepler() {
    // Energy error stays at the tolerance; the closing error of an eccentric orbit is a phase
    // error amplified by the fast pericentre passage, so it is checked for proportionality.
    let mut errs = Vec::new();
    for rtol in [1e-6, 1e-9] {
        let z0 = Kepler::initial(0.6);
        let mut z = z0;
        let mut integ =
            Integrator::new(Method::Dopri5, 4, Settings::tolerances(rtol, rtol)).expect("settings");
        let st = integ
            .advance(&mut Kepler, 0.0, TAU, &mut z)
            .expect("integrates");
        let err = (0..4).map(|i| (z[i] - z0[i]).abs()).fold(0.0, f64::max);
        let de = (Kepler::energy(&z) - Kepler::energy(&z0)).abs();
        eprintln!(
            "Kepler e = 0.6, rtol {rtol:e}: orbit error {err:.3e}, energy error {de:.3e}, {st:?}"
        );
        assert!(de < 100.0 * rtol, "rtol {rtol}: energy error {de}");
        assert!(err < 1e3 * rtol, "rtol {rtol}: closing error {err}");
        assert!(st.rejected < st.steps, "controller adapts: {st:?}");
        errs.push(err);
    }
    let ratio = errs[0] / errs[1];
    assert!(
        (1e2..1e4).contains(&ratio),
        "error ratio {ratio} for a tolerance ratio 1e3"
    );
}

#[test]
fn no_method_evaluates_past_t1() {
    for method in Method::ALL {
        let mut integ = Integrator::new(
            method,
            2,
            Settings {
                h: 0.03,
                ..Settings::tolerances(1e-3, 1e-3)
            },
        )
        .expect("settings");
        let mut z = [1.0, 1.0];
        for k in 0..10 {
            let (t0, t1) = (0.1 * k as f64, 0.1 * (k + 1) as f64);
            let mut p = Probe::new();
            integ
                .advance_split(&mut p, t0, t1, &mut z)
                .expect("integrates");
            assert!(p.max_t <= t1, "{method} evaluated at {} > {t1}", p.max_t);
        }
        // Euler-type global error at h = 0.03 is about h e / 2 = 0.04.
        assert!((z[0] - 1f64.exp()).abs() < 0.05, "{method}: {}", z[0]);
    }
}

#[test]
fn dopri5_keeps_its_step_size_between_calls() {
    let mut integ =
        Integrator::new(Method::Dopri5, 2, Settings::tolerances(1e-8, 1e-8)).expect("settings");
    let mut z = [2.0, 0.0];
    let first = integ
        .advance(&mut VanDerPol { mu: 1.0 }, 0.0, 0.01, &mut z)
        .expect("integrates");
    let h = integ.step_estimate();
    assert!(h > 0.0 && h.is_finite());
    let second = integ
        .advance(&mut VanDerPol { mu: 1.0 }, 0.01, 0.02, &mut z)
        .expect("integrates");
    // The first call spends one evaluation on the automatic initial step; the second reuses h.
    assert!(
        second.rhs_evals < first.rhs_evals,
        "{first:?} then {second:?}"
    );
    integ.reset();
    assert_eq!(integ.step_estimate(), 0.0);
}

#[test]
fn many_short_calls_agree_with_one_long_call() {
    let run = |chunks: usize| {
        let mut integ = Integrator::new(Method::Dopri5, 4, Settings::tolerances(1e-10, 1e-10))
            .expect("settings");
        let mut z = Kepler::initial(0.3);
        for k in 0..chunks {
            let t = |k: usize| 3.0 * k as f64 / chunks as f64;
            integ
                .advance(&mut Kepler, t(k), t(k + 1), &mut z)
                .expect("integrates");
        }
        z
    };
    let (a, b) = (run(1), run(300));
    let d = (0..4).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max);
    assert!(d < 1e-8, "chunked vs single call differ by {d}");
}

/// Rotation `z' = [-z1, z0]` whose projection renormalises `z`, counting projections.
struct Circle {
    projections: std::cell::Cell<usize>,
}

impl OdeSystem for Circle {
    type Error = std::convert::Infallible;
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&mut self, _t: f64, z: &[f64], zd: &mut [f64]) -> Result<(), Self::Error> {
        zd[0] = -z[1];
        zd[1] = z[0];
        Ok(())
    }
    fn project(&self, z: &mut [f64]) {
        self.projections.set(self.projections.get() + 1);
        let r = z[0].hypot(z[1]);
        z.iter_mut().for_each(|x| *x /= r);
    }
}

#[test]
fn project_runs_after_every_accepted_step() {
    for method in [Method::Euler, Method::Rk4, Method::Dopri5] {
        let mut sys = Circle {
            projections: 0.into(),
        };
        let mut integ = Integrator::new(
            method,
            2,
            Settings {
                h: 0.1,
                ..Settings::tolerances(1e-4, 1e-4)
            },
        )
        .expect("settings");
        let mut z = [1.0, 0.0];
        let st = integ
            .advance(&mut sys, 0.0, 3.0, &mut z)
            .expect("integrates");
        assert_eq!(sys.projections.get(), st.steps, "{method}");
        assert!(
            (z[0].hypot(z[1]) - 1.0).abs() < 1e-15,
            "{method} on the circle"
        );
        assert!((z[0] - 3f64.cos()).abs() < 0.2, "{method}: {z:?}");
    }
}
