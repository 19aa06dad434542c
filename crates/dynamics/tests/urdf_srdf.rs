//! SRDF import: rotor parameters and group states, located errors, and inputs that must be
//! rejected (a URDF given as an SRDF) or must not recurse or take quadratic time.

use biped_dynamics::urdf::srdf::{load_srdf_file, parse_srdf};
use biped_test_support::mutate;
use proptest::prelude::*;

/// A TALOS-like SRDF: groups (not read), a group state with a free-flyer and two joints,
/// rotor parameters.
const SRDF: &str = r#"<?xml version="1.0" ?>
<robot name="talos">
    <group name="r_leg">
        <joint name="leg_right_1_joint" />
    </group>
    <!-- <rotor_params><joint name="commented" mass="x"/></rotor_params> -->
    <group_state name="half_sitting" group="all">
        <joint name="root_joint" value="0. 0. 1.01927 0. 0. 0. 1." />
        <joint name="leg_left_4_joint" value="0.6" />
        <joint name="leg_left_3_joint" value="-4e-1" />
    </group_state>
    <rotor_params>
        <joint name="leg_left_3_joint" mass="1e-5" gear_ratio="100." />
        <joint name="leg_left_4_joint" mass="2e-5" gear_ratio="50" />
    </rotor_params>
</robot>
"#;

#[test]
fn reads_rotors_and_group_states() {
    let s = parse_srdf(SRDF, "talos.srdf").unwrap();
    assert_eq!(s.rotors.len(), 2);
    let r = &s.rotors[1];
    assert_eq!(
        (r.joint.as_str(), r.inertia, r.gear_ratio, r.line),
        ("leg_left_4_joint", 2e-5, 50.0, 14)
    );
    // N^2 J: 50^2 * 2e-5 = 0.05; 100^2 * 1e-5 = 0.1.
    assert!((r.armature() - 0.05).abs() < 1e-15);
    assert!((s.rotors[0].armature() - 0.1).abs() < 1e-15);
    let h = s.state("half_sitting").unwrap();
    assert_eq!((h.group.as_str(), h.line), ("all", 7));
    assert_eq!(h.joints[0].1, vec![0.0, 0.0, 1.01927, 0.0, 0.0, 0.0, 1.0]);
    assert_eq!(h.joints[1], ("leg_left_4_joint".to_string(), vec![0.6]));
    assert_eq!(h.joints[2].1, vec![-0.4]);
    assert!(s.state("standing").is_none());
}

#[test]
fn bad_entries_are_errors_at_their_line() {
    let cases = [
        (
            "mass=\"2e-5\"",
            "mass=\"-1\"",
            ":14: rotor_params joint \"leg_left_4_joint\": mass",
        ),
        (
            "gear_ratio=\"50\"",
            "gear_ratio=\"0\"",
            ":14: rotor_params joint \"leg_left_4_joint\": gear_ratio: must be > 0",
        ),
        (
            "gear_ratio=\"50\"",
            "",
            ":14: rotor_params joint \"leg_left_4_joint\": gear_ratio: missing",
        ),
        (
            "mass=\"2e-5\"",
            "mass=\"heavy\"",
            ":14: rotor_params joint \"leg_left_4_joint\": mass: \"heavy\"",
        ),
        (
            "value=\"0.6\"",
            "value=\"0.6 x\"",
            ":9: group_state \"half_sitting\" joint \"leg_left_4_joint\": value",
        ),
        (
            "value=\"0.6\"",
            "value=\"\"",
            ":9: group_state \"half_sitting\" joint \"leg_left_4_joint\": value",
        ),
        (
            "<group_state name=\"half_sitting\"",
            "<group_state",
            ":7: group_state: name: missing",
        ),
        (
            "</robot>",
            "</robt>",
            "talos.srdf:16: not a valid SRDF document",
        ),
    ];
    for (from, to, expected) in cases {
        // Replace the last occurrence so the rotor entries, not the state, are changed.
        let at = SRDF.rfind(from).unwrap();
        let text = format!("{}{}{}", &SRDF[..at], to, &SRDF[at + from.len()..]);
        let e = parse_srdf(&text, "talos.srdf").unwrap_err().to_string();
        assert!(e.contains(expected), "{from} -> {to}: {e}");
    }
    let e = parse_srdf("<urdf/>", "x.srdf").unwrap_err().to_string();
    assert!(e.contains("x.srdf:1") && e.contains("<robot>"), "{e}");
    let e = load_srdf_file("/no/such.srdf").unwrap_err().to_string();
    assert!(e.contains("/no/such.srdf: cannot read SRDF file"), "{e}");
}

proptest! {
    /// Arbitrary text, and the sample with any one byte range deleted, give a result or
    /// an error, never a panic; what parses has finite values, inertias >= 0, ratios > 0.
    #[test]
    fn never_panics(text in ".{0,200}", cut in 0usize..600, len in 0usize..40) {
        let start = cut.min(SRDF.len());
        let end = (start + len).min(SRDF.len());
        let (start, end) = (floor(SRDF, start), floor(SRDF, end));
        let damaged = format!("{}{}", &SRDF[..start], &SRDF[end..]);
        for t in [text.as_str(), damaged.as_str()] {
            if let Ok(s) = parse_srdf(t, "f.srdf") {
                prop_assert!(s.rotors.iter().all(|r| r.inertia >= 0.0 && r.gear_ratio > 0.0));
                let values = s.states.iter().flat_map(|g| g.joints.iter().flat_map(|j| &j.1));
                prop_assert!(values.clone().all(|x| x.is_finite()));
            }
        }
    }
}

/// The largest char boundary of `s` at or below `i`.
fn floor(s: &str, mut i: usize) -> usize {
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// A reflected inertia `N^2 J` beyond f64 (finite `J` and `N`) is an error, not an
/// infinite armature.
#[test]
fn overflowing_reflected_inertia_is_an_error() {
    let text = SRDF.replace("mass=\"2e-5\"", "mass=\"1e306\"");
    let e = parse_srdf(&text, "talos.srdf").unwrap_err().to_string();
    assert!(
        e.contains(":14: rotor_params joint \"leg_left_4_joint\": gear_ratio"),
        "{e}"
    );
    assert!(parse_srdf(&SRDF.replace("mass=\"2e-5\"", "mass=\"1e304\""), "t").is_ok());
}

/// The bundled G1 URDF (a `<robot>` root like an SRDF's, but with links and joints).
fn g1_path() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/g1_29dof_rev_1_0.urdf")
}

/// A URDF passed as the SRDF is an error at its first `<link>` (G1's first links are
/// commented out: the first real one is `pelvis`), not an SRDF without rotors or states.
#[test]
fn urdf_given_as_srdf_is_an_error_at_its_first_link() {
    let text = std::fs::read_to_string(g1_path()).unwrap();
    let line = 1 + text
        .lines()
        .position(|l| l.trim_start().starts_with("<link name=\"pelvis\""))
        .unwrap();
    let e = load_srdf_file(g1_path()).unwrap_err().to_string();
    let at = format!("g1_29dof_rev_1_0.urdf:{line}: <link>");
    assert!(e.contains(&at) && e.contains("looks like a URDF"), "{e}");
    // SRDF groups list links and joints one level deeper: still an SRDF.
    let group = "<robot><group name=\"g\"><link name=\"a\"/><joint name=\"j\"/></group></robot>";
    assert_eq!(parse_srdf(group, "g.srdf").unwrap(), Default::default());
}

/// A UTF-8 byte-order mark is accepted; invalid UTF-8 is an error at its line.
#[test]
fn byte_order_mark_is_accepted_and_bad_utf8_located() {
    let s = parse_srdf(&format!("\u{feff}{SRDF}"), "bom.srdf").unwrap();
    assert_eq!(s, parse_srdf(SRDF, "talos.srdf").unwrap());
    let path = std::env::temp_dir().join(format!("biped-srdf-{}.srdf", std::process::id()));
    let mut bytes = SRDF.as_bytes().to_vec();
    let at = SRDF.find("leg_left_4_joint\" mass").unwrap();
    bytes[at] = 0xff;
    std::fs::write(&path, &bytes).unwrap();
    let e = load_srdf_file(&path).unwrap_err().to_string();
    std::fs::remove_file(&path).unwrap();
    assert!(e.ends_with(".srdf:14: not UTF-8 text"), "{e}");
}

/// `depth` nested elements under the root, in a thread with a 256 KiB stack: reading must
/// not recurse on the nesting (the main thread's stack is 8 MiB, a test thread's 2 MiB).
fn parse_nested(depth: usize) -> Result<biped_dynamics::urdf::srdf::Srdf, String> {
    let text = format!(
        "<robot name=\"deep\">\n{}{}</robot>\n",
        "<x>".repeat(depth),
        "</x>".repeat(depth)
    );
    std::thread::Builder::new()
        .stack_size(256 << 10)
        .spawn(move || parse_srdf(&text, "deep.srdf").map_err(|e| e.to_string()))
        .unwrap()
        .join()
        .unwrap()
}

#[test]
fn deeply_nested_elements_do_not_overflow_the_stack() {
    for depth in [20_000, 200_000] {
        assert_eq!(parse_nested(depth), Ok(Default::default()), "{depth}");
    }
}

/// An SRDF with `n` rotor entries and `n` group-state joints.
fn many_entries(n: usize) -> String {
    let mut text = String::from("<robot name=\"many\">\n<group_state name=\"s\" group=\"all\">\n");
    for i in 0..n {
        text += &format!("  <joint name=\"j{i}\" value=\"0.{i}\"/>\n");
    }
    text += "</group_state>\n<rotor_params>\n";
    for i in 0..n {
        text += &format!(
            "  <joint name=\"j{i}\" mass=\"1e-5\" gear_ratio=\"{}\"/>\n",
            i + 1
        );
    }
    text + "</rotor_params>\n</robot>\n"
}

/// Seconds of one parse of `text`.
fn parse_seconds(text: &str) -> f64 {
    let t = std::time::Instant::now();
    let s = parse_srdf(text, "many.srdf").unwrap();
    assert!(!s.rotors.is_empty());
    t.elapsed().as_secs_f64()
}

/// Parsing time grows linearly with the entries: 10x the entries take well under 30x the
/// time (locating each entry's line by rescanning the text made it ~100x). The line of the
/// last entry is counted independently.
#[test]
fn parse_time_is_linear_in_the_entries() {
    let (small, large) = (many_entries(3_000), many_entries(30_000));
    let s = parse_srdf(&large, "many.srdf").unwrap();
    let last = s.rotors.last().unwrap();
    assert_eq!(last.line as usize, large.lines().count() - 2);
    // Fastest of five alternated parses each, so that a busy machine slows both alike.
    let (mut t_small, mut t_large) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..5 {
        t_small = t_small.min(parse_seconds(&small));
        t_large = t_large.min(parse_seconds(&large));
    }
    let ratio = t_large / t_small;
    assert!(ratio < 30.0, "10x entries took {ratio:.1}x the time");
}

/// Characters of XML structure, quotes and numbers, for the corruptions below.
const XML_ALPHABET: &[u8] = b"<>/!-?\"'= \n9.e-xjoint";

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// Corruptions of the sample (byte edits, structural edits, edge numbers, both): a
    /// one-line error naming the file, or rotors and states with finite values, inertias
    /// >= 0 and gear ratios > 0.
    #[test]
    fn corrupted_sample_is_an_error_or_finite(c in mutate::corruptions(XML_ALPHABET, 6)) {
        match parse_srdf(&c.apply(SRDF), "bad.srdf") {
            Err(e) => {
                let text = e.to_string();
                prop_assert!(text.starts_with("bad.srdf") && !text.contains('\n'), "{}", text);
            }
            Ok(s) => {
                prop_assert!(s.rotors.iter().all(|r| r.inertia >= 0.0 && r.gear_ratio > 0.0));
                prop_assert!(s.rotors.iter().all(|r| r.armature().is_finite()), "{:?}", s);
                let values = s.states.iter().flat_map(|g| g.joints.iter().flat_map(|j| &j.1));
                prop_assert!(values.clone().all(|x| x.is_finite()));
            }
        }
    }
}
