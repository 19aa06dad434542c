//! The foot force control of the dynamic walk: its leg offsets move a sole as asked (forward
//! kinematics of the offset joints), and with it the default walk's feet share the ground
//! without the hops of the position-controlled legs.

use biped_control::walk::dynamic::{ForceControl, ForceGains};
use biped_control::walk::{run_dynamic_walk, DynamicWalkParams};
use biped_dynamics::{update_placements, Data};
use biped_robots::lola::{self, LolaType};
use biped_robots::plant::lola_plant;
use biped_sim::plant::PlantConfig;
use nalgebra::{DVector, Vector3};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// `leg_offsets(dp)` moves the sole by `dp` relative to the pelvis and keeps its
    /// orientation, for knees bent as in walking (0.5 rad and more: the damped least squares
    /// shorten a step by < 3 % there; towards the stretched knee the vertical step shrinks).
    #[test]
    fn leg_offsets_move_the_sole_by_the_asked_amount(
        knee in 0.5f64..1.2,
        side in 0usize..2,
        dp in prop::array::uniform3(-1e-3f64..1e-3),
    ) {
        let lola = lola::build(LolaType::Type2).unwrap();
        let plant = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap().plant;
        let mut fc = ForceControl::new(&lola, &plant, ForceGains::default()).unwrap();
        let model = &lola.model;
        let mut q = model.neutral();
        for (name, x) in [("thigh", -knee / 2.0), ("shank", knee), ("ankle_cross", -knee / 2.0)] {
            for s in ["l", "r"] {
                let l = lola.limits.iter().find(|l| l.name == format!("{s}_{name}")).unwrap();
                q[l.q_index] = x;
            }
        }
        let angles: Vec<f64> = lola.limits.iter().map(|l| q[l.q_index]).collect();
        let dp = Vector3::from(dp);
        let dq = fc.leg_offsets_at(&angles, side, dp).unwrap();
        let sole = model.body_id(["l_sole", "r_sole"][side]).unwrap();
        let mut data = Data::new(model);
        update_placements(model, &mut data, &q).unwrap();
        let (p0, r0) = (data.world_pos[sole], data.world_rot[sole]);
        let mut q1: DVector<f64> = q.clone();
        for (l, d) in lola.limits.iter().zip(&dq) {
            q1[l.q_index] += d;
        }
        update_placements(model, &mut data, &q1).unwrap();
        let moved = data.world_pos[sole] - p0;
        prop_assert!((moved - dp).norm() < 0.03 * dp.norm() + 1e-7, "{moved} for {dp}");
        let turn = (data.world_rot[sole] * r0.transpose() - nalgebra::Matrix3::identity()).norm();
        prop_assert!(turn < 0.03 * dp.norm() + 1e-7, "orientation changed by {turn}");
        // Only the leg of that side moves.
        let other = ["r_", "l_"][side];
        for (l, d) in lola.limits.iter().zip(&dq) {
            if l.name.starts_with(other) || !(l.name.starts_with("l_") || l.name.starts_with("r_")) {
                prop_assert_eq!(*d, 0.0, "{}", l.name);
            }
        }
    }
}

/// The default 10-step walk with the force control: a foot on the ground nearly throughout
/// (no flight phase over 5 ms) and landings below 4x the mean ground force; without it the
/// same walk hops at the step changes.
#[test]
fn the_force_control_keeps_a_foot_on_the_ground() {
    let with = run_dynamic_walk(&DynamicWalkParams::default())
        .unwrap()
        .summary;
    assert!(with.walked, "{with:?}");
    assert!(with.longest_flight < 0.005, "{with:?}");
    assert!(
        with.peak_ground_force < 4.0 * with.mean_ground_force,
        "{with:?}"
    );
    let without = DynamicWalkParams {
        force: None,
        ..DynamicWalkParams::default()
    };
    let without = run_dynamic_walk(&without).unwrap().summary;
    assert!(without.longest_flight > 0.02, "{without:?}");
    assert!(!without.contact_kept, "{without:?}");
    assert!(
        without.flight_time > 5.0 * with.flight_time.max(1e-3),
        "{without:?}"
    );
}
