//! Long-time energy behaviour on the harmonic oscillator, against the analytic growth factors
//! of each method's stability function.

mod ode_support;

use biped_sim::ode::{Integrator, Method, Settings};
use ode_support::Oscillator;
use std::f64::consts::TAU;

/// Integrates `periods` periods of `x'' = -x` from `[1, 0]`, one `advance` call per period
/// (each period is 126 sub-steps of `h ~ 0.0499`); returns the effective step and the energy
/// extremes.
fn energy_band(method: Method, periods: usize) -> (f64, f64, f64, f64) {
    let mut osc = Oscillator { w: 1.0 };
    let mut integ = Integrator::new(method, 2, Settings::fixed(0.05)).expect("settings");
    let mut z = [1.0, 0.0];
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for k in 0..periods {
        integ
            .advance_dense(
                &mut osc,
                k as f64 * TAU,
                (k + 1) as f64 * TAU,
                &mut z,
                &[],
                |_, _| {},
            )
            .expect("integrates");
        let e = osc.energy(&z);
        lo = lo.min(e);
        hi = hi.max(e);
    }
    let h = TAU / (TAU / 0.05).ceil();
    (h, lo, hi, osc.energy(&z))
}

#[test]
fn symplectic_euler_energy_stays_bounded_over_1e5_periods() {
    // Symplectic Euler conserves H~ = H - (h/2) x v exactly for this linear system, and
    // |x v| <= H, so |H - H0| <= h H0 (to first order) for all time.
    let mut osc = Oscillator { w: 1.0 };
    let mut integ =
        Integrator::new(Method::Symplectic, 2, Settings::fixed(0.05)).expect("settings");
    let mut z = [1.0, 0.0];
    let e0 = osc.energy(&z);
    let h = TAU / (TAU / 0.05).ceil();
    let mut worst: f64 = 0.0;
    for k in 0..100_000 {
        integ
            .advance_split(&mut osc, k as f64 * TAU, (k + 1) as f64 * TAU, &mut z)
            .expect("integrates");
        worst = worst.max((osc.energy(&z) - e0).abs() / e0);
        let modified = osc.energy(&z) - 0.5 * h * z[0] * z[1];
        assert!(
            (modified - e0).abs() < 1e-9,
            "modified energy drifts at period {k}: {modified}"
        );
    }
    assert!(
        worst <= 1.05 * h,
        "relative energy excursion {worst} > h = {h}"
    );
    eprintln!("symplectic Euler, 1e5 periods, h = {h:.4}: max |dE|/E0 = {worst:.3e}");
}

#[test]
fn explicit_euler_energy_grows_by_one_plus_h_squared_per_step() {
    let (h, lo, _hi, e_end) = energy_band(Method::Euler, 20);
    let steps = 20 * (TAU / 0.05).ceil() as i32;
    let expected = 0.5 * (1.0 + h * h).powi(steps);
    assert!(
        (e_end - expected).abs() < 1e-10 * expected,
        "{e_end} vs {expected}"
    );
    assert!(lo > 0.5, "energy grows monotonically");
    eprintln!("explicit Euler, 20 periods: E/E0 = {:.4}", e_end / 0.5);
}

#[test]
fn rk4_energy_decays_by_its_stability_function() {
    // |R(i h)|^2 = 1 - h^6 / 72 + h^8 / 576 for R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24.
    let periods = 1000;
    let (h, _lo, hi, e_end) = energy_band(Method::Rk4, periods);
    let steps = periods as i32 * (TAU / 0.05).ceil() as i32;
    let factor = 1.0 - h.powi(6) / 72.0 + h.powi(8) / 576.0;
    let expected = 0.5 * factor.powi(steps);
    assert!((e_end - expected).abs() < 1e-9, "{e_end} vs {expected}");
    assert!(hi <= 0.5, "RK4 energy never grows for h < 2 sqrt 2");
    let drift = (0.5 - e_end) / 0.5;
    assert!(
        drift > 0.0 && drift < 1e-4,
        "RK4 relative drift over {periods} periods {drift:e}"
    );
    eprintln!("RK4, {periods} periods, h = {h:.4}: relative energy drift {drift:.3e}");
}
