//! One walking IK cycle allocates nothing (counting global allocator), for every method.

use biped_control::pattern::WalkingPattern;
use biped_control::walk::{walk_pattern_params, Method, WalkController, WalkParams};
use biped_robots::lola::{self, LolaType};
use biped_test_support::alloc::{allocations, Counting};

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn cycle_does_not_allocate() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let pattern =
        WalkingPattern::generate(&walk_pattern_params(&lola, 2, 0.4, 0.8).unwrap()).unwrap();
    for method in Method::ALL {
        let mut ctrl = WalkController::new(&lola, method, WalkParams::default(), &pattern).unwrap();
        let samples = pattern.samples();
        for s in &samples[..1500] {
            ctrl.cycle(s, 1e-3).unwrap();
        }
        let before = allocations();
        for s in &samples[1500..1600] {
            ctrl.cycle(s, 1e-3).unwrap();
        }
        let n = allocations() - before;
        assert_eq!(n, 0, "{method}: {n} allocations in 100 cycles");
    }
}
