//! URDF inputs the importer must reject with a located error or read in linear time: deep
//! nesting, a wrong root element, empty names, malformed markup, bad UTF-8, large files.

use biped_dynamics::urdf::{load_file, load_str, UrdfError, UrdfOptions, MAX_DEPTH};
use biped_test_support::mutate;
use proptest::prelude::*;

/// The error of importing `xml` labelled `test.urdf`, as its message.
fn error_of(xml: &str) -> String {
    match load_str(xml, "test.urdf", &UrdfOptions::default()) {
        Ok(_) => panic!("accepted: {xml}"),
        Err(e) => e.to_string(),
    }
}

/// A one-link robot whose link holds `depth` nested `<x>` elements.
fn nested(depth: usize) -> String {
    format!(
        "<robot name=\"r\">\n<link name=\"a\">\n{}{}</link>\n</robot>\n",
        "<x>".repeat(depth),
        "</x>".repeat(depth)
    )
}

/// 20 000 nested elements used to overflow the stack in urdf-rs' recursive XML tree (the
/// process aborted); now the nesting is checked first, without recursion, and the first
/// element beyond [`MAX_DEPTH`] levels is named. Exactly `MAX_DEPTH` levels are read.
#[test]
fn deep_nesting_is_a_located_error_not_a_stack_overflow() {
    let e = error_of(&nested(20_000));
    let expected = format!("test.urdf:3: elements nested deeper than {MAX_DEPTH} levels");
    assert_eq!(e, expected);
    // robot and link are levels 1 and 2.
    let ok = load_str(&nested(MAX_DEPTH - 2), "ok.urdf", &UrdfOptions::default());
    assert_eq!(ok.map(|m| m.links.len()).ok(), Some(1));
    assert!(error_of(&nested(MAX_DEPTH - 1)).contains("nested deeper"));
    // Inside an element the importer drops (`<visual>`) the nesting counts too.
    let visual = nested(20_000).replace("<link name=\"a\">\n", "<link name=\"a\">\n<visual>");
    let visual = visual.replace("</link>", "</visual></link>");
    assert!(error_of(&visual).contains("nested deeper"), "{visual:.80}");
}

/// The root element must be `<robot>`: urdf-rs read `<robo>` as an empty robot.
#[test]
fn wrong_root_element_is_an_error() {
    let e = error_of("<?xml version=\"1.0\"?>\n<robo name=\"r\"><link name=\"a\"/></robo>");
    assert_eq!(e, "test.urdf:2: <robo>: root element: must be <robot>");
    assert!(error_of("  \n").contains("no <robot> element"));
}

/// Empty (or blank) link and joint names are errors at their element.
#[test]
fn empty_names_are_errors() {
    let e = error_of("<robot name=\"r\">\n<link name=\"\"/>\n</robot>");
    assert_eq!(e, "test.urdf:2: link \"\": name: must not be empty");
    let joint = "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n\
                 <joint name=\" \" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n\
                 </robot>";
    assert_eq!(
        error_of(joint),
        "test.urdf:4: joint \" \": name: must not be empty"
    );
}

/// Unterminated and mismatched markup is named at its line.
#[test]
fn malformed_markup_is_located() {
    let e = error_of("<robot name=\"r\">\n<link name=\"a\">\n</robot>");
    assert_eq!(
        e,
        "test.urdf:3: not a valid URDF document: </robot> does not close <link> (line 2)"
    );
    let e = error_of("<robot name=\"r\">\n<link name=\"a\"/>\n<!-- no end\n</robot>");
    assert!(
        e.starts_with("test.urdf:3: not a valid URDF document"),
        "{e}"
    );
}

/// A byte-order mark is accepted; invalid UTF-8 is an error at its line.
#[test]
fn byte_order_mark_and_bad_utf8() {
    let xml = "<robot name=\"r\">\n<link name=\"a\"/>\n</robot>\n";
    let m = load_str(
        &format!("\u{feff}{xml}"),
        "bom.urdf",
        &UrdfOptions::default(),
    )
    .unwrap();
    assert_eq!(m.links[0].link, "a");
    let path = std::env::temp_dir().join(format!("biped-urdf-{}.urdf", std::process::id()));
    let mut bytes = xml.as_bytes().to_vec();
    bytes[xml.find("a\"/>").unwrap()] = 0xc3;
    std::fs::write(&path, &bytes).unwrap();
    let e = load_file(&path, &UrdfOptions::default()).err().unwrap();
    std::fs::remove_file(&path).unwrap();
    assert!(matches!(e, UrdfError::NotUtf8 { line: 2, .. }), "{e}");
}

/// A chain of `n` links joined by revolute joints.
fn chain(n: usize) -> String {
    let mut xml = String::from("<robot name=\"chain\">\n");
    for i in 0..n {
        xml += &format!(
            "<link name=\"l{i}\"><inertial><mass value=\"1\"/><inertia ixx=\"0.1\" ixy=\"0\" \
             ixz=\"0\" iyy=\"0.1\" iyz=\"0\" izz=\"0.1\"/></inertial></link>\n"
        );
    }
    for i in 1..n {
        xml += &format!(
            "<joint name=\"j{i}\" type=\"revolute\"><parent link=\"l{}\"/><child link=\"l{i}\"/>\
             <axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>\
             </joint>\n",
            i - 1
        );
    }
    xml + "</robot>\n"
}

/// Seconds of one import of `xml`, which must give `n - 1` coordinates.
fn import_seconds(xml: &str, n: usize) -> f64 {
    let t = std::time::Instant::now();
    let m = load_str(xml, "chain.urdf", &UrdfOptions::default()).unwrap();
    assert_eq!(m.model.nv(), n - 1);
    t.elapsed().as_secs_f64()
}

/// Import time grows linearly with the links: 10 000 links take well under 30x the time of
/// 1 000 (locating each body's element by rescanning the text made it ~100x: 0.3 s vs 32 s).
/// The error for the last joint is still located at its line.
#[test]
fn import_time_is_linear_in_the_links() {
    let (small, large) = (chain(1_000), chain(10_000));
    // Fastest of three alternated imports each, so that a busy machine slows both alike.
    let (mut t_small, mut t_large) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..3 {
        t_small = t_small.min(import_seconds(&small, 1_000));
        t_large = t_large.min(import_seconds(&large, 10_000));
    }
    let ratio = t_large / t_small;
    assert!(ratio < 30.0, "10x links took {ratio:.1}x the time");
    let bad = large.replace(
        "<axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>\
             </joint>\n</robot>",
        "<axis xyz=\"0 0 0\"/></joint>\n</robot>",
    );
    let line = large.lines().count() - 1;
    assert!(error_of(&bad).starts_with(&format!("test.urdf:{line}: joint \"j9999\": axis")));
}

/// Markup fragments that change how a reader tokenizes (comments, CDATA, processing
/// instructions, quotes, bare `<` and `>`).
const FRAGMENTS: [&str; 16] = [
    "<a>",
    "</a>",
    "<a/>",
    "<!--",
    "-->",
    "<![CDATA[",
    "]]>",
    "<?",
    "?>",
    "'",
    "\"",
    "=",
    " b",
    "<",
    ">",
    "<x>",
];

/// A fragment, or 2 000 nested elements (closed, or only opened, or only the end tags).
fn fragment() -> impl Strategy<Value = String> {
    let (open, close) = ("<x>".repeat(2_000), "</x>".repeat(2_000));
    prop_oneof![
        12 => prop::sample::select(&FRAGMENTS[..]).prop_map(str::to_string),
        2 => Just(open.clone() + &close),
        1 => Just(open),
        1 => Just(close),
    ]
}

/// Imports `xml` in a thread with a 512 KiB stack (urdf-rs needs about 1 KiB per nesting
/// level, so a bypassed depth check aborts the test process).
fn import_in_small_stack(xml: String) -> Result<(), String> {
    std::thread::Builder::new()
        .stack_size(512 << 10)
        .spawn(
            move || match load_str(&xml, "fuzz.urdf", &UrdfOptions::default()) {
                Err(e) if e.to_string().contains('\n') => Err(format!("multi-line error: {e}")),
                _ => Ok(()),
            },
        )
        .unwrap()
        .join()
        .map_err(|_| "panicked".to_string())?
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Random markup around a robot with a link (deep runs included): a result or a one-line
    /// error, never a stack overflow or a panic.
    #[test]
    fn random_markup_never_recurses_deeply(parts in prop::collection::vec(fragment(), 0..24)) {
        let xml = format!("<robot name=\"r\"><link name=\"l\">{}</link></robot>", parts.concat());
        prop_assert_eq!(import_in_small_stack(xml), Ok(()));
    }
}

/// The three-link chain of `urdf_import.rs` with limits and dynamics, for corruptions.
fn sample() -> String {
    chain(3).replace(
        "</joint>\n</robot>",
        "<dynamics damping=\"0.1\" friction=\"0.2\"/></joint>\n</robot>",
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// Corruptions of the sample (byte edits, XML-structure edits, edge numbers, both): a
    /// one-line error naming the file, or a model whose joint limits, damping, friction and
    /// forward dynamics are finite (or a typed error).
    #[test]
    fn corrupted_chain_is_an_error_or_finite(c in mutate::corruptions(b"<>/\"'=-9e.0 \nxyz!", 6)) {
        let xml = c.apply(&sample());
        match load_str(&xml, "bad.urdf", &UrdfOptions { floating: true, ..Default::default() }) {
            Err(e) => {
                let text = e.to_string();
                prop_assert!(text.starts_with("bad.urdf") && !text.contains('\n'), "{}", text);
            }
            Ok(m) => {
                for j in &m.joints {
                    let values = [j.damping, j.friction].into_iter().chain(j.effort).chain(j.velocity);
                    prop_assert!(values.clone().all(f64::is_finite), "{:?}", j);
                    prop_assert!(j.range.is_none_or(|r| !r[0].is_nan() && !r[1].is_nan()), "{:?}", j);
                }
                let model = &m.model;
                let (q, v) = (model.neutral(), nalgebra::DVector::zeros(model.nv()));
                let tau = nalgebra::DVector::from_element(model.nv(), 0.1);
                let mut data = biped_dynamics::Data::new(model);
                let algo = biped_dynamics::Algorithm::On;
                if let Ok(a) = biped_dynamics::forward_dynamics(model, &mut data, &q, &v, &tau, None, algo) {
                    prop_assert!(a.iter().all(|x| x.is_finite()), "{:?}", a);
                }
            }
        }
    }
}
