//! `tanh` for the smoothed Coulomb friction `tanh(omega / omega_eps)`, evaluated 24 times per
//! right-hand side: a rational function near zero (where a standing robot's joints are) and
//! `exp` beyond, within a few ulp of the C library's `tanh` and without its `expm1` call (the
//! C library's pair is a measurable share of a `stand` cycle, see BENCHMARKS.md).
//!
//! For `|x| <= 0.625`: Lambert's continued fraction `tanh x = x / (1 + x^2 / (3 + x^2 / (5 +
//! ...)))` truncated after `15`, i.e. the Padé approximant `x P(x^2) / Q(x^2)` with integer
//! coefficients, relative truncation error below 6.2e-18 there (checked in 60-digit
//! arithmetic when derived). Beyond: `1 - 2 / (exp(2 |x|) + 1)` with the sign of `x`, where
//! the subtraction loses less than one bit.

/// Numerator `P(t)` coefficients, constant term first.
const P: [f64; 4] = [2_027_025.0, 270_270.0, 6_930.0, 36.0];
/// Denominator `Q(t)` coefficients, constant term first.
const Q: [f64; 5] = [2_027_025.0, 945_945.0, 51_975.0, 630.0, 1.0];
/// Largest `|x|` of the rational branch.
const RATIONAL_MAX: f64 = 0.625;

/// Hyperbolic tangent (see the module docs); `NaN` for `NaN`, `+-1` for `+-inf`.
#[inline]
pub fn tanh(x: f64) -> f64 {
    let a = x.abs();
    if a <= RATIONAL_MAX {
        let t = x * x;
        let p = ((P[3] * t + P[2]) * t + P[1]) * t + P[0];
        let q = (((Q[4] * t + Q[3]) * t + Q[2]) * t + Q[1]) * t + Q[0];
        x * (p / q)
    } else {
        (1.0 - 2.0 / ((2.0 * a).exp() + 1.0)).copysign(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Distance in units in the last place of `b` (`b` finite and nonzero).
    fn ulps(a: f64, b: f64) -> f64 {
        let ulp = f64::from_bits(b.abs().to_bits() + 1) - b.abs();
        (a - b).abs() / ulp
    }

    /// Within 4 ulp of the C library over 1e-300 .. 40 (log-spaced, both signs, both branches
    /// and the switch between them); exact `+-0`, `+-1` and `NaN` at the ends.
    #[test]
    fn matches_libm_tanh_over_the_range() {
        let switch = [RATIONAL_MAX, f64::from_bits(RATIONAL_MAX.to_bits() + 1)];
        let logs = (0..=200_000).map(|k| 10f64.powf(-300.0 + 301.6 * k as f64 / 200_000.0));
        let worst = (logs.chain(switch))
            .flat_map(|x| [x, -x])
            .map(|x| ulps(tanh(x), x.tanh()))
            .fold(0.0f64, f64::max);
        assert!(worst <= 4.0, "worst {worst} ulp");
        assert_eq!(tanh(0.0).to_bits(), 0.0f64.to_bits());
        assert_eq!(tanh(-0.0).to_bits(), (-0.0f64).to_bits());
        assert_eq!((tanh(f64::INFINITY), tanh(f64::NEG_INFINITY)), (1.0, -1.0));
        assert_eq!((tanh(800.0), tanh(-800.0)), (1.0, -1.0));
        assert!(tanh(f64::NAN).is_nan());
    }

    proptest! {
        /// Random arguments of the friction's working range (`omega / omega_eps`): within 4
        /// ulp of the C library, odd, and never above 1 in magnitude.
        #[test]
        fn random_arguments_match_libm(x in -50.0f64..50.0) {
            prop_assert!(ulps(tanh(x), x.tanh()) <= 4.0 || x == 0.0);
            prop_assert_eq!(tanh(-x), -tanh(x));
            prop_assert!(tanh(x).abs() <= 1.0);
        }
    }
}
