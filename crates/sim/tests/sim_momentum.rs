//! The recorder's centroidal sample (sum of body momenta over one kinematics pass) equals
//! the centroidal momentum matrix route `h_G = A_G v` of `Centroidal::compute`, on Lola
//! Type 2 and Type 3 (coupled rotors, roller screws, slider-cranks) at random states.

use biped_dynamics::{Centroidal, Data};
use biped_robots::lola::{self, LolaType};
use biped_sim::simulation::centroidal_sample;
use nalgebra::DVector;
use proptest::prelude::*;

fn check(kind: LolaType, dq: &[f64], v: &[f64]) {
    let lm = lola::build(kind).unwrap();
    let m = &lm.model;
    let mut q = m.neutral();
    // Perturb the joint angles (after the 7 free-flyer coordinates) and the base position.
    for (k, x) in q.iter_mut().enumerate().skip(7).take(dq.len()) {
        *x += dq[k % dq.len()];
    }
    q[0] += dq[0];
    let v = DVector::from_fn(m.nv(), |i, _| v[i % v.len()]);
    let mut d = Data::new(m);
    let s = centroidal_sample(m, &mut d, &q, &v).unwrap();
    let mut c = Centroidal::new(m);
    c.compute(m, &mut Data::new(m), &q, &v).unwrap();
    let h = c.momentum().unwrap();
    let scale = 1.0 + h.ang.norm() + h.lin.norm();
    assert!((s.com - c.com()).norm() < 1e-12, "{} vs {}", s.com, c.com());
    assert!(
        (s.momentum.ang - h.ang).norm() < 1e-10 * scale,
        "{} vs {}",
        s.momentum.ang,
        h.ang
    );
    assert!(
        (s.momentum.lin - h.lin).norm() < 1e-10 * scale,
        "{} vs {}",
        s.momentum.lin,
        h.lin
    );
    assert!(h.ang.norm() > 1e-3, "a non-trivial case");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]
    #[test]
    fn centroidal_sample_equals_ag_times_v(
        dq in prop::collection::vec(-0.2f64..0.2, 7),
        v in prop::collection::vec(-1.5f64..1.5, 11),
        type3 in any::<bool>(),
    ) {
        let kind = if type3 { LolaType::Type3 } else { LolaType::Type2 };
        check(kind, &dq, &v);
    }
}

/// After a plant right-hand side the plant's workspace holds the forward-dynamics first pass
/// at that state (the solve keeps it), so `centroidal_momentum_current` on it equals the
/// recorder's own sample there (no second kinematics pass needed at a shared state).
#[test]
fn plant_rhs_kinematics_give_the_same_sample() {
    use biped_dynamics::centroidal_momentum_current;
    use biped_robots::plant::lola_plant;
    use biped_sim::plant::PlantConfig;
    use biped_sim::OdeSystem;
    let mut plant = lola_plant(LolaType::Type2, PlantConfig::default())
        .unwrap()
        .plant;
    let m = plant.model().clone();
    let mut q = m.neutral();
    q[2] += 1.0; // off the ground
    for (k, x) in q.iter_mut().enumerate().skip(7) {
        *x += 0.05 * ((k % 5) as f64 - 2.0);
    }
    let v = DVector::from_fn(m.nv(), |i, _| 0.3 * ((i % 7) as f64 - 3.0));
    let z = plant.initial_state(&q, &v).unwrap();
    let mut zdot = vec![0.0; z.len()];
    plant.rhs(0.0, &z, &mut zdot).unwrap();
    let c = centroidal_momentum_current(plant.model(), plant.data()).unwrap();
    let s = centroidal_sample(&m, &mut Data::new(&m), &q, &v).unwrap();
    assert_eq!(c.com, s.com);
    assert_eq!(c.momentum, s.momentum);
    assert!(s.momentum.ang.norm() > 1e-3, "a non-trivial case");
}
