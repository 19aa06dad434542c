//! URDF import checked through the dynamics: equivalent URDFs must give identical mass matrices
//! and inverse dynamics (fixed-joint merging, inertial frames, axis normalisation, floating base).

use biped_dynamics::urdf::{load_file, load_str, UrdfOptions};
use biped_dynamics::{inverse_dynamics, mass_matrix, Data, Model};
use nalgebra::{DMatrix, DVector};
use std::path::PathBuf;

/// Loads URDF text with a fixed base.
fn load(xml: &str) -> Model {
    load_str(xml, "test.urdf", &UrdfOptions::default())
        .unwrap()
        .model
}

/// Mass matrix at `q`.
fn mm(model: &Model, q: &DVector<f64>) -> DMatrix<f64> {
    let mut data = Data::new(model);
    mass_matrix(model, &mut data, q).unwrap().clone()
}

/// Inverse dynamics at (q, v, a).
fn id(model: &Model, q: &DVector<f64>, v: &DVector<f64>, a: &DVector<f64>) -> DVector<f64> {
    let mut data = Data::new(model);
    inverse_dynamics(model, &mut data, q, v, a, None)
        .unwrap()
        .clone()
}

/// A four-link chain base -j1- a -j2- b -j3- c whose middle joint j2 is `JOINT2` (fixed or not).
fn chain(joint2_type: &str, extra: &str, b_inertial: &str, axis3: &str) -> String {
    format!(
        r#"<robot name="chain">
  <link name="base"/>
  <link name="a"><inertial><mass value="1"/><origin xyz="0.1 0.02 0" rpy="0.1 0 0"/>
    <inertia ixx="0.01" ixy="0.001" ixz="0" iyy="0.02" iyz="0" izz="0.025"/></inertial></link>
  <link name="b">{b_inertial}</link>
  <link name="c"><inertial><mass value="0.2"/><origin xyz="0 0 -0.1"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.0015"/></inertial></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/>
    <origin xyz="0 0 0.5" rpy="0.2 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j2" type="{joint2_type}"><parent link="a"/><child link="b"/>
    <origin xyz="0.3 0 0.1" rpy="0 0.4 0.5"/>{extra}</joint>
  <joint name="j3" type="continuous"><parent link="b"/><child link="c"/>
    <origin xyz="0.2 0.1 0" rpy="0.3 0 0"/><axis xyz="{axis3}"/></joint>
</robot>"#
    )
}

const B_INERTIAL: &str = r#"<inertial><mass value="0.5"/><origin xyz="0.05 0.1 0" rpy="0.3 0.2 0.1"/>
    <inertia ixx="0.002" ixy="0" ixz="0" iyy="0.003" iyz="0" izz="0.004"/></inertial>"#;
const J2_AXIS: &str = r#"<axis xyz="1 0 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/>"#;

#[test]
fn fixed_joint_equals_locked_revolute_joint() {
    let fixed = load(&chain("fixed", "", B_INERTIAL, "0 0 1"));
    let free = load(&chain("revolute", J2_AXIS, B_INERTIAL, "0 0 1"));
    assert_eq!((fixed.nv(), free.nv()), (2, 3));
    let (q1, q3) = (0.7, -0.4);
    let qf = DVector::from_vec(vec![q1, q3]);
    let qr = DVector::from_vec(vec![q1, 0.0, q3]);
    let keep = [0usize, 2];
    let m_fixed = mm(&fixed, &qf);
    let m_free = mm(&free, &qr);
    for (i, &ri) in keep.iter().enumerate() {
        for (j, &rj) in keep.iter().enumerate() {
            let (a, b) = (m_fixed[(i, j)], m_free[(ri, rj)]);
            assert!((a - b).abs() < 1e-12, "M[{i}][{j}]: {a} vs {b}");
        }
    }
    // Same with velocities and gravity: locked joint has zero rate and acceleration.
    let (v, a) = (
        DVector::from_vec(vec![0.3, -1.2]),
        DVector::from_vec(vec![0.5, 2.0]),
    );
    let widen = |x: &DVector<f64>| DVector::from_vec(vec![x[0], 0.0, x[1]]);
    let t_fixed = id(&fixed, &qf, &v, &a);
    let t_free = id(&free, &qr, &widen(&v), &widen(&a));
    for (i, &ri) in keep.iter().enumerate() {
        assert!((t_fixed[i] - t_free[ri]).abs() < 1e-11, "tau[{i}]");
    }
}

#[test]
fn inertial_rotation_equals_pre_rotated_tensor() {
    // diag(2, 3, 4)e-3 turned by 90 deg about z is diag(3, 2, 4)e-3; by 90 deg about x diag(2, 4, 3)e-3.
    let rotated = r#"<inertial><mass value="0.5"/><origin xyz="0.05 0.1 0" rpy="1.5707963267948966 0 1.5707963267948966"/>
    <inertia ixx="0.002" ixy="0" ixz="0" iyy="0.003" iyz="0" izz="0.004"/></inertial>"#;
    // R = Rz(90) Rx(90): body axes x_b = R e_x = e_y, y_b = R e_y = e_z, z_b = R e_z = e_x,
    // so the link-frame moments are I_xx = 0.004 (z_b), I_yy = 0.002 (x_b), I_zz = 0.003 (y_b).
    let by_hand = r#"<inertial><mass value="0.5"/><origin xyz="0.05 0.1 0"/>
    <inertia ixx="0.004" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.003"/></inertial>"#;
    let m1 = load(&chain("revolute", J2_AXIS, rotated, "0 0 1"));
    let m2 = load(&chain("revolute", J2_AXIS, by_hand, "0 0 1"));
    let q = DVector::from_vec(vec![0.3, -0.8, 1.1]);
    assert!((mm(&m1, &q) - mm(&m2, &q)).amax() < 1e-14);
}

#[test]
fn joint_axis_is_normalised() {
    let unit = load(&chain("fixed", "", B_INERTIAL, "0 0.6 0.8"));
    let long = load(&chain("fixed", "", B_INERTIAL, "0 3 4"));
    let q = DVector::from_vec(vec![0.4, 0.9]);
    assert!((mm(&unit, &q) - mm(&long, &q)).amax() < 1e-15);
}

#[test]
fn floating_base_joint_block_equals_fixed_base_mass_matrix() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/g1_29dof_rev_1_0.urdf");
    let floating = UrdfOptions {
        floating: true,
        reject_mimic: false,
    };
    let free = load_file(&path, &floating).unwrap().model;
    let fixed = load_file(&path, &UrdfOptions::default()).unwrap().model;
    let n = fixed.nv();
    let joints = DVector::from_fn(n, |k, _| (0.37 * (k as f64 + 1.0)).sin());
    let mut q = free.neutral();
    q.rows_mut(0, 3).copy_from_slice(&[0.3, -0.2, 0.9]);
    let quat = nalgebra::Vector4::new(0.1, -0.3, 0.2, 0.9).normalize();
    q.rows_mut(3, 4).copy_from(&quat);
    q.rows_mut(7, n).copy_from(&joints);
    let m_free = mm(&free, &q);
    let m_fixed = mm(&fixed, &joints);
    let block = m_free.view((6, 6), (n, n));
    assert!((block - &m_fixed).amax() < 1e-12 * m_fixed.amax());
}

#[test]
fn urdf_floating_joint_equals_floating_option() {
    let body = chain("revolute", J2_AXIS, B_INERTIAL, "0 0 1");
    let with_world = body.replace(
        "<link name=\"base\"/>",
        "<link name=\"world\"/>\n  <link name=\"base\"><inertial><mass value=\"2\"/>\
         <inertia ixx=\"0.1\" ixy=\"0\" ixz=\"0\" iyy=\"0.2\" iyz=\"0\" izz=\"0.25\"/></inertial></link>\n  \
         <joint name=\"free\" type=\"floating\"><parent link=\"world\"/><child link=\"base\"/></joint>",
    );
    let own = load(&with_world);
    let option = load_str(
        &with_world.replace(
            "<link name=\"world\"/>",
            "",
        )
        .replace(
            "<joint name=\"free\" type=\"floating\"><parent link=\"world\"/><child link=\"base\"/></joint>",
            "",
        ),
        "test.urdf",
        &UrdfOptions {
            floating: true,
            reject_mimic: false,
        },
    )
    .unwrap()
    .model;
    assert_eq!((own.nq(), own.nv()), (10, 9));
    assert_eq!(own.joints()[0].name, "free");
    assert_eq!(option.joints()[0].name, "root");
    let mut q = own.neutral();
    q.rows_mut(0, 7)
        .copy_from_slice(&[0.1, 0.2, 0.3, 0.2, -0.1, 0.3, 0.9]);
    let norm = q.rows(3, 4).norm();
    q.rows_mut(3, 4).unscale_mut(norm);
    q.rows_mut(7, 3).copy_from_slice(&[0.4, -0.5, 0.6]);
    assert!((mm(&own, &q) - mm(&option, &q)).amax() < 1e-14);
}
