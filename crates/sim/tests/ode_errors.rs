//! Error paths of the integrators: bad input is reported, never panics, never yields NaN.

mod ode_support;

use biped_sim::ode::{ConfigError, IntegrateError, Integrator, Method, Quantity, Settings};
use ode_support::{Oscillator, Probe, Riccati};

/// An integrator of dimension 2 with loose Dopri5 tolerances.
fn integ(method: Method) -> Integrator {
    Integrator::new(
        method,
        2,
        Settings {
            h: 0.01,
            ..Settings::tolerances(1e-6, 1e-6)
        },
    )
    .expect("settings")
}

#[test]
fn nan_derivative_is_reported_with_its_time() {
    for method in Method::ALL {
        let mut p = Probe {
            nan_after: 0.5,
            ..Probe::new()
        };
        let mut z = [1.0, 1.0];
        let e = integ(method)
            .advance_split(&mut p, 0.0, 1.0, &mut z)
            .expect_err("NaN rhs");
        match e {
            IntegrateError::NonFinite {
                t,
                what: Quantity::Derivative,
            } => assert!(t > 0.5 && t <= 1.0),
            other => panic!("{method}: {other}"),
        }
        assert!(
            z.iter().all(|v| v.is_finite()),
            "{method} leaves a finite state: {z:?}"
        );
    }
}

#[test]
fn system_errors_are_wrapped() {
    for method in Method::ALL {
        let mut p = Probe {
            fail_after: 0.25,
            ..Probe::new()
        };
        let mut z = [1.0, 1.0];
        let e = integ(method)
            .advance_split(&mut p, 0.0, 1.0, &mut z)
            .expect_err("rhs fails");
        assert!(
            matches!(e, IntegrateError::System(ode_support::Fail(t)) if t > 0.25),
            "{method}: {e}"
        );
        assert!(std::error::Error::source(&e).is_some());
    }
}

#[test]
fn intervals_are_checked() {
    for method in Method::ALL {
        let mut z = [1.0, 2.0];
        let mut p = Probe::new();
        let e = integ(method)
            .advance_split(&mut p, 1.0, 0.5, &mut z)
            .expect_err("t1 < t0");
        assert!(
            matches!(e, IntegrateError::InvalidInterval { .. }),
            "{method}: {e}"
        );
        let e = integ(method)
            .advance_split(&mut p, 0.0, f64::NAN, &mut z)
            .expect_err("NaN t1");
        assert!(
            matches!(e, IntegrateError::InvalidInterval { .. }),
            "{method}: {e}"
        );
        let st = integ(method)
            .advance_split(&mut p, 1.0, 1.0, &mut z)
            .expect("t1 == t0 is a no-op");
        assert_eq!((st.steps, st.rhs_evals, z), (0, 0, [1.0, 2.0]));
    }
}

#[test]
fn dimensions_and_split_are_checked() {
    let mut z3 = [1.0, 2.0, 3.0];
    let e = integ(Method::Rk4)
        .advance(&mut Oscillator { w: 1.0 }, 0.0, 1.0, &mut z3)
        .expect_err("len");
    assert!(
        matches!(
            e,
            IntegrateError::DimensionMismatch {
                expected: 2,
                got: 3,
                ..
            }
        ),
        "{e}"
    );
    let mut z1 = [1.0];
    let e = integ(Method::Rk4)
        .advance(&mut Riccati, 0.0, 1.0, &mut z1)
        .expect_err("dim");
    assert!(
        matches!(
            e,
            IntegrateError::DimensionMismatch {
                expected: 2,
                got: 1,
                ..
            }
        ),
        "{e}"
    );
    let mut z = [1.0, 0.0];
    let e = integ(Method::Symplectic)
        .advance(&mut Oscillator { w: 1.0 }, 0.0, 1.0, &mut z)
        .expect_err("split");
    assert!(
        matches!(e, IntegrateError::SplitRequired(Method::Symplectic)),
        "{e}"
    );
    let mut nan = [f64::NAN, 0.0];
    let e = integ(Method::Euler)
        .advance(&mut Oscillator { w: 1.0 }, 0.0, 1.0, &mut nan)
        .expect_err("NaN");
    assert!(
        matches!(
            e,
            IntegrateError::NonFinite {
                what: Quantity::State,
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn output_times_are_checked() {
    for times in [&[0.5, 0.2][..], &[1.5], &[-0.1], &[f64::NAN]] {
        let mut z = [1.0, 0.0];
        let e = integ(Method::Dopri5)
            .advance_dense(
                &mut Oscillator { w: 1.0 },
                0.0,
                1.0,
                &mut z,
                times,
                |_, _| {},
            )
            .expect_err("bad output times");
        assert!(
            matches!(e, IntegrateError::InvalidOutputTime { .. }),
            "{times:?}: {e}"
        );
    }
}

#[test]
fn step_limits_are_enforced() {
    let s = Settings {
        h: 1e-3,
        max_steps: 10,
        ..Settings::tolerances(1e-10, 1e-10)
    };
    for method in Method::ALL {
        let mut z = [1.0, 0.0];
        let mut i = Integrator::new(method, 2, s).expect("settings");
        let e = i
            .advance_split(&mut Oscillator { w: 1.0 }, 0.0, 1.0, &mut z)
            .expect_err("too many");
        assert!(
            matches!(e, IntegrateError::TooManySteps { max_steps: 10, .. }),
            "{method}: {e}"
        );
    }
    // y' = y^2 from y(0) = 1 blows up at t = 1: the step size collapses or the state overflows.
    struct Blowup;
    impl biped_sim::ode::OdeSystem for Blowup {
        type Error = std::convert::Infallible;
        fn dim(&self) -> usize {
            1
        }
        fn rhs(&mut self, _t: f64, z: &[f64], zd: &mut [f64]) -> Result<(), Self::Error> {
            zd[0] = z[0] * z[0];
            Ok(())
        }
    }
    let mut i = Integrator::new(
        Method::Dopri5,
        1,
        Settings {
            h_min: 1e-9,
            ..Settings::default()
        },
    )
    .expect("settings");
    let mut z = [1.0];
    let e = i
        .advance(&mut Blowup, 0.0, 2.0, &mut z)
        .expect_err("blow-up");
    assert!(
        matches!(e, IntegrateError::StepSizeUnderflow { t, .. } | IntegrateError::NonFinite { t, .. } if (t - 1.0).abs() < 1e-3),
        "{e}"
    );
    assert!(z[0].is_finite() && z[0] > 1.0);
}

#[test]
fn settings_are_validated() {
    let bad = [
        Settings {
            h: 0.0,
            ..Settings::default()
        },
        Settings {
            h: f64::NAN,
            ..Settings::default()
        },
        Settings {
            rtol: -1.0,
            ..Settings::default()
        },
        Settings {
            rtol: 0.0,
            atol: 0.0,
            ..Settings::default()
        },
        Settings {
            h_max: 0.0,
            ..Settings::default()
        },
        Settings {
            max_steps: 0,
            ..Settings::default()
        },
        Settings {
            safety: 1.5,
            ..Settings::default()
        },
        Settings {
            fac_min: 1.0,
            ..Settings::default()
        },
        Settings {
            fac_max: 0.5,
            ..Settings::default()
        },
        Settings {
            beta: 0.3,
            ..Settings::default()
        },
    ];
    for s in bad {
        let e = Integrator::new(Method::Dopri5, 2, s).expect_err("invalid settings");
        assert!(matches!(e, ConfigError::Setting { .. }), "{s:?}");
    }
    assert!(Integrator::new(Method::Dopri5, 0, Settings::default()).is_ok());
}

#[test]
fn methods_parse_and_print() {
    for m in Method::ALL {
        assert_eq!(m.to_string().parse::<Method>(), Ok(m));
    }
    assert_eq!(" RK4 ".parse::<Method>(), Ok(Method::Rk4));
    assert!("rk45".parse::<Method>().is_err());
}

#[test]
fn overflowing_state_is_reported_and_the_last_good_state_kept() {
    /// `y' = f64::MAX`: one step from `y = 0.999 f64::MAX` overflows to infinity.
    struct Huge;
    impl biped_sim::ode::OdeSystem for Huge {
        type Error = std::convert::Infallible;
        fn dim(&self) -> usize {
            2
        }
        fn rhs(&mut self, _t: f64, _z: &[f64], zd: &mut [f64]) -> Result<(), Self::Error> {
            zd[0] = f64::MAX;
            zd[1] = 0.0;
            Ok(())
        }
    }
    for method in [Method::Euler, Method::Rk4, Method::Dopri5] {
        let mut z = [0.999 * f64::MAX, 1.0];
        let e = integ(method)
            .advance(&mut Huge, 0.0, 1.0, &mut z)
            .expect_err("overflow");
        assert!(
            matches!(
                e,
                IntegrateError::NonFinite { .. } | IntegrateError::StepSizeUnderflow { .. }
            ),
            "{method}: {e}"
        );
        assert!(
            z.iter().all(|v| v.is_finite()),
            "{method} keeps a finite state: {z:?}"
        );
    }
}
