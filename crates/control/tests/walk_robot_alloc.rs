//! One walking IK cycle of the G1 (a described robot) allocates nothing, for every method.

use biped_control::pattern::WalkingPattern;
use biped_control::walk::{Method, WalkController, WalkParams, WalkRobot};
use biped_robots::description::Robot;
use biped_test_support::alloc::{allocations, Counting};

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn g1_cycle_does_not_allocate() {
    let g1 = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
    let robot = WalkRobot::from_description(&g1).unwrap();
    let params = robot.pattern_params(2, robot.natural_step_length, 0.8);
    let pattern = WalkingPattern::generate(&params).unwrap();
    for method in Method::ALL {
        let mut ctrl =
            WalkController::for_robot(&robot, method, WalkParams::default(), &pattern).unwrap();
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
