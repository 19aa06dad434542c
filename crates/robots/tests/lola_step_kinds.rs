//! The kinematics fast paths chosen per body in `Data::new` give the general step's results
//! (up to rounding) on both Lola types, whose Harmonic Drive rotors, knee and ankle parts,
//! feet frames and free base take every step kind: world poses, `g_i`, velocities, bias and
//! conventional accelerations at random states; the forward-dynamics pass leaves exactly the
//! rotor-type axial members untouched.

#[path = "../../dynamics/tests/kin_support/mod.rs"]
mod kin_support;

use biped_dynamics::JointModel;
use biped_robots::lola::{self, LolaType};
use kin_support::{fast_path_deviation, fd_pass_deviation};
use nalgebra::DVector;
use rand::{Rng, SeedableRng};

#[test]
fn lola_fast_paths_equal_the_general_step() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(11);
    for t in [LolaType::Type2, LolaType::Type3] {
        let lm = lola::build(t).expect("shipped file builds");
        let m = &lm.model;
        for _ in 0..20 {
            let (q, v) = lm.random_state(&mut |a, b| rng.random_range(a..b));
            let a = DVector::from_fn(m.nv(), |_, _| rng.random_range(-5.0..5.0));
            let dev = fast_path_deviation(m, &q, &v, &a);
            assert!(dev < 1e-12, "{t:?} forward kinematics {dev:e}");
            let (dev, skipped) = fd_pass_deviation(m, &q, &v);
            assert!(dev < 1e-12, "{t:?} forward-dynamics kinematics {dev:e}");
            let rotor = |&i: &usize| {
                let body = &m.bodies()[i];
                let rotor_joint = matches!(
                    body.joint(),
                    JointModel::GearedRotor { .. } | JointModel::Coupled { .. }
                );
                rotor_joint && body.first_child().is_none()
            };
            assert!(
                !skipped.is_empty() && skipped.iter().all(rotor),
                "{t:?} {skipped:?}"
            );
        }
    }
}
