//! The trajectory of a walk replays: forward kinematics of each row's coordinates gives the
//! row's sole frames and CoM (computed here independently of the IK), the feet stand on the
//! ground `z = 0` in support, and the ground force carries the robot's weight.

use biped_control::pattern::{Contact, PatternParams, WalkingPattern};
use biped_control::walk::{run_walk, walk_pattern_params, Method, WalkParams};
use biped_dynamics::{center_of_mass, Data};
use biped_robots::lola::{build, LolaType};
use nalgebra::{DVector, Quaternion, UnitQuaternion};

#[test]
fn trajectory_rows_replay_soles_and_com() {
    let lola = build(LolaType::Type2).unwrap();
    let params = PatternParams {
        start_time: 0.3,
        end_time: 0.3,
        ..walk_pattern_params(&lola, 3, 0.4, 0.8).unwrap()
    };
    let pattern = WalkingPattern::generate(&params).unwrap();
    let run = run_walk(&lola, &pattern, Method::Minimization, WalkParams::default()).unwrap();
    let tr = &run.trajectory;
    let model = &lola.model;
    assert_eq!(tr.len(), pattern.len());
    assert_eq!(tr.q_names, model.q_names());
    assert_eq!(tr.columns().len(), tr.row(0).count());
    let mass: f64 = model.bodies().iter().map(|b| b.inertia().mass()).sum();
    let soles = ["l_sole", "r_sole"].map(|n| model.body_id(n).unwrap());
    let mut data = Data::new(model);
    let samples: Vec<_> = pattern.iter().collect();
    for k in (0..tr.len()).step_by(97) {
        let q = DVector::from_column_slice(tr.q_row(k));
        // Runs the kinematics into `data` too.
        let com = center_of_mass(model, &mut data, &q, None).unwrap().position;
        for (side, &b) in soles.iter().enumerate() {
            let row = tr.soles[k][side];
            let p = data.world_pos[b];
            assert!((p - nalgebra::Vector3::new(row[0], row[1], row[2])).norm() < 1e-12);
            let r =
                UnitQuaternion::from_quaternion(Quaternion::new(row[6], row[3], row[4], row[5]));
            let diff = r.to_rotation_matrix().matrix() - data.world_rot[b];
            assert!(diff.norm() < 1e-9, "row {k} side {side}");
            if samples[k].feet[side].contact == Contact::Flat {
                assert!(row[2].abs() < 0.01, "row {k}: flat sole at z = {}", row[2]);
            }
        }
        let row = tr.com[k];
        assert!((com - nalgebra::Vector3::new(row[0], row[1], row[2])).norm() < 1e-12);
        let fz = tr.ground[k][2];
        assert!((fz / (mass * 9.81) - 1.0).abs() < 0.2, "row {k}: f_z {fz}");
    }
}
