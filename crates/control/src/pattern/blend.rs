//! The minimum-jerk blend that the pattern's timelines, foot rolls and swings share.

/// Minimum-jerk blend `[s, ds/dtau, d2s/dtau2]` at `tau` (clamped to \[0, 1]).
pub fn min_jerk(tau: f64) -> [f64; 3] {
    let t = tau.clamp(0.0, 1.0);
    let (t2, t3) = (t * t, t * t * t);
    [
        t3 * (10.0 - 15.0 * t + 6.0 * t2),
        30.0 * t2 * (1.0 - t) * (1.0 - t),
        60.0 * t * (1.0 - t) * (1.0 - 2.0 * t),
    ]
}

/// Smallest `tau` in \[0, 1] with `min_jerk(tau) >= s` (bisection; 1 if `s > 1`).
pub fn min_jerk_inverse(s: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 1.0);
    if s <= 0.0 {
        return 0.0;
    }
    if s >= 1.0 {
        return 1.0;
    }
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if min_jerk(mid)[0] < s {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    hi
}
