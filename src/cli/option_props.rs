//! Property tests of the option parsers of `biped simulate` and `biped walk`: any value of a
//! numeric option (negative, huge, tiny, NaN, infinite, empty, garbage, lists of any length)
//! is either accepted or refused with one line naming that option; never a panic.

use crate::cli::simulate::{parse_args, setup::Job};
use crate::cli::walk;
use proptest::prelude::*;

/// G1 URDF and its soles, for the URDF-only options.
const G1: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/crates/dynamics/data/g1_29dof_rev_1_0.urdf"
);
const G1_FEET: &str = "left_ankle_roll_link,right_ankle_roll_link";

/// One number as a user might write it, or something that is not one: mostly magnitudes
/// from 1e-15 to 1e15 of either sign (so that lists often have every entry in range and one
/// out), the bounds of the ranges, any `f64`, whole numbers, and text that is no number.
fn number() -> impl Strategy<Value = String> {
    let special = prop::sample::select(vec![
        "nan", "NaN", "inf", "-inf", "infinity", "", " ", "1e400", "-1e400", "-0", "0", "0x10",
        "1_000", "1e", "--", "-", "e5", "1,", ",", "abc", "\u{ff11}", "1e-320", "+3", "1e-6",
        "1e-3", "0.001", "1e-2", "0.1", "1e2", "1e3", "1e5", "1e6", "1e8", "1e9", "5", "100",
        "-0.6", "0.6", "0.2",
    ])
    .prop_map(String::from);
    let magnitude = (any::<bool>(), -15.0f64..15.0, any::<bool>()).prop_map(|(neg, e, sci)| {
        let x = if neg { -(10f64.powf(e)) } else { 10f64.powf(e) };
        if sci {
            format!("{x:e}")
        } else {
            format!("{x}")
        }
    });
    prop_oneof![
        4 => magnitude,
        1 => any::<f64>().prop_map(|x| format!("{x}")),
        1 => (-5i64..2000).prop_map(|n| n.to_string()),
        2 => special,
        1 => "[ -~]{0,10}",
    ]
}

/// A comma-separated list, mostly of the lengths the list options take (2 and 3).
fn list() -> impl Strategy<Value = String> {
    let n = prop_oneof![2 => Just(2usize..3), 1 => Just(3usize..4), 1 => Just(0usize..6)];
    n.prop_flat_map(|len| prop::collection::vec(number(), len))
        .prop_map(|v| v.join(","))
}

/// `NAME=VALUE` entries with joint names of Lola and the G1, unknown names or garbage.
fn named(names: &'static [&'static str]) -> impl Strategy<Value = String> {
    let entry = (prop::sample::select(names), number()).prop_map(|(n, x)| format!("{n}={x}"));
    let item = prop_oneof![4 => entry, 1 => number()];
    prop::collection::vec(item, 1..4).prop_map(|v| v.join(","))
}

/// The error of `biped ARGS` up to the built job, as the line `main` prints.
fn simulate_error(args: &[String]) -> Option<String> {
    let a = match parse_args(args) {
        Ok(a) => a,
        Err(line) => return Some(format!("error: {line}")),
    };
    Job::from_args(&a).err().map(|e| format!("error: {e}"))
}

/// Asserts that `args`, whose option under test is `flag`, build or fail with one line
/// naming `flag`.
fn check_simulate(flag: &str, args: &[String]) -> Result<(), TestCaseError> {
    if let Some(line) = simulate_error(args) {
        prop_assert!(!line.contains('\n'), "{args:?}: {line}");
        prop_assert!(
            line.starts_with(&format!("error: {flag}")),
            "{args:?}: {line}"
        );
    }
    Ok(())
}

/// `--flag value` after `context`.
fn argv(context: &[&str], flag: &str, value: &str) -> Vec<String> {
    let mut v: Vec<String> = context.iter().map(|s| s.to_string()).collect();
    v.extend([flag.to_string(), value.to_string()]);
    v
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// The numeric options of the Lola plant.
    #[test]
    fn simulate_lola_options(
        which in 0usize..9,
        one in number(),
        many in list(),
        pose in named(&["l_shank", "r_thigh", "l_foot", "no_joint", ""]),
    ) {
        let (context, flag, value): (&[&str], &str, &str) = match which {
            0 => (&[], "--duration", &one),
            1 => (&[], "--step", &one),
            2 => (&["--lola", "type3"], "--step", &one),
            3 => (&[], "--every", &one),
            4 => (&[], "--bandwidth", &one),
            5 => (&[], "--friction", &one),
            6 => (&[], "--contact", &many),
            7 => (&["--integrator", "dopri5"], "--tolerances", &many),
            _ => (&[], "--pose", &pose),
        };
        check_simulate(flag, &argv(context, flag, value))?;
    }

    /// `--sway` of the sway scenario.
    #[test]
    fn simulate_sway_motion(many in list()) {
        check_simulate("--sway", &argv(&["--scenario", "sway"], "--sway", &many))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// The numeric options of a URDF robot (each case loads the G1).
    #[test]
    fn simulate_urdf_options(
        which in 0usize..3,
        many in list(),
        armature in named(&["*_knee_joint", "*", "left_hip_pitch_joint", "no_joint"]),
    ) {
        let context = ["--urdf", G1, "--floating", "--feet", G1_FEET];
        let (flag, value) = match which {
            0 => ("--sole-center", &many),
            1 => ("--sole-size", &many),
            _ => ("--armature", &armature),
        };
        check_simulate(flag, &argv(&context, flag, value))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// The numeric options of `biped walk` (checked while parsing).
    #[test]
    fn walk_options(which in 0usize..3, one in number()) {
        let flag = ["--steps", "--step-length", "--step-time"][which];
        let argv = [flag, &one];
        if let Err(line) = walk::parse_args(argv) {
            let line = format!("error: {line}");
            prop_assert!(!line.contains('\n'), "{argv:?}: {line}");
            prop_assert!(line.starts_with(&format!("error: {flag}")), "{argv:?}: {line}");
        }
    }
}
