//! The kinematics fast paths chosen per body in `Data::new` give the general step's results
//! (up to rounding) on the shipped URDF model, fixed and floating base, at random states:
//! world poses, `g_i`, velocities, bias and conventional accelerations, in the general and the
//! forward-dynamics passes (the Lola models are checked in `biped_robots`' tests).

mod kin_support;

use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::Model;
use kin_support::{fast_path_deviation, fd_pass_deviation};
use nalgebra::{DVector, Vector4};
use proptest::prelude::*;
use std::path::PathBuf;
use std::sync::OnceLock;

/// The shipped G1 URDF, fixed (`false`) and floating (`true`) base.
fn g1(floating: bool) -> &'static Model {
    static MODELS: OnceLock<[Model; 2]> = OnceLock::new();
    let models = MODELS.get_or_init(|| {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/g1_29dof_rev_1_0.urdf");
        [false, true].map(|floating| {
            let options = UrdfOptions {
                floating,
                ..UrdfOptions::default()
            };
            load_file(&path, &options)
                .expect("shipped URDF loads")
                .model
        })
    });
    &models[usize::from(floating)]
}

/// `q` of `model`: the free joint's position `xs[..3]` and orientation `xs[3..7]` (normalised)
/// if `floating`, the joint angles from the rest of `xs`.
fn configuration(model: &Model, floating: bool, xs: &[f64]) -> DVector<f64> {
    let mut q = DVector::from_column_slice(&xs[..model.nq()]);
    if floating {
        let quat = Vector4::from_column_slice(&xs[3..7])
            .add_scalar(1e-3)
            .normalize();
        q.rows_mut(3, 4).copy_from(&quat);
    }
    q
}

proptest! {
    /// Fast and general paths agree at random states, both bases.
    #[test]
    fn urdf_fast_paths_equal_the_general_step(
        floating in any::<bool>(),
        xs in prop::collection::vec(-3.0f64..3.0, 64),
        vs in prop::collection::vec(-4.0f64..4.0, 64),
        accs in prop::collection::vec(-4.0f64..4.0, 64),
    ) {
        let model = g1(floating);
        let q = configuration(model, floating, &xs);
        let (v, a) = (DVector::from_column_slice(&vs[..model.nv()]), DVector::from_column_slice(&accs[..model.nv()]));
        let dev = fast_path_deviation(model, &q, &v, &a);
        prop_assert!(dev < 1e-12, "forward kinematics {dev:e}");
        let (dev, skipped) = fd_pass_deviation(model, &q, &v);
        prop_assert!(dev < 1e-12, "forward-dynamics kinematics {dev:e}");
        prop_assert!(skipped.is_empty(), "{skipped:?}");
    }
}
