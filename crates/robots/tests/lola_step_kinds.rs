//! The kinematics step kinds precomputed in `Data::new` agree with the per-pass chain of
//! checks they replace (`Data::step_kinds_match_checks`) on both Lola types, whose Harmonic
//! Drive rotors, knee and ankle parts, feet frames and free base take every kind.

use biped_dynamics::Data;
use biped_robots::lola::{self, LolaType};

#[test]
fn lola_step_kinds_match_the_checks() {
    for t in [LolaType::Type2, LolaType::Type3] {
        let model = lola::build(t).expect("shipped file builds").model;
        assert!(Data::new(&model).step_kinds_match_checks(&model), "{t:?}");
    }
}
