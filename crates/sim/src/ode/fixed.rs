//! Fixed-step methods of thesis 2.1: explicit Euler, semi-implicit (symplectic) Euler, RK4.
//!
//! The interval `[t0, t1]` is split into `N = ceil((t1 - t0) / h)` equal sub-steps (a ratio
//! within `1e-9` of an integer counts as that integer), so the last sub-step ends exactly at
//! `t1`. Dense output of these methods is the sub-step grid: a requested time `t` is answered
//! with the state at the first grid time `>= t`, and the sink receives that grid time.
//! On an error the state is restored to the start of the failed sub-step.

use super::error::{IntegrateError, Quantity};
use super::settings::{Method, StepStats};
use super::work::{eval, finite, Outputs, Split, Work};
use super::OdeSystem;

/// Number of equal sub-steps of length `<= h` covering `span > 0`, or `None` if absurdly many.
pub(crate) fn sub_steps(span: f64, h: f64) -> Option<usize> {
    let r = span / h;
    let k = r.round();
    let n = if (r - k).abs() <= 1e-9 * k.max(1.0) {
        k
    } else {
        r.ceil()
    };
    (n < 1e15).then_some(n.max(1.0) as usize)
}

/// The fixed-step schemes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Fixed {
    Euler,
    Symplectic,
    Rk4,
}

/// Advances `z` from `t0` to `t1 > t0` with the fixed-step scheme `kind`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn advance<S: OdeSystem, F: FnMut(f64, &[f64])>(
    kind: Fixed,
    h: f64,
    max_steps: usize,
    w: &mut Work,
    sys: &mut S,
    split: Split<S>,
    (t0, t1): (f64, f64),
    z: &mut [f64],
    out: &mut Outputs<'_, F>,
) -> Result<StepStats, IntegrateError<S::Error>> {
    let mut stats = StepStats::default();
    let n_sub = match sub_steps(t1 - t0, h) {
        Some(n) if n <= max_steps => n,
        _ => return Err(IntegrateError::TooManySteps { max_steps, t: t0 }),
    };
    let hs = (t1 - t0) / n_sub as f64;
    for i in 0..n_sub {
        let t = t0 + i as f64 * hs;
        let t_next = if i + 1 == n_sub {
            t1
        } else {
            t0 + (i + 1) as f64 * hs
        };
        let h = t_next - t;
        w.next.copy_from_slice(z);
        let step = match kind {
            Fixed::Euler => euler(w, sys, t, h, z, &mut stats),
            Fixed::Rk4 => rk4(w, sys, t, h, z, &mut stats),
            Fixed::Symplectic => match split {
                Some((np, rate)) => symplectic(w, sys, np, rate, t, h, z, &mut stats),
                None => Err(IntegrateError::SplitRequired(Method::Symplectic)),
            },
        };
        if let Err(e) = step.and_then(|_| finite(z, t_next, Quantity::State)) {
            z.copy_from_slice(&w.next);
            return Err(e);
        }
        sys.project(z);
        stats.steps += 1;
        while out.due(t_next).is_some() {
            (out.sink)(t_next, z);
            out.next += 1;
        }
    }
    Ok(stats)
}

/// Explicit Euler step `z += h f(t, z)`.
fn euler<S: OdeSystem>(
    w: &mut Work,
    sys: &mut S,
    t: f64,
    h: f64,
    z: &mut [f64],
    stats: &mut StepStats,
) -> Result<(), IntegrateError<S::Error>> {
    let k = &mut w.k[0];
    eval(sys, t, z, k, stats)?;
    z.iter_mut()
        .zip(k.iter())
        .for_each(|(zi, ki)| *zi += h * ki);
    Ok(())
}

/// Semi-implicit Euler: rates `v += h vdot(t, z)`, then positions `x += h xdot(x, v_new)`.
#[allow(clippy::too_many_arguments)]
fn symplectic<S: OdeSystem>(
    w: &mut Work,
    sys: &mut S,
    np: usize,
    rate: fn(&S, &[f64], &mut [f64]),
    t: f64,
    h: f64,
    z: &mut [f64],
    stats: &mut StepStats,
) -> Result<(), IntegrateError<S::Error>> {
    let [k, xdot, ..] = &mut w.k;
    eval(sys, t, z, k, stats)?;
    z[np..]
        .iter_mut()
        .zip(&k[np..])
        .for_each(|(zi, ki)| *zi += h * ki);
    let xdot = &mut xdot[..np];
    rate(sys, z, xdot);
    finite(xdot, t + h, Quantity::PositionRate)?;
    z[..np]
        .iter_mut()
        .zip(xdot.iter())
        .for_each(|(zi, ki)| *zi += h * ki);
    Ok(())
}

/// Classic fourth-order Runge-Kutta step.
fn rk4<S: OdeSystem>(
    w: &mut Work,
    sys: &mut S,
    t: f64,
    h: f64,
    z: &mut [f64],
    stats: &mut StepStats,
) -> Result<(), IntegrateError<S::Error>> {
    let [k1, k2, k3, k4, ..] = &mut w.k;
    let y = &mut w.stage;
    let axpy = |y: &mut [f64], a: f64, k: &[f64]| {
        y.iter_mut()
            .zip(z.iter().zip(k))
            .for_each(|(yi, (zi, ki))| *yi = zi + a * ki)
    };
    eval(sys, t, z, k1, stats)?;
    axpy(y, 0.5 * h, k1);
    eval(sys, t + 0.5 * h, y, k2, stats)?;
    axpy(y, 0.5 * h, k2);
    eval(sys, t + 0.5 * h, y, k3, stats)?;
    axpy(y, h, k3);
    eval(sys, t + h, y, k4, stats)?;
    let h6 = h / 6.0;
    for (i, zi) in z.iter_mut().enumerate() {
        *zi += h6 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
    }
    Ok(())
}
