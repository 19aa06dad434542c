//! Centroidal momentum of both Lola types (Harmonic Drive rotors, knee riders, ankle screw
//! rotors and sliding nuts lumped into their carriers' terms) against an independent route:
//! the linear momentum is the mass times the CoM velocity, a central difference of the CoM
//! along `q(t) = q (+) v t`.

use biped_dynamics::{centroidal_momentum, integrate, Data};
use biped_robots::lola::{self, LolaType};
use rand::{Rng, SeedableRng};

#[test]
fn linear_momentum_is_mass_times_com_rate() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(5);
    for t in [LolaType::Type2, LolaType::Type3] {
        let lm = lola::build(t).expect("shipped file builds");
        let (m, mut data) = (&lm.model, Data::new(&lm.model));
        for _ in 0..10 {
            let (q, v) = lm.random_state(&mut |a, b| rng.random_range(a..b));
            let mut com_at = |s: f64| {
                let qs = integrate(m, &q, &v, s).expect("integrates");
                centroidal_momentum(m, &mut data, &qs, &v)
                    .expect("momentum")
                    .com
            };
            let h = 1e-6;
            let rate = (com_at(h) - com_at(-h)) / (2.0 * h);
            let s = centroidal_momentum(m, &mut data, &q, &v).expect("momentum");
            let p = s.momentum.lin;
            let err = (rate * s.mass - p).norm();
            assert!(err < 1e-6 * (1.0 + p.norm()), "{t:?}: {err:e}, p {p}");
        }
    }
}
