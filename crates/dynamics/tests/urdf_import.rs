//! URDF import: structure of the bundled humanoid, merging, and located errors.

use biped_dynamics::urdf::{load_file, load_str, UrdfError, UrdfOptions};
use biped_test_support::mutate;
use std::path::PathBuf;

/// The bundled Unitree G1 URDF (BSD-3-Clause, see data/README.md).
fn g1_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/g1_29dof_rev_1_0.urdf")
}

/// The XML text without `<!-- .. -->` comments.
fn strip_comments(xml: &str) -> String {
    let mut out = String::new();
    let mut rest = xml;
    while let Some(start) = rest.find("<!--") {
        out.push_str(&rest[..start]);
        let end = rest[start..]
            .find("-->")
            .map_or(rest.len(), |e| start + e + 3);
        rest = &rest[end..];
    }
    out + rest
}

/// Sum of all `<mass value="..">` attributes, read straight from the XML text.
fn masses_in_text(xml: &str) -> f64 {
    xml.split("<mass")
        .skip(1)
        .map(|rest| {
            let v = rest.split('"').nth(1).expect("value attribute");
            v.parse::<f64>().expect("number")
        })
        .sum()
}

/// Number of `type="revolute"` joints in the text (G1 has no continuous/prismatic ones).
fn revolute_in_text(xml: &str) -> usize {
    xml.matches("type=\"revolute\"").count()
}

const FLOATING: UrdfOptions = UrdfOptions {
    floating: true,
    reject_mimic: false,
};

#[test]
fn g1_fixed_base_has_one_coordinate_per_revolute_joint() {
    let xml = strip_comments(&std::fs::read_to_string(g1_path()).unwrap());
    let m = load_file(g1_path(), &UrdfOptions::default()).unwrap().model;
    let n = revolute_in_text(&xml);
    assert_eq!(n, 29);
    assert_eq!((m.nq(), m.nv(), m.joints().len()), (n, n, n));
    for (k, j) in m.joints().iter().enumerate() {
        assert_eq!(
            (j.nq, j.nv, j.q_index, j.v_index),
            (1, 1, k, k),
            "{}",
            j.name
        );
    }
    assert_eq!(m.neutral(), nalgebra::DVector::zeros(n));
}

#[test]
fn g1_floating_base_starts_with_root_free_joint() {
    let m = load_file(g1_path(), &FLOATING).unwrap().model;
    assert_eq!((m.nq(), m.nv()), (36, 35));
    let root = &m.joints()[0];
    assert_eq!((root.name.as_str(), root.nq, root.nv), ("root", 7, 6));
    let q0 = m.neutral();
    assert_eq!(
        q0.rows(0, 7).as_slice(),
        &[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]
    );
    assert_eq!(m.body_names()[0], "pelvis");
    assert_eq!(m.body_id("pelvis"), Some(0));
}

#[test]
fn g1_floating_total_mass_equals_sum_of_inertials() {
    let xml = strip_comments(&std::fs::read_to_string(g1_path()).unwrap());
    let imported = load_file(g1_path(), &FLOATING).unwrap();
    // Every link is either a body or merged into one: all masses are kept.
    assert!(imported.links.iter().all(|l| l.body.is_some()));
    let total = biped_dynamics_total_mass(&imported.model);
    let expected = masses_in_text(&xml);
    assert!(
        (total - expected).abs() < 1e-9 * expected,
        "{total} vs {expected}"
    );
}

/// Total mass of a model from the public API: the bodies' inertias are not public, so use the
/// mass matrix of the free joint's linear part at the neutral pose (m * identity).
fn biped_dynamics_total_mass(model: &biped_dynamics::Model) -> f64 {
    let mut data = biped_dynamics::Data::new(model);
    let q = model.neutral();
    let m = biped_dynamics::mass_matrix(model, &mut data, &q).unwrap();
    m[(0, 0)]
}

#[test]
fn every_link_is_listed_once_with_its_body() {
    let xml = strip_comments(&std::fs::read_to_string(g1_path()).unwrap());
    let imported = load_file(g1_path(), &UrdfOptions::default()).unwrap();
    assert_eq!(imported.links.len(), xml.matches("<link ").count());
    let names = imported.model.body_names();
    for l in &imported.links {
        if let Some(b) = l.body {
            assert!(b < names.len());
        }
        if names.contains(&l.link.as_str()) {
            assert!(
                l.pose.translation.vector.norm() == 0.0,
                "body link has identity pose"
            );
        }
    }
}

/// A three-link chain: base -(revolute j1)- a -(fixed jf)- b -(JOINT)- c.
fn chain(joint3: &str) -> String {
    format!(
        r#"<robot name="chain">
  <link name="base"/>
  <link name="a"><inertial><mass value="1"/><origin xyz="0.1 0 0"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.02"/></inertial></link>
  <link name="b"><inertial><mass value="0.5"/><origin xyz="0 0.1 0" rpy="0.3 0.2 0.1"/>
    <inertia ixx="0.002" ixy="0" ixz="0" iyy="0.003" iyz="0" izz="0.004"/></inertial></link>
  <link name="c"><inertial><mass value="0.2"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="jf" type="fixed"><parent link="a"/><child link="b"/><origin xyz="0.3 0 0" rpy="0 0 0.5"/></joint>
  {joint3}
</robot>"#
    )
}

const J3_OK: &str = r#"<joint name="j3" type="continuous"><parent link="b"/><child link="c"/>
    <origin xyz="0.2 0 0"/><axis xyz="0 0 2"/></joint>"#;

#[test]
fn fixed_joints_are_merged_and_frames_kept() {
    let imported = load_str(&chain(J3_OK), "chain.urdf", &UrdfOptions::default()).unwrap();
    let m = &imported.model;
    assert_eq!(m.body_names(), vec!["a", "c"]);
    let names: Vec<&str> = m.joints().iter().map(|j| j.name.as_str()).collect();
    assert_eq!(names, vec!["j1", "j3"]);
    let b = imported.links.iter().find(|l| l.link == "b").unwrap();
    assert_eq!(b.body, m.body_id("a"));
    assert!((b.pose.translation.vector - nalgebra::Vector3::new(0.3, 0.0, 0.0)).norm() < 1e-15);
    let base = imported.links.iter().find(|l| l.link == "base").unwrap();
    assert_eq!(base.body, None);
}

/// Error text of a failed in-memory import.
fn error_of(xml: &str, options: &UrdfOptions) -> (UrdfError, String) {
    let err = load_str(xml, "test.urdf", options)
        .err()
        .expect("import must fail");
    let text = err.to_string();
    assert!(!text.contains('\n'), "one line: {text}");
    (err, text)
}

#[test]
fn zero_axis_is_a_located_error() {
    let xml = chain(
        r#"<joint name="j3" type="revolute"><parent link="b"/><child link="c"/>
    <axis xyz="0 0 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>"#,
    );
    let line = 1 + xml[..xml.find("name=\"j3\"").unwrap()]
        .matches('\n')
        .count();
    let (err, text) = error_of(&xml, &UrdfOptions::default());
    assert!(matches!(err, UrdfError::Invalid(_)));
    assert!(
        text.starts_with(&format!("test.urdf:{line}: joint \"j3\"")),
        "{text}"
    );
    assert!(text.contains("axis"), "{text}");
}

#[test]
fn unknown_link_and_unsupported_type_are_errors() {
    let (_, text) = error_of(
        &chain(r#"<joint name="j3" type="fixed"><parent link="b"/><child link="zz"/></joint>"#),
        &UrdfOptions::default(),
    );
    assert!(
        text.contains("joint \"j3\"") && text.contains("\"zz\""),
        "{text}"
    );
    let (_, text) = error_of(
        &chain(r#"<joint name="j3" type="planar"><parent link="b"/><child link="c"/></joint>"#),
        &UrdfOptions::default(),
    );
    assert!(
        text.contains("joint \"j3\"") && text.contains("planar"),
        "{text}"
    );
}

#[test]
fn disconnected_and_cyclic_trees_are_errors() {
    let (_, text) = error_of(&chain(""), &UrdfOptions::default());
    assert!(
        text.contains("several root links") && text.contains('c'),
        "{text}"
    );
    let cyclic = chain(
        r#"<joint name="j3" type="fixed"><parent link="b"/><child link="c"/></joint>
  <joint name="j4" type="fixed"><parent link="c"/><child link="a"/></joint>"#,
    );
    let (_, text) = error_of(&cyclic, &UrdfOptions::default());
    assert!(
        text.contains("joint \"j4\"") && text.contains("already the child"),
        "{text}"
    );
}

#[test]
fn mimic_warns_by_default_and_is_rejected_on_request() {
    let xml = chain(
        r#"<joint name="j3" type="revolute"><parent link="b"/><child link="c"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/><mimic joint="j1" multiplier="2"/></joint>"#,
    );
    let imported = load_str(&xml, "m.urdf", &UrdfOptions::default()).unwrap();
    assert_eq!(imported.model.nq(), 2, "mimic joints stay independent");
    assert_eq!(imported.warnings.len(), 1);
    assert!(imported.warnings[0].contains("m.urdf:") && imported.warnings[0].contains("j3"));
    let reject = UrdfOptions {
        floating: false,
        reject_mimic: true,
    };
    let (_, text) = error_of(&xml, &reject);
    assert!(
        text.contains("joint \"j3\"") && text.contains("mimic"),
        "{text}"
    );
}

#[test]
fn missing_file_and_bad_xml_name_the_file() {
    let err = load_file("/nonexistent/robot.urdf", &UrdfOptions::default())
        .err()
        .unwrap();
    assert!(err.to_string().contains("/nonexistent/robot.urdf"));
    let (err, text) = error_of(
        "<robot name=\"x\"><link name=\"a\">",
        &UrdfOptions::default(),
    );
    assert!(matches!(err, UrdfError::Parse { .. }));
    assert!(text.starts_with("test.urdf:"), "{text}");
}

/// An imported (possibly corrupted but accepted) model: forward dynamics at the neutral
/// configuration is finite or a typed error, never a panic or a NaN.
fn dynamics_is_finite_or_error(model: &biped_dynamics::Model) -> Result<(), String> {
    let (q, v) = (model.neutral(), nalgebra::DVector::zeros(model.nv()));
    let tau = nalgebra::DVector::from_element(model.nv(), 0.1);
    let mut data = biped_dynamics::Data::new(model);
    let algo = biped_dynamics::Algorithm::On;
    match biped_dynamics::forward_dynamics(model, &mut data, &q, &v, &tau, None, algo) {
        Ok(ddq) if ddq.iter().any(|x| !x.is_finite()) => Err(format!("qddot {ddq:?}")),
        _ => Ok(()),
    }
}

/// Checks one import of mutated text: a one-line error naming the source, or a model whose
/// dynamics are finite or a typed error.
fn check_mutated(bytes: &[u8], options: &UrdfOptions) -> Result<(), String> {
    let xml = String::from_utf8_lossy(bytes);
    match load_str(&xml, "mutated.urdf", options) {
        Err(e) => {
            let text = e.to_string();
            match !text.contains('\n') && text.starts_with("mutated.urdf") {
                true => Ok(()),
                false => Err(format!("error not one located line: {text}")),
            }
        }
        Ok(imported) => dynamics_is_finite_or_error(&imported.model),
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(200))]

    /// Random byte edits of the G1 file, floating base: never a panic.
    #[test]
    fn mutated_g1_never_panics(edits in mutate::byte_edits(6)) {
        let bytes = mutate::apply(&std::fs::read(g1_path()).unwrap(), &edits);
        let options = UrdfOptions { floating: true, ..UrdfOptions::default() };
        let r = check_mutated(&bytes, &options);
        proptest::prop_assert!(r.is_ok(), "{:?}", r);
    }

    /// Numbers of the G1 file replaced by edge values (zero, +-1e308, subnormal, negative):
    /// masses, inertias, origins, axes and limits reach the import's checks.
    #[test]
    fn edge_numbers_in_g1_never_panic(edits in mutate::number_edits(4)) {
        let text = mutate::apply_numbers(&std::fs::read_to_string(g1_path()).unwrap(), &edits);
        let options = UrdfOptions { floating: true, ..UrdfOptions::default() };
        let r = check_mutated(text.as_bytes(), &options);
        proptest::prop_assert!(r.is_ok(), "{:?}", r);
    }

    /// Edits of the three-link chain by the characters of XML structure and numbers (most
    /// land in attributes that matter there): never a panic.
    #[test]
    fn structural_mutations_of_a_chain_never_panic(
        edits in mutate::structural_edits(b"<>/\"=-9e.0 \nxyz", 4),
    ) {
        let bytes = mutate::apply(chain(J3_OK).as_bytes(), &edits);
        let r = check_mutated(&bytes, &UrdfOptions::default());
        proptest::prop_assert!(r.is_ok(), "{:?}", r);
    }
}
