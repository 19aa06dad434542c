//! Measured convergence orders of the four methods on ODEs with known solutions, and the
//! accuracy of Dopri5 dense output at off-grid times.

mod ode_support;

use biped_sim::ode::{Integrator, Method, OdeSystem, Settings, SplitSystem, StepStats, TABLEAU};
use ode_support::{slope, Oscillator, Quadrature, Riccati};

/// Settings that make Dopri5 take exactly steps of `h` (huge tolerances, `h_max = h`).
fn dopri_fixed(h: f64) -> Settings {
    Settings {
        h_init: h,
        h_max: h,
        rtol: 1e3,
        atol: 1e3,
        ..Settings::default()
    }
}

/// Integrates `sys` over `[0, t1]` from `z0` with `method` and step `h` in one call.
fn run<S: SplitSystem>(
    sys: &mut S,
    method: Method,
    h: f64,
    t1: f64,
    z0: &[f64],
) -> (Vec<f64>, StepStats) {
    let settings = if method == Method::Dopri5 {
        dopri_fixed(h)
    } else {
        Settings::fixed(h)
    };
    let mut integ = Integrator::new(method, z0.len(), settings).expect("settings");
    let mut z = z0.to_vec();
    let stats = integ
        .advance_split(sys, 0.0, t1, &mut z)
        .expect("integrates");
    (z, stats)
}

const HS: [f64; 4] = [0.1, 0.05, 0.025, 0.0125];

/// Global error at t = 2 of the oscillator for each step in `HS`.
fn oscillator_errors(method: Method) -> Vec<f64> {
    let mut osc = Oscillator { w: 1.5 };
    HS.iter()
        .map(|&h| {
            let (z, st) = run(&mut osc, method, h, 2.0, &[1.0, 0.5]);
            assert_eq!(
                st.steps,
                (2.0 / h).round() as usize,
                "{method} takes T/h steps"
            );
            assert_eq!(st.rejected, 0);
            let ex = osc.exact([1.0, 0.5], 2.0);
            (z[0] - ex[0]).hypot(z[1] - ex[1])
        })
        .collect()
}

#[test]
fn orders_on_the_oscillator() {
    for (method, order) in [
        (Method::Euler, 1.0),
        (Method::Symplectic, 1.0),
        (Method::Rk4, 4.0),
    ] {
        let p = slope(&HS, &oscillator_errors(method));
        eprintln!("oscillator {method}: measured order {p:.3}");
        assert!((p - order).abs() < 0.15, "{method}: measured order {p}");
    }
    let p = slope(&HS, &oscillator_errors(Method::Dopri5));
    eprintln!("oscillator dopri5 (fixed h): measured order {p:.3}");
    assert!((p - 5.0).abs() < 0.3, "dopri5: measured order {p}");
}

#[test]
fn orders_on_a_non_autonomous_nonlinear_ode() {
    /// Riccati is not split; give it an empty position block so all methods run.
    struct R(Riccati);
    impl OdeSystem for R {
        type Error = std::convert::Infallible;
        fn dim(&self) -> usize {
            1
        }
        fn rhs(&mut self, t: f64, z: &[f64], zd: &mut [f64]) -> Result<(), Self::Error> {
            self.0.rhs(t, z, zd)
        }
    }
    impl SplitSystem for R {
        fn position_len(&self) -> usize {
            0
        }
        fn position_rate(&self, _z: &[f64], _xd: &mut [f64]) {}
    }
    for (method, order, tol) in [
        (Method::Euler, 1.0, 0.15),
        (Method::Rk4, 4.0, 0.2),
        (Method::Dopri5, 5.0, 0.35),
    ] {
        let errs: Vec<f64> = HS
            .iter()
            .map(|&h| {
                (run(&mut R(Riccati), method, h, 1.5, &[1.0]).0[0] - Riccati::exact(1.5)).abs()
            })
            .collect();
        let p = slope(&HS, &errs);
        eprintln!("riccati {method}: measured order {p:.3}");
        assert!(
            (p - order).abs() < tol,
            "{method}: measured order {p} from {errs:?}"
        );
    }
}

#[test]
fn dopri5_tableau_satisfies_the_order_conditions() {
    let t = TABLEAU;
    for i in 0..7 {
        let row: f64 = t.a[i].iter().sum();
        assert!((row - t.c[i]).abs() < 1e-15, "row sum {i}");
    }
    // Quadrature conditions sum b_i c_i^(k-1) = 1/k: order 5 for b, 4 for bhat.
    let quad = |w: &[f64; 7], k: i32| -> f64 { (0..7).map(|i| w[i] * t.c[i].powi(k - 1)).sum() };
    for k in 1..=5 {
        assert!(
            (quad(&t.b, k) - 1.0 / k as f64).abs() < 1e-14,
            "b order {k}"
        );
    }
    for k in 1..=4 {
        assert!(
            (quad(&t.bhat, k) - 1.0 / k as f64).abs() < 1e-14,
            "bhat order {k}"
        );
    }
    assert!(
        (quad(&t.bhat, 5) - 0.2).abs() > 1e-6,
        "bhat is only order 4"
    );
    // FSAL: the last stage is the fifth-order solution.
    assert_eq!(t.a[6][..6], t.b[..6]);
}

/// Dense outputs of Dopri5 on `sys` over `[0, t1]` at `times`.
fn dense<S: OdeSystem>(sys: &mut S, s: Settings, t1: f64, times: &[f64]) -> Vec<(f64, f64)> {
    let mut integ = Integrator::new(Method::Dopri5, 1, s).expect("settings");
    let mut z = [0.0];
    if sys.dim() == 1 {
        z[0] = if t1 > 0.0 { Riccati::exact(0.0) } else { 0.0 };
    }
    let mut got = Vec::new();
    integ
        .advance_dense(sys, 0.0, t1, &mut z, times, |t, y| got.push((t, y[0])))
        .expect("integrates");
    got
}

#[test]
fn dense_output_is_exact_for_cubic_quadrature() {
    // The continuous extension has order 4, so y' = cubic is integrated exactly at every theta.
    let mut q = Quadrature(vec![0.3, -1.0, 2.0, 0.7]);
    let times: Vec<f64> = (0..=40).map(|i| 0.0731 * i as f64).collect();
    let mut integ = Integrator::new(Method::Dopri5, 1, dopri_fixed(0.37)).expect("settings");
    let mut z = [0.0];
    let mut got = Vec::new();
    integ
        .advance_dense(&mut q, 0.0, 3.0, &mut z, &times[..41], |t, y| {
            got.push((t, y[0]))
        })
        .expect("integrates");
    assert_eq!(got.len(), times.len());
    for ((t, y), &tr) in got.iter().zip(&times) {
        assert_eq!(*t, tr);
        assert!(
            (y - q.exact(tr)).abs() < 1e-12 * (1.0 + q.exact(tr).abs()),
            "t {tr}: {y}"
        );
    }
    // A quartic is not integrated exactly between the grid points (order exactly 4).
    let mut q4 = Quadrature(vec![0.0, 0.0, 0.0, 0.0, 1.0]);
    let exact = |t: f64| t.powi(5) / 5.0;
    let mut z = [0.0];
    let mut worst: f64 = 0.0;
    let mut integ = Integrator::new(Method::Dopri5, 1, dopri_fixed(0.5)).expect("settings");
    integ
        .advance_dense(&mut q4, 0.0, 1.0, &mut z, &[0.2, 0.7], |t, y| {
            worst = worst.max((y[0] - exact(t)).abs())
        })
        .expect("integrates");
    assert!(worst > 1e-6, "quartic error {worst}");
}

#[test]
fn dense_output_converges_at_off_grid_times() {
    // Midpoints of the steps: the interpolant error must fall like h^5 (order-4 extension,
    // local error h^5); a plain cubic Hermite interpolant would give only h^4.
    let errs: Vec<f64> = HS
        .iter()
        .map(|&h| {
            let times: Vec<f64> = (0..(1.5 / h).round() as usize)
                .map(|i| (i as f64 + 0.5) * h)
                .collect();
            let got = dense(&mut Riccati, dopri_fixed(h), 1.5, &times);
            assert_eq!(got.len(), times.len());
            got.iter()
                .map(|(t, y)| (y - Riccati::exact(*t)).abs())
                .fold(0.0, f64::max)
        })
        .collect();
    let p = slope(&HS, &errs);
    eprintln!("dopri5 dense output at step midpoints: measured order {p:.3}");
    assert!(p > 4.6, "dense output order {p} from {errs:?}");
}

#[test]
fn adaptive_dense_output_meets_the_tolerance_off_grid() {
    let times: Vec<f64> = (1..100).map(|i| 0.03 * i as f64 + 0.001).collect();
    for rtol in [1e-5, 1e-8] {
        let got = dense(
            &mut Riccati,
            Settings::tolerances(rtol, rtol * 1e-3),
            3.0,
            &times,
        );
        let worst = got
            .iter()
            .map(|(t, y)| (y - Riccati::exact(*t)).abs())
            .fold(0.0, f64::max);
        assert!(worst < 10.0 * rtol, "rtol {rtol}: dense error {worst}");
    }
}

#[test]
fn fixed_step_dense_output_reports_grid_times() {
    let mut osc = Oscillator { w: 1.0 };
    let mut integ = Integrator::new(Method::Rk4, 2, Settings::fixed(0.1)).expect("settings");
    let mut z = [1.0, 0.0];
    let mut got = Vec::new();
    integ
        .advance_dense(
            &mut osc,
            0.0,
            0.5,
            &mut z,
            &[0.0, 0.05, 0.1, 0.34, 0.5],
            |t, y| got.push((t, y[0])),
        )
        .expect("integrates");
    let ts: Vec<f64> = got.iter().map(|g| g.0).collect();
    let grid = |i: f64| i * (0.5 / 5.0);
    assert_eq!(ts, vec![0.0, grid(1.0), grid(1.0), grid(4.0), 0.5]);
    assert_eq!(got[4].1, z[0], "last output is the final state");
}
