//! One updating progress line on stderr (percent of simulated time, realtime factor), shown
//! only when stderr is a terminal and the run is projected to take more than a second. Written
//! best effort: a closed stderr does not stop the run.

use crate::cli::out;
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// Wall time before the first projection of the run time.
const GRACE: Duration = Duration::from_millis(250);
/// Projected run time above which the line is shown.
const LONG_RUN: Duration = Duration::from_secs(1);
/// Smallest interval between redraws.
const REDRAW: Duration = Duration::from_millis(100);

/// Progress of a run of `duration` simulated seconds.
pub struct Progress {
    enabled: bool,
    duration: f64,
    start: Instant,
    last_draw: Option<Instant>,
}

impl Progress {
    /// Starts the clock; the line is enabled only if stderr is a terminal.
    pub fn new(duration: f64) -> Self {
        Self {
            enabled: std::io::stderr().is_terminal() && duration > 0.0,
            duration,
            start: Instant::now(),
            last_draw: None,
        }
    }

    /// Redraws the line for simulated time `t` if it is due.
    pub fn update(&mut self, t: f64) {
        if !self.enabled {
            return;
        }
        let now = Instant::now();
        let elapsed = now - self.start;
        let fraction = (t / self.duration).clamp(0.0, 1.0);
        let due = match self.last_draw {
            Some(last) => now - last >= REDRAW,
            None => elapsed >= GRACE && projected_long(elapsed, fraction),
        };
        if due {
            self.last_draw = Some(now);
            let rtf = t / elapsed.as_secs_f64();
            let line = format!(
                "\r{:5.1} % of {} s simulated, realtime factor {rtf:.3}",
                100.0 * fraction,
                self.duration
            );
            out::progress(&line);
        }
    }

    /// Erases the line if it was drawn.
    pub fn finish(&mut self) {
        if self.last_draw.take().is_some() {
            out::progress(&format!("\r{:70}\r", ""));
        }
    }
}

/// Whether a run that did `fraction` of its work in `elapsed` takes longer than [`LONG_RUN`].
fn projected_long(elapsed: Duration, fraction: f64) -> bool {
    fraction <= 0.0 || elapsed.as_secs_f64() / fraction > LONG_RUN.as_secs_f64()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn projection_of_the_run_time() {
        let ms = Duration::from_millis;
        assert!(projected_long(ms(300), 0.2), "1.5 s projected");
        assert!(!projected_long(ms(300), 0.5), "0.6 s projected");
        assert!(projected_long(ms(300), 0.0), "no progress yet");
    }
}
