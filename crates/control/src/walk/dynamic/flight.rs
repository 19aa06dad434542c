//! Flight phases and impacts of a dynamic walk: the cycles in which no contact point of
//! either foot touches the ground (a walk keeps one foot down; a run or a hop does not), and
//! the largest total vertical ground force against its mean (which is the robot's weight
//! over a walk that ends as it starts, so the ratio is the peak in body weights).

/// Flight and impact figures of a series of contact samples.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Flight {
    /// Time with both feet off the ground \[s].
    pub total: f64,
    /// Longest single flight phase \[s].
    pub longest: f64,
    /// Start of the longest flight phase \[s].
    pub longest_at: Option<f64>,
    /// Largest total vertical ground force \[N].
    pub peak_force: f64,
    /// Mean total vertical ground force \[N].
    pub mean_force: f64,
}

impl Flight {
    /// The figures of samples at times `t` (period `dt`) with the contact points touching per
    /// side `points` and the vertical force per side `fz`.
    pub fn of(t: &[f64], dt: f64, points: &[[usize; 2]], fz: &[[f64; 2]]) -> Self {
        let mut out = Self::default();
        let mut run: Option<(f64, f64)> = None; // (start, length) of the current flight
        for (k, &tk) in t.iter().enumerate() {
            let airborne = points.get(k).is_some_and(|p| p[0] + p[1] == 0);
            if airborne {
                out.total += dt;
                let (start, len) = run.get_or_insert((tk, 0.0));
                *len += dt;
                if *len > out.longest {
                    (out.longest, out.longest_at) = (*len, Some(*start));
                }
            } else {
                run = None;
            }
        }
        let total: Vec<f64> = fz.iter().map(|f| f[0] + f[1]).collect();
        out.peak_force = total.iter().copied().fold(0.0, f64::max);
        out.mean_force = match total.len() {
            0 => 0.0,
            n => total.iter().sum::<f64>() / n as f64,
        };
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flights_are_the_runs_without_contact() {
        let dt = 0.001;
        let t: Vec<f64> = (0..10).map(|k| k as f64 * dt).collect();
        // contact, 2 airborne, contact, 3 airborne, contact
        let pts = [1, 0, 0, 2, 0, 0, 0, 1, 1, 3].map(|n| [n, 0]);
        let fz = [[100.0, 0.0]; 10];
        let f = Flight::of(&t, dt, &pts, &fz);
        assert!((f.total - 5.0 * dt).abs() < 1e-15);
        assert!((f.longest - 3.0 * dt).abs() < 1e-15);
        assert_eq!(f.longest_at, Some(4.0 * dt));
        assert_eq!((f.peak_force, f.mean_force), (100.0, 100.0));
    }

    #[test]
    fn one_foot_down_is_no_flight() {
        let t = [0.0, 0.001, 0.002];
        let pts = [[0, 4], [3, 0], [0, 1]];
        let fz = [[0.0, 500.0], [1500.0, 0.0], [0.0, 100.0]];
        let f = Flight::of(&t, 0.001, &pts, &fz);
        assert_eq!((f.total, f.longest, f.longest_at), (0.0, 0.0, None));
        assert_eq!(f.peak_force, 1500.0);
        assert!((f.mean_force - 700.0).abs() < 1e-12);
    }
}
