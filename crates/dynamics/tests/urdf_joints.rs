//! URDF joint properties (`<limit>`, `<dynamics>`): values against the raw text, conventions,
//! and located errors.

use biped_dynamics::urdf::{load_file, load_str, JointProps, UrdfOptions};
use std::path::PathBuf;

fn g1_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/g1_29dof_rev_1_0.urdf")
}

/// Attribute `name="value"` of the first `<tag ...>` in `text`, read by plain string search.
fn attribute(text: &str, tag: &str, name: &str) -> Option<f64> {
    let start = text.find(&format!("<{tag} "))?;
    let element = &text[start..start + text[start..].find('>')?];
    let at = element.find(&format!(" {name}=\""))? + name.len() + 3;
    element[at..].split('"').next()?.parse().ok()
}

/// The `<joint name="..">` element's text (up to its `</joint>`).
fn joint_text<'a>(xml: &'a str, name: &str) -> &'a str {
    let start = xml.find(&format!("<joint name=\"{name}\"")).expect("joint");
    let end = xml[start..].find("</joint>").expect("end tag");
    &xml[start..start + end]
}

#[test]
fn g1_joint_limits_equal_the_file_text() {
    let xml = std::fs::read_to_string(g1_path()).unwrap();
    let opts = UrdfOptions {
        floating: true,
        reject_mimic: false,
    };
    let u = load_file(g1_path(), &opts).unwrap();
    assert_eq!(u.joints.len(), xml.matches("type=\"revolute\"").count());
    for j in &u.joints {
        let text = joint_text(&xml, &j.name);
        let lim = |a| attribute(text, "limit", a).expect("G1 limits are explicit");
        assert_eq!(j.range, Some([lim("lower"), lim("upper")]), "{}", j.name);
        assert_eq!(j.effort, Some(lim("effort")), "{}", j.name);
        assert_eq!(j.velocity, Some(lim("velocity")), "{}", j.name);
        assert_eq!(
            (j.damping, j.friction),
            (0.0, 0.0),
            "{} has no <dynamics>",
            j.name
        );
        assert_eq!(u.model.body(j.body).unwrap().joint_name(), j.name);
    }
}

/// base -(j1)- a -(j2)- b with the given joint-2 attributes.
fn two_links(j2_type: &str, j2_children: &str) -> String {
    format!(
        r#"<robot name="two">
  <link name="base"/>
  <link name="a"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="b"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="2"/></joint>
  <joint name="j2" type="{j2_type}"><parent link="a"/><child link="b"/><axis xyz="1 0 0"/>
    {j2_children}</joint>
</robot>"#
    )
}

fn props(j2_type: &str, j2_children: &str) -> (Vec<JointProps>, Vec<String>) {
    let u = load_str(
        &two_links(j2_type, j2_children),
        "two.urdf",
        &UrdfOptions::default(),
    )
    .unwrap();
    (u.joints, u.warnings)
}

#[test]
fn limits_and_dynamics_are_read_per_joint() {
    let children = r#"<limit lower="-0.5" upper="2" effort="30" velocity="4"/>
    <dynamics damping="0.7" friction="0.2"/>"#;
    let (j, warnings) = props("prismatic", children);
    assert!(warnings.is_empty(), "{warnings:?}");
    assert_eq!(j[0].name, "j1");
    assert_eq!(j[0].range, Some([-1.0, 1.0]));
    assert_eq!((j[0].effort, j[0].velocity), (Some(1.0), Some(2.0)));
    assert_eq!((j[0].damping, j[0].friction), (0.0, 0.0));
    assert_eq!(j[1].range, Some([-0.5, 2.0]));
    assert_eq!((j[1].effort, j[1].velocity), (Some(30.0), Some(4.0)));
    assert_eq!((j[1].damping, j[1].friction), (0.7, 0.2));
}

#[test]
fn missing_zero_and_infinite_limits_mean_none() {
    let (j, warnings) = props("continuous", r#"<limit effort="0" velocity="inf"/>"#);
    assert_eq!((j[1].range, j[1].effort, j[1].velocity), (None, None, None));
    assert!(
        warnings.is_empty(),
        "continuous joints have no range: {warnings:?}"
    );

    let (j, warnings) = props("revolute", "");
    assert_eq!((j[1].range, j[1].effort, j[1].velocity), (None, None, None));
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].contains("joint \"j2\""), "{}", warnings[0]);

    let (j, _) = props(
        "revolute",
        r#"<limit lower="-inf" upper="1.5" effort="3" velocity="1"/>"#,
    );
    assert_eq!(j[1].range, Some([f64::NEG_INFINITY, 1.5]));
}

#[test]
fn bad_limits_and_coefficients_are_located_errors() {
    let cases = [
        (
            r#"<limit lower="1" upper="-1" effort="1" velocity="1"/>"#,
            "limit:",
        ),
        (
            r#"<limit lower="nan" upper="1" effort="1" velocity="1"/>"#,
            "limit:",
        ),
        (
            r#"<limit lower="0" upper="1" effort="-3" velocity="1"/>"#,
            "limit effort",
        ),
        (
            r#"<limit lower="0" upper="1" effort="3" velocity="nan"/>"#,
            "limit velocity",
        ),
        (r#"<dynamics damping="-0.1"/>"#, "dynamics damping"),
        (
            r#"<dynamics damping="0" friction="inf"/>"#,
            "dynamics friction",
        ),
    ];
    for (children, field) in cases {
        let xml = two_links("revolute", children);
        let Err(err) = load_str(&xml, "two.urdf", &UrdfOptions::default()) else {
            panic!("{children} must be rejected");
        };
        let text = err.to_string();
        let line = xml.lines().position(|l| l.contains("name=\"j2\"")).unwrap() + 1;
        assert!(
            text.starts_with(&format!("two.urdf:{line}: joint \"j2\": {field}")),
            "{children}: {text}"
        );
        assert!(!text.contains('\n'), "{text}");
    }
}
