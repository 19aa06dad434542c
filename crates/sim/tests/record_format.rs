//! The recorder's CSV number text (`record::push_f64`) parses back to exactly the same
//! `f64` for arbitrary bit patterns (finite, subnormal, huge, signed zero, NaN, infinities)
//! and agrees in value with Rust's own shortest round-trip text (the notation may differ:
//! `-0.0000623` vs `-6.23e-5`).

use biped_sim::record::push_f64;
use proptest::prelude::*;

fn text(x: f64) -> String {
    let mut out = Vec::new();
    push_f64(&mut out, x).unwrap();
    String::from_utf8(out).unwrap()
}

fn round_trips(x: f64) {
    let s = text(x);
    let y: f64 = s.parse().unwrap();
    assert!(
        y.to_bits() == x.to_bits() || (x.is_nan() && y.is_nan()),
        "{x:?} -> {s}"
    );
    let rust: f64 = format!("{x:?}").parse().unwrap();
    assert!(rust.to_bits() == y.to_bits() || y.is_nan());
}

#[test]
fn special_values_round_trip() {
    for x in [
        0.0,
        -0.0,
        1.0,
        -1.5,
        0.1,
        1e-7,
        1e300,
        -1e-300,
        5e-324,
        f64::MAX,
        f64::MIN_POSITIVE,
    ] {
        round_trips(x);
    }
    assert_eq!(text(f64::NAN), "NaN");
    assert_eq!(text(f64::INFINITY), "inf");
    assert_eq!(text(f64::NEG_INFINITY), "-inf");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]
    #[test]
    fn arbitrary_bits_round_trip(bits in any::<u64>()) {
        round_trips(f64::from_bits(bits));
    }

    #[test]
    fn simulation_scale_values_round_trip(x in -1e4f64..1e4) {
        round_trips(x);
    }
}
