//! `advance` performs no heap allocation: a counting global allocator observes every call
//! of the test thread.

mod ode_support;

use biped_sim::ode::{Integrator, Method, Settings};
use biped_test_support::alloc::{allocations, Counting};
use ode_support::Kepler;

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn advance_does_not_allocate() {
    for method in Method::ALL {
        let mut integ = Integrator::new(method, 4, Settings::fixed(1e-3)).expect("settings");
        let mut z = Kepler::initial(0.5);
        let outputs = [0.25, 0.3, 0.35];
        let mut sum = 0.0;
        let before = allocations();
        for k in 0..20 {
            let (t0, t1) = (0.01 * k as f64, 0.01 * (k + 1) as f64);
            integ
                .advance_split(&mut Kepler, t0, t1, &mut z)
                .expect("integrates");
        }
        integ
            .advance_split_dense(&mut Kepler, 0.2, 0.4, &mut z, &outputs, |_, y| sum += y[0])
            .expect("integrates");
        let after = allocations();
        assert_eq!(after - before, 0, "{method} allocated");
        assert!(sum.is_finite() && sum != 0.0);
    }
}
