//! The URDF geometry reader: shapes, origins, located errors, and no panic on mutated input.

use biped_dynamics::urdf::{read_geometry_str, Shape, UrdfError};
use nalgebra::{Point3, Vector3};
use proptest::prelude::*;

const URDF: &str = r#"<robot name="r">
  <link name="base">
    <visual><geometry><mesh filename="package://p/v.obj"/></geometry></visual>
    <collision>
      <origin xyz="0.1 0 0" rpy="0 0 1.5707963267948966"/>
      <geometry><box size="0.4 0.2 0.1"/></geometry>
    </collision>
    <collision><geometry><cylinder radius="0.05" length="0.3"/></geometry></collision>
  </link>
  <link name="empty"/>
  <link name="tip">
    <collision><geometry><sphere radius="0.02"/></geometry></collision>
    <collision><geometry><capsule radius="0.03" length="0.1"/></geometry></collision>
    <collision><geometry><mesh filename="m.stl" scale="0.001 0.001 0.002"/></geometry></collision>
  </link>
</robot>"#;

#[test]
fn shapes_and_origins_by_hand() {
    let links = read_geometry_str(URDF, "r.urdf").unwrap();
    let names: Vec<&str> = links.iter().map(|l| l.link.as_str()).collect();
    assert_eq!(names, ["base", "empty", "tip"]);
    let base = &links[0];
    assert_eq!(base.visuals.len(), 1);
    assert_eq!(base.collisions.len(), 2);
    let c = &base.collisions[0];
    assert_eq!(
        c.shape,
        Shape::Box {
            size: [0.4, 0.2, 0.1]
        }
    );
    assert_eq!(c.at.line, Some(4));
    assert_eq!(c.at.element, "link \"base\" collision");
    // yaw of 90 degrees turns x into y, then the origin shifts by 0.1 along x
    let p = c.origin * Point3::new(1.0, 0.0, 0.0);
    assert!((p - Point3::new(0.1, 1.0, 0.0)).norm() < 1e-12);
    assert_eq!(
        base.collisions[1].origin.translation.vector,
        Vector3::zeros()
    );
    assert!(links[1].collisions.is_empty());
    let tip: Vec<&Shape> = links[2].collisions.iter().map(|c| &c.shape).collect();
    assert_eq!(
        tip,
        [
            &Shape::Sphere { radius: 0.02 },
            &Shape::Capsule {
                radius: 0.03,
                length: 0.1
            },
            &Shape::Mesh {
                filename: "m.stl".into(),
                scale: [0.001, 0.001, 0.002]
            },
        ]
    );
}

#[test]
fn bad_fields_are_located() {
    let cases = [
        (
            r#"<box size="0.4 0.2"/>"#,
            "box size: \"0.4 0.2\" is not 3 finite numbers",
        ),
        (
            r#"<box size="0.4 0 1"/>"#,
            "box size: [0.4, 0.0, 1.0] must be > 0",
        ),
        (r#"<sphere/>"#, "sphere radius: missing"),
        (
            r#"<cylinder radius="nan" length="1"/>"#,
            "cylinder radius: \"nan\" is not a finite number",
        ),
        (r#"<mesh filename=" "/>"#, "mesh filename: missing"),
        (
            r#"<mesh filename="a.stl" scale="1 0 1"/>"#,
            "mesh scale: [1.0, 0.0, 1.0] has a zero factor",
        ),
        (
            r#"<cone radius="1"/>"#,
            "geometry: <cone> is not a supported shape",
        ),
    ];
    for (shape, expected) in cases {
        let xml = format!(
            "<robot>\n<link name=\"a\">\n<collision>\n<geometry>{shape}</geometry>\n</collision></link></robot>"
        );
        let err = read_geometry_str(&xml, "f.urdf").unwrap_err().to_string();
        assert_eq!(err, format!("f.urdf:3: link \"a\" collision: {expected}"));
    }
    let no_geometry = "<robot>\n<link name=\"a\"><visual/></link></robot>";
    let err = read_geometry_str(no_geometry, "f.urdf")
        .unwrap_err()
        .to_string();
    assert_eq!(err, "f.urdf:2: link \"a\" visual: geometry: missing");
    let origin = "<robot><link name=\"a\"><visual><origin xyz=\"1 2\"/><geometry><sphere radius=\"1\"/></geometry></visual></link></robot>";
    let err = read_geometry_str(origin, "f.urdf").unwrap_err().to_string();
    assert!(
        err.ends_with("origin xyz: \"1 2\" is not 3 finite numbers"),
        "{err}"
    );
    let deep = format!("<robot>{}{}</robot>", "<a>".repeat(200), "</a>".repeat(200));
    assert!(matches!(
        read_geometry_str(&deep, "f"),
        Err(UrdfError::TooDeep { .. })
    ));
    let root = read_geometry_str("<robots/>", "f").unwrap_err().to_string();
    assert_eq!(root, "f:1: <robots>: root element: must be <robot>");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]
    /// Truncated or byte-mutated URDF text: an error or a result, never a panic, and every
    /// number read is finite.
    #[test]
    fn mutated_input_never_panics(cut in 0usize..URDF.len(), at in 0usize..URDF.len(), byte in 32u8..127) {
        let mut bytes = URDF.as_bytes()[..cut.max(1)].to_vec();
        let k = at % bytes.len();
        bytes[k] = byte;
        if let Ok(text) = String::from_utf8(bytes) {
            if let Ok(links) = read_geometry_str(&text, "m") {
                for c in links.iter().flat_map(|l| l.collisions.iter().chain(&l.visuals)) {
                    prop_assert!(c.origin.translation.vector.iter().all(|x| x.is_finite()));
                    prop_assert!(c.origin.rotation.coords.iter().all(|x| x.is_finite()));
                }
            }
        }
    }
}
