//! Which control periods `biped simulate` records (every `--every`-th and the last) and the
//! cap on the memory the recorded samples may take.

/// Cap on the recorded samples of a run, rows x columns x 8 bytes: 1 GiB. A longer run is
/// refused before it starts (it would otherwise fill the memory while running, and write
/// nothing); `--every N` records every N-th control period instead.
pub const RECORD_CAP_BYTES: u64 = 1 << 30;

/// Which control periods are recorded: every `every`-th and the last.
#[derive(Debug, Clone, Copy)]
pub struct Recording {
    period: f64,
    every: u64,
    cycles: u64,
}

impl Recording {
    /// The rows of a run of `duration` s with control `period`, every `every`-th recorded.
    pub fn new(duration: f64, period: f64, every: u64) -> Self {
        let cycles = (duration / period).round() as u64;
        Self {
            period,
            every,
            cycles,
        }
    }

    /// Whether the frame at time `t` is recorded.
    pub fn at(&self, t: f64) -> bool {
        let k = (t / self.period).round() as u64;
        k.checked_rem(self.every) == Some(0) || k >= self.cycles
    }

    /// Number of recorded rows.
    pub fn rows(&self) -> u64 {
        self.cycles / self.every + 1 + u64::from(self.cycles.checked_rem(self.every) != Some(0))
    }

    /// Refuses a recording of `signals` columns (besides the time and the total contact force
    /// of `output`) over `duration` seconds whose samples would exceed [`RECORD_CAP_BYTES`]:
    /// names the size and the smallest `--every` that fits.
    pub fn check_size(&self, signals: u64, duration: f64) -> Result<(), String> {
        let columns = signals + 2;
        let bytes = |r: &Recording| r.rows().saturating_mul(columns).saturating_mul(8);
        let rec = *self;
        if bytes(&rec) <= RECORD_CAP_BYTES {
            return Ok(());
        }
        // `rows() <= cycles / every + 2`: this `every` fits; a few smaller ones may too.
        let max_rows = (RECORD_CAP_BYTES / (8 * columns)).max(3);
        let mut every = rec.cycles.div_ceil(max_rows - 2);
        let fits = |every| bytes(&Recording { every, ..rec }) <= RECORD_CAP_BYTES;
        while every > 1 && fits(every - 1) {
            every -= 1;
        }
        Err(format!(
            "--duration: recording {} s every {} control period(s) takes {} rows x {columns} \
             columns x 8 bytes = {}, over the {} cap of recorded samples: record every N-th \
             period with --every {every} or more, or shorten --duration",
            duration,
            self.every,
            rec.rows(),
            size(bytes(&rec)),
            size(RECORD_CAP_BYTES)
        ))
    }
}

/// `bytes` in binary units, e.g. `4.5 GiB`.
fn size(bytes: u64) -> String {
    let units = ["bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"];
    let mut x = bytes as f64;
    let mut unit = 0;
    while x >= 1024.0 && unit + 1 < units.len() {
        x /= 1024.0;
        unit += 1;
    }
    match unit {
        0 => format!("{bytes} bytes"),
        _ => format!("{} {}", (x * 10.0).round() / 10.0, units[unit]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `rows()` counts what `at()` selects, over the control times of a run.
    #[test]
    fn recorded_rows_match_the_selection() {
        for (cycles, every) in [(200, 1), (200, 10), (205, 10), (7, 3), (3, 5), (1, 1)] {
            let r = Recording {
                period: 1e-3,
                every,
                cycles,
            };
            let selected = (0..=cycles).filter(|k| r.at(*k as f64 * 1e-3)).count() as u64;
            assert_eq!(selected, r.rows(), "{cycles} cycles, every {every}");
            assert!(r.at(0.0) && r.at(cycles as f64 * 1e-3), "first and last");
        }
    }

    /// 1e6 s at 1 kHz is 1e9 + 1 rows of 135 + 2 columns, 1096 bytes a row: 1020.7 GiB. The
    /// 1 GiB cap holds 2^30 / 1096 = 979690 rows; every 1021st period gives
    /// floor(1e9 / 1021) + 2 = 979433 rows, every 1020th 980394: 1021 is the way out.
    #[test]
    fn over_the_cap_names_the_every_that_fits() {
        let e = Recording::new(1e6, 1e-3, 1)
            .check_size(135, 1e6)
            .unwrap_err();
        assert!(
            e.contains("1000000001 rows x 137 columns x 8 bytes = 1020.7 GiB"),
            "{e}"
        );
        assert!(
            e.contains("over the 1 GiB cap") && e.contains("--every 1021 or more"),
            "{e}"
        );
        assert!(Recording::new(1e6, 1e-3, 1021).check_size(135, 1e6).is_ok());
        assert!(Recording::new(1e6, 1e-3, 1020)
            .check_size(135, 1e6)
            .is_err());
        assert!(Recording::new(3.0, 1e-3, 1).check_size(135, 3.0).is_ok());
    }
}
