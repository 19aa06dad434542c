//! The kinematics step kinds precomputed in `Data::new` agree with the per-pass chain of
//! checks they replace (`Data::step_kinds_match_checks`) on the shipped URDF model, fixed and
//! floating base (the Lola models are checked in `biped_robots`' tests).

use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::Data;
use std::path::PathBuf;

#[test]
fn urdf_step_kinds_match_the_checks() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/g1_29dof_rev_1_0.urdf");
    let floating = UrdfOptions {
        floating: true,
        ..UrdfOptions::default()
    };
    for options in [UrdfOptions::default(), floating] {
        let model = load_file(&path, &options)
            .expect("shipped URDF loads")
            .model;
        assert!(Data::new(&model).step_kinds_match_checks(&model));
    }
}
