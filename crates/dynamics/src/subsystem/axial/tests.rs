use super::*;
use crate::spatial::Axis;
use nalgebra::{Isometry3, Matrix3, Vector3};

/// The constant congruence equals the spun one at any angle; asymmetric rotors get none.
#[test]
fn spin_invariant_matches_spun_congruence() {
    let ic = Matrix3::from_diagonal(&Vector3::new(2e-5, 2e-5, 3e-5));
    let rotor = RigidInertia::new(0.15, Vector3::new(0.0, 0.0, 0.01), ic).expect("valid");
    let pose = Isometry3::new(Vector3::new(0.3, -0.1, 0.7), Vector3::new(0.9, -0.4, 1.2));
    let frame = SpatialTransform::from_pose(&pose);
    let k = spin_invariant(&rotor, &frame).expect("axisymmetric");
    for angle in [0.3, -2.0, 17.0, 1234.5] {
        let (s, c) = f64::sin_cos(angle);
        let x = SpatialTransform::new(Axis::Z.rot_tr_mul(s, c, &frame.rot), frame.trans);
        let dense = x.to_matrix().transpose() * rotor.to_matrix() * x.to_matrix();
        assert!((k.to_matrix() - dense).amax() < 1e-14);
    }
    // The constant B_S / M_S contributions against the dense C^T M J and J^T M J.
    let j = Motion::new(Vector3::new(0.0, 0.0, -80.0), Vector3::zeros());
    let sp = frame.inv_apply_motion(&j);
    let ks = k.apply(&sp).to_vector();
    let (s, c) = f64::sin_cos(2.3);
    let x = SpatialTransform::new(Axis::Z.rot_tr_mul(s, c, &frame.rot), frame.trans);
    let (m, jv) = (rotor.to_matrix(), j.to_vector());
    let dense = x.to_matrix().transpose() * m * jv;
    assert!((ks - dense).amax() < 1e-12 * dense.amax());
    let jmj = (jv.transpose() * m * jv)[0];
    assert!((sp.to_vector().dot(&ks) - jmj).abs() < 1e-12 * jmj);
    let off_axis = RigidInertia::new(0.15, Vector3::new(1e-3, 0.0, 0.0), ic).expect("valid");
    assert!(spin_invariant(&off_axis, &frame).is_none());
    let flat = Matrix3::from_diagonal(&Vector3::new(2e-5, 2.1e-5, 3e-5));
    let flat = RigidInertia::new(0.15, Vector3::zeros(), flat).expect("valid");
    assert!(spin_invariant(&flat, &frame).is_none());
}

/// Ankle roller-screw rotors take the axial path (rate from the loop) when axisymmetric
/// about the screw axis, the general one otherwise; nuts always do (sliders), rods never.
#[test]
fn ankle_screw_parts_qualify() {
    use crate::mechanism::ankle::AnklePart;
    for off_axis in [false, true] {
        let (model, parts) = ankle_leg(off_axis);
        let data = crate::Data::new(&model);
        for &(act, part, j) in &parts {
            let kind = data.axial_member[j].map(|rc| rc.kind);
            let expected = match part {
                AnklePart::Rotor if off_axis && act == 1 => None,
                AnklePart::Rotor => Some(AxialKind::Screw),
                AnklePart::Nut => Some(AxialKind::Slider),
                AnklePart::Rod => None,
            };
            assert_eq!(kind, expected, "{part:?} {act}");
        }
    }
}

/// A lumped member's spin torque and load against the whole parent-frame bias: the bias
/// less the rigid-body forces of its carrier-frame inertia is `[torque; 0]`, and `s . h`
/// is the load (ankle screw rotors: speed, spin acceleration and an off-origin `s`).
#[test]
fn spin_load_matches_parent_frame_bias() {
    let (model, _) = ankle_leg(false);
    let data = crate::Data::new(&model);
    let lumped = data.axial_members.iter().filter(|(_, rc)| rc.lumped());
    let (w, g) = (Vector3::new(0.7, -1.3, 2.1), Vector3::new(0.4, -2.0, -9.5));
    let mut n = 0;
    for (_, rc) in lumped {
        let (qd, sigma) = (-3.7, 55.0);
        let h = parent_frame_bias(rc, &w, &g, (rc.com, qd, sigma));
        let (torque, load) = rc.spin_load(&w, &g, (qd, sigma));
        let rigid = RigidInertia::new(rc.mass, rc.com, rc.inertia_com).expect("valid");
        let spin = h - (rigid.bias_force(&w) - rigid.gravity_force(&g));
        let scale = h.to_vector().amax();
        assert!((spin.ang - torque).amax() < 1e-13 * scale && spin.lin.amax() < 1e-13 * scale);
        assert!((rc.s.dot(&h) - load).abs() < 1e-13 * scale);
        n += 1;
    }
    assert!(n > 0);
}

/// The knee's rotor (when axisymmetric) and nut ride on the housing of the same drive,
/// which carries them with its inertia plus the rotor's as the constant base.
#[test]
fn knee_parts_ride_on_the_housing() {
    use crate::mechanism::knee::{KneeDrive, KneeDriveParams, KneePart};
    use crate::model::{BodySpec, ModelBuilder};
    let drive = KneeDrive::new(KneeDriveParams::default()).expect("drive");
    let ic = Matrix3::from_diagonal(&Vector3::new(4e-5, 4e-5, 2e-5));
    for round_rotor in [true, false] {
        let com = Vector3::new(if round_rotor { 0.0 } else { 1e-3 }, 0.0, 0.05);
        let rotor = RigidInertia::new(0.1, com, ic).expect("valid");
        let part = RigidInertia::new(0.2, Vector3::new(0.0, 0.0, 0.1), ic).expect("valid");
        let mut b = ModelBuilder::new();
        let mut add = |name: &str, parent, joint, inertia| {
            let spec = BodySpec::named(name, parent, joint, Isometry3::identity(), inertia);
            b.add_body(spec).expect("body")
        };
        let z = JointModel::Revolute {
            axis: Vector3::z_axis(),
        };
        let thigh = add("thigh", None, z.clone(), part);
        let shank = add("shank", Some(thigh), z, part);
        let mut ids = vec![];
        for (p, inertia) in [
            (KneePart::Housing, part),
            (KneePart::Nut, part),
            (KneePart::Rotor, rotor),
        ] {
            let joint = JointModel::Coupled {
                mechanism: Mechanism::Knee(drive.part(p)),
                inputs: vec![shank],
            };
            ids.push(add(&format!("{p:?}"), Some(thigh), joint, inertia));
        }
        let model = b.build().expect("model");
        let data = crate::Data::new(&model);
        let (housing, nut, rotor) = (ids[0], ids[1], ids[2]);
        assert!(data.axial_member[housing].is_none());
        let rider = |j: usize| data.axial_member[j].map(|rc| (rc.kind, rc.carrier, rc.rider));
        assert_eq!(rider(nut), Some((AxialKind::Slider, housing, true)));
        let expect = round_rotor.then_some((AxialKind::Screw, housing, true));
        assert_eq!(rider(rotor), expect);
        let carried = data.carried[housing].as_ref().expect("carrier");
        let base = if round_rotor { 0.3 } else { 0.2 };
        assert!((carried.base.mass() - base).abs() < 1e-15);
        assert_eq!(carried.riders.len(), if round_rotor { 2 } else { 1 });
    }
}

/// Shank, ankle cross and foot with the six parts of the default ankle drive; rotor 1's
/// CoM off its axis if `off_axis`. Returns the model and the parts (actuator, part, body).
fn ankle_leg(
    off_axis: bool,
) -> (
    Model,
    Vec<(usize, crate::mechanism::ankle::AnklePart, usize)>,
) {
    use crate::mechanism::ankle::{AnkleDrive, AnkleDriveParams, AnklePart};
    use crate::model::{BodySpec, ModelBuilder};
    let drive = AnkleDrive::new(AnkleDriveParams::default()).expect("drive");
    let ic = Matrix3::from_diagonal(&Vector3::new(4e-5, 4e-5, 2e-5));
    let com = |x| Vector3::new(x, 0.0, 0.05);
    let round = RigidInertia::new(0.1, com(0.0), ic).expect("valid");
    let off = RigidInertia::new(0.1, com(1e-3), ic).expect("valid");
    let mut b = ModelBuilder::new();
    let mut add = |name: String, parent, joint, inertia| {
        let spec = BodySpec::named(&name, parent, joint, Isometry3::identity(), inertia);
        b.add_body(spec).expect("body")
    };
    let rev = |axis| JointModel::Revolute { axis };
    let shank = add("shank".into(), None, rev(Vector3::z_axis()), round);
    let cross = add("cross".into(), Some(shank), rev(Vector3::y_axis()), round);
    let foot = add("foot".into(), Some(cross), rev(Vector3::x_axis()), round);
    let mut parts = vec![];
    for act in 0..2 {
        for part in [AnklePart::Nut, AnklePart::Rotor, AnklePart::Rod] {
            let joint = JointModel::Coupled {
                mechanism: Mechanism::Ankle(drive.part(act, part).expect("part")),
                inputs: vec![cross, foot],
            };
            let inertia = if off_axis && act == 1 { off } else { round };
            let j = add(format!("{part:?}{act}"), Some(shank), joint, inertia);
            parts.push((act, part, j));
        }
    }
    (b.build().expect("model"), parts)
}
