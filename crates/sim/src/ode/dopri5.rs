//! Adaptive Dormand-Prince 5(4) with embedded error control, a PI step-size controller and the
//! free fourth-order continuous extension for dense output (thesis 2.1, integration of (2.2)).
//!
//! Tableau: Dormand & Prince (1980), FSAL (the last stage is `f` at the new state). The error
//! of a step is the RMS norm of `h * sum (b_i - bhat_i) k_i` scaled by
//! `atol + rtol * max(|y0_i|, |y1_i|)`; a step is accepted when that norm is `<= 1`. The new
//! step is `h * clamp(safety * err^-(1/5 - 0.75 beta) * err_prev^beta, fac_min, fac_max)`,
//! never growing right after a rejection. The last step of a call is clipped to end exactly at
//! `t1` (a step reaching within 1 % of `t1` is stretched to it, avoiding a tiny rest step from
//! rounding, so it may exceed `h_max` by up to 1 %); the unclipped step-size estimate is kept
//! for the next call. The first stage is
//! re-evaluated at the start of every call (the input may have changed) and whenever
//! `project` changed the accepted state, otherwise it is reused (FSAL). Dense output values
//! come from the interpolant of the unprojected step, before `project` is applied.

use super::error::{IntegrateError, Quantity};
use super::settings::{Settings, StepStats};
use super::tableau::{A, C, D, E};
use super::work::{eval, finite, project, Outputs, Work};
use super::OdeSystem;

/// Step-size memory of Dopri5 carried between calls.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Memory {
    /// Proposed next step (0 = choose automatically).
    pub h: f64,
    /// Previous accepted error norm (for the PI controller).
    pub err_prev: f64,
}

/// Advances `z` from `t0` to `t1 > t0` adaptively.
pub(crate) fn advance<S: OdeSystem, F: FnMut(f64, &[f64])>(
    s: &Settings,
    mem: &mut Memory,
    w: &mut Work,
    sys: &mut S,
    (t0, t1): (f64, f64),
    z: &mut [f64],
    out: &mut Outputs<'_, F>,
) -> Result<StepStats, IntegrateError<S::Error>> {
    let mut st = StepStats::default();
    eval(sys, t0, z, &mut w.k[0], &mut st)?;
    if mem.h <= 0.0 {
        mem.h = if s.h_init > 0.0 {
            s.h_init
        } else {
            initial_step(s, w, sys, t0, z, &mut st)?
        };
        mem.err_prev = 1e-4;
    }
    let mut t = t0;
    let mut rejected_last = false;
    while t < t1 {
        if st.steps + st.rejected >= s.max_steps {
            return Err(IntegrateError::TooManySteps {
                max_steps: s.max_steps,
                t,
            });
        }
        let h_prop = mem.h.min(s.h_max);
        let clipped = t + 1.01 * h_prop >= t1;
        let h = if clipped { t1 - t } else { h_prop };
        if h_prop < s.h_min || t + h == t {
            return Err(IntegrateError::StepSizeUnderflow { t, h: h_prop });
        }
        let err = try_step(w, sys, s, t, h, z, &mut st)?;
        if err <= 1.0 {
            let t_new = if clipped { t1 } else { t + h };
            emit(w, t, h, t_new, z, out);
            z.copy_from_slice(&w.next);
            if project(sys, z, &w.next) {
                eval(sys, t_new, z, &mut w.k[0], &mut st)?;
            } else {
                w.k.swap(0, 6);
            }
            let fac = controller(s, err, mem.err_prev, rejected_last);
            let h_new = (h * fac).min(s.h_max);
            mem.h = if clipped && h_new >= h {
                h_new.max(h_prop)
            } else {
                h_new
            };
            mem.err_prev = err.max(1e-4);
            st.steps += 1;
            t = t_new;
            rejected_last = false;
        } else {
            mem.h = h * (s.safety * err.powf(-0.2)).clamp(s.fac_min, 1.0);
            st.rejected += 1;
            rejected_last = true;
        }
    }
    Ok(st)
}

/// Step-size ratio after an accepted step with error norm `err`.
fn controller(s: &Settings, err: f64, err_prev: f64, rejected_last: bool) -> f64 {
    let fac = if err == 0.0 {
        s.fac_max
    } else {
        s.safety * err.powf(-(0.2 - 0.75 * s.beta)) * err_prev.powf(s.beta)
    };
    let hi = if rejected_last { 1.0 } else { s.fac_max };
    fac.clamp(s.fac_min, hi)
}

/// One trial step from `(t, z)` with `k[0] = f(t, z)`: fills `k[1..7]`, `next`, returns the
/// scaled error norm.
fn try_step<S: OdeSystem>(
    w: &mut Work,
    sys: &mut S,
    s: &Settings,
    t: f64,
    h: f64,
    z: &[f64],
    st: &mut StepStats,
) -> Result<f64, IntegrateError<S::Error>> {
    for i in 1..7 {
        let (done, rest) = w.k.split_at_mut(i);
        let y = if i == 6 { &mut w.next } else { &mut w.stage };
        y.copy_from_slice(z);
        combine(y, h, &A[i][..i], done);
        eval(sys, t + C[i] * h, y, &mut rest[0], st)?;
    }
    finite(&w.next, t + h, Quantity::State)?;
    let n = z.len();
    if n == 0 {
        return Ok(0.0);
    }
    let e = &mut w.stage;
    e.fill(0.0);
    combine(e, h, &E, &w.k);
    let mut sum = 0.0;
    for ((ej, y0), y1) in e.iter().zip(z).zip(&w.next) {
        let r = ej / (s.atol + s.rtol * y0.abs().max(y1.abs()));
        sum += r * r;
    }
    let err = (sum / n as f64).sqrt();
    if err.is_nan() {
        return Err(IntegrateError::NonFinite {
            t,
            what: Quantity::ErrorEstimate,
        });
    }
    Ok(err)
}

/// `y += h sum_l coef_l k_l` over the stages with non-zero coefficient (vectorisable axpys).
fn combine(y: &mut [f64], h: f64, coef: &[f64], k: &[Vec<f64>]) {
    for (&c, kl) in coef.iter().zip(k) {
        if c != 0.0 {
            let a = h * c;
            y.iter_mut().zip(kl).for_each(|(yj, kj)| *yj += a * kj);
        }
    }
}

/// Sends the interpolated state at every pending output time in `(t, t_new]` to the sink.
fn emit<F: FnMut(f64, &[f64])>(
    w: &mut Work,
    t: f64,
    h: f64,
    t_new: f64,
    z: &[f64],
    out: &mut Outputs<'_, F>,
) {
    while let Some(to) = out.due(t_new) {
        let theta = ((to - t) / h).clamp(0.0, 1.0);
        interpolate(w, h, theta, z);
        (out.sink)(to, &w.out);
        out.next += 1;
    }
}

/// Continuous extension at `t + theta h` into `w.out`, from `y0 = z`, `y1 = w.next` and the
/// stages (`k[6] = f(t + h, y1)`).
fn interpolate(w: &mut Work, h: f64, theta: f64, z: &[f64]) {
    let th1 = 1.0 - theta;
    for (j, o) in w.out.iter_mut().enumerate() {
        let r2 = w.next[j] - z[j];
        let r3 = h * w.k[0][j] - r2;
        let r4 = r2 - h * w.k[6][j] - r3;
        let r5 = h * (0..7).map(|l| D[l] * w.k[l][j]).sum::<f64>();
        *o = z[j] + theta * (r2 + th1 * (r3 + theta * (r4 + th1 * r5)));
    }
}

/// Automatic initial step (Hairer, Norsett & Wanner, II.4): uses `k[0] = f(t0, z)` and one
/// more evaluation.
fn initial_step<S: OdeSystem>(
    s: &Settings,
    w: &mut Work,
    sys: &mut S,
    t0: f64,
    z: &[f64],
    st: &mut StepStats,
) -> Result<f64, IntegrateError<S::Error>> {
    let n = z.len().max(1) as f64;
    let sc = |j: usize| s.atol + s.rtol * z[j].abs();
    let rms =
        |f: &dyn Fn(usize) -> f64| ((0..z.len()).map(|j| f(j) * f(j)).sum::<f64>() / n).sqrt();
    let d0 = rms(&|j| z[j] / sc(j));
    let d1 = rms(&|j| w.k[0][j] / sc(j));
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    let h0 = h0.min(s.h_max);
    for ((y, zj), kj) in w.stage.iter_mut().zip(z).zip(&w.k[0]) {
        *y = zj + h0 * kj;
    }
    let (k0, rest) = w.k.split_at_mut(1);
    eval(sys, t0 + h0, &w.stage, &mut rest[0], st)?;
    let d2 = rms(&|j| (rest[0][j] - k0[0][j]) / sc(j)) / h0;
    let dm = d1.max(d2);
    let h1 = if dm <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / dm).powf(0.2)
    };
    Ok((100.0 * h0).min(h1).min(s.h_max).max(s.h_min))
}
