//! The [`Integrator`]: one object per simulation, created once with its buffers, advancing a
//! system over one control period `[t0, t1]` per call.

use super::dopri5::{self, Memory};
use super::error::{ConfigError, IntegrateError, Quantity};
use super::fixed::{self, Fixed};
use super::settings::{Method, Settings, StepStats};
use super::work::{finite, Outputs, Split, Work};
use super::{OdeSystem, SplitSystem};

/// Integrator of `zdot = f(t, z)` (2.2) with preallocated buffers for one dimension `n`.
///
/// Entry points: [`Self::advance`] / [`Self::advance_dense`] accept any [`OdeSystem`] and serve
/// Euler, RK4 and Dopri5 (symplectic Euler fails with [`IntegrateError::SplitRequired`]);
/// [`Self::advance_split`] / [`Self::advance_split_dense`] accept a [`SplitSystem`] and serve
/// all four methods, so a plant implementing [`SplitSystem`] uses only those.
#[derive(Debug, Clone)]
pub struct Integrator {
    method: Method,
    n: usize,
    settings: Settings,
    work: Work,
    memory: Memory,
}

impl Integrator {
    /// Creates an integrator for states of dimension `n`, validating `settings`.
    pub fn new(method: Method, n: usize, settings: Settings) -> Result<Self, ConfigError> {
        settings.validate()?;
        Ok(Integrator {
            method,
            n,
            settings,
            work: Work::new(n),
            memory: Memory::default(),
        })
    }

    /// The integration method.
    pub fn method(&self) -> Method {
        self.method
    }

    /// The state dimension the buffers were allocated for.
    pub fn dim(&self) -> usize {
        self.n
    }

    /// The settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// Current Dopri5 step-size estimate for the next call (0 before the first call).
    pub fn step_estimate(&self) -> f64 {
        self.memory.h
    }

    /// Forgets the Dopri5 step-size memory (e.g. after a state jump); the next call restarts.
    pub fn reset(&mut self) {
        self.memory = Memory::default();
    }

    /// Integrates `z` from `t0` exactly to `t1` (never evaluating past `t1`); `t1 == t0` is a
    /// no-op, `t1 < t0` an error.
    pub fn advance<S: OdeSystem>(
        &mut self,
        sys: &mut S,
        t0: f64,
        t1: f64,
        z: &mut [f64],
    ) -> Result<StepStats, IntegrateError<S::Error>> {
        self.advance_dense(sys, t0, t1, z, &[], |_, _| {})
    }

    /// Like [`Self::advance`], calling `sink(t, z(t))` once per sorted output time in
    /// `[t0, t1]`: Dopri5 gives the interpolant at exactly `t`, fixed-step methods the state at
    /// the first sub-step grid time `>= t` (and pass that grid time).
    pub fn advance_dense<S: OdeSystem>(
        &mut self,
        sys: &mut S,
        t0: f64,
        t1: f64,
        z: &mut [f64],
        outputs: &[f64],
        sink: impl FnMut(f64, &[f64]),
    ) -> Result<StepStats, IntegrateError<S::Error>> {
        self.run(sys, None, (t0, t1), z, outputs, sink)
    }

    /// Like [`Self::advance`] for a split system; serves all four methods.
    pub fn advance_split<S: SplitSystem>(
        &mut self,
        sys: &mut S,
        t0: f64,
        t1: f64,
        z: &mut [f64],
    ) -> Result<StepStats, IntegrateError<S::Error>> {
        self.advance_split_dense(sys, t0, t1, z, &[], |_, _| {})
    }

    /// Like [`Self::advance_dense`] for a split system; serves all four methods.
    pub fn advance_split_dense<S: SplitSystem>(
        &mut self,
        sys: &mut S,
        t0: f64,
        t1: f64,
        z: &mut [f64],
        outputs: &[f64],
        sink: impl FnMut(f64, &[f64]),
    ) -> Result<StepStats, IntegrateError<S::Error>> {
        let split = Some((
            sys.position_len(),
            S::position_rate as fn(&S, &[f64], &mut [f64]),
        ));
        self.run(sys, split, (t0, t1), z, outputs, sink)
    }

    /// Validates the call and dispatches to the method.
    fn run<S: OdeSystem, F: FnMut(f64, &[f64])>(
        &mut self,
        sys: &mut S,
        split: Split<S>,
        (t0, t1): (f64, f64),
        z: &mut [f64],
        times: &[f64],
        sink: F,
    ) -> Result<StepStats, IntegrateError<S::Error>> {
        self.check(sys, split, (t0, t1), z, times)?;
        let mut out = Outputs {
            times,
            next: 0,
            sink,
        };
        while out.due(t0).is_some() {
            (out.sink)(t0, z);
            out.next += 1;
        }
        if t1 == t0 {
            return Ok(StepStats::default());
        }
        let s = &self.settings;
        let w = &mut self.work;
        let (t, z) = ((t0, t1), z);
        match self.method {
            Method::Euler => fixed::advance(
                Fixed::Euler,
                s.h,
                s.max_steps,
                w,
                sys,
                split,
                t,
                z,
                &mut out,
            ),
            Method::Rk4 => {
                fixed::advance(Fixed::Rk4, s.h, s.max_steps, w, sys, split, t, z, &mut out)
            }
            Method::Symplectic => fixed::advance(
                Fixed::Symplectic,
                s.h,
                s.max_steps,
                w,
                sys,
                split,
                t,
                z,
                &mut out,
            ),
            Method::Dopri5 => dopri5::advance(s, &mut self.memory, w, sys, t, z, &mut out),
        }
    }

    /// Dimension, interval, split, output-time and initial-state checks.
    fn check<S: OdeSystem>(
        &self,
        sys: &S,
        split: Split<S>,
        (t0, t1): (f64, f64),
        z: &[f64],
        times: &[f64],
    ) -> Result<(), IntegrateError<S::Error>> {
        let mismatch = |got, what| IntegrateError::DimensionMismatch {
            expected: self.n,
            got,
            what,
        };
        if sys.dim() != self.n {
            return Err(mismatch(sys.dim(), "system dim"));
        }
        if z.len() != self.n {
            return Err(mismatch(z.len(), "state length"));
        }
        if let Some((np, _)) = split {
            if np > self.n {
                return Err(IntegrateError::InvalidSplit {
                    position_len: np,
                    dim: self.n,
                });
            }
        }
        if !(t0.is_finite() && t1.is_finite() && t0 <= t1) {
            return Err(IntegrateError::InvalidInterval { t0, t1 });
        }
        let mut prev = t0;
        for &t in times {
            if !(t >= prev && t <= t1) {
                return Err(IntegrateError::InvalidOutputTime { t, t0, t1 });
            }
            prev = t;
        }
        finite(z, t0, Quantity::State)
    }
}
