use super::simulate::{CONTACT, EVERY, STEP};
use super::*;

#[test]
fn values_outside_the_range_name_option_and_range() {
    assert_eq!(STEP.parse(" 1e-4 "), Ok(1e-4));
    let e = STEP.parse("1").unwrap_err();
    assert_eq!(
        e,
        "--step: 1 s is out of range: must be >= 1e-6 and <= 0.001 s"
    );
    let e = STEP
        .at_most(1e-4, "at most the control period")
        .parse("1e-3");
    assert!(e
        .unwrap_err()
        .ends_with("<= 1e-4 s (at most the control period)"));
    for bad in ["nan", "inf", "-inf", "0", "-1e-3"] {
        assert!(
            STEP.parse(bad).unwrap_err().starts_with("--step: "),
            "{bad}"
        );
    }
    assert_eq!(
        STEP.parse("x").unwrap_err(),
        "--step: \"x\" is not a number"
    );
    assert_eq!(EVERY.parse_whole("12"), Ok(12));
    assert!(EVERY
        .parse_whole("1.5")
        .unwrap_err()
        .contains("a whole number >= 1"));
    assert!(EVERY.parse_whole("0").is_err() && EVERY.parse_whole("1e10").is_err());
    assert_eq!(CONTACT.parse("1e5, 10"), Ok([1e5, 10.0]));
    let e = CONTACT.parse("1e5,0").unwrap_err();
    assert!(
        e.starts_with("--contact: damping 0 N s/m is out of range: must be >= 0.01"),
        "{e}"
    );
    let e = CONTACT.parse("1e5").unwrap_err();
    assert_eq!(
        e,
        "--contact: expected 2 comma-separated numbers K,D, got \"1e5\""
    );
    assert_eq!(show(1e300), "1e300");
    assert_eq!(show(-0.25), "-0.25");
}
