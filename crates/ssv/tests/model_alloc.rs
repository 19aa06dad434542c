//! A collision-model update allocates nothing after construction (counting allocator).

mod model_support;

use biped_ssv::format;
use biped_test_support::alloc::{allocations, Counting};
use model_support::data_path;

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn update_does_not_allocate() {
    let mut loaded = format::load(data_path("humanoid.toml")).unwrap();
    let postures: Vec<_> = loaded.poses.values().cloned().collect();
    let before = allocations();
    for _ in 0..10 {
        for poses in &postures {
            loaded.model.update(poses).unwrap();
            std::hint::black_box(loaded.model.min_distance());
        }
    }
    assert_eq!(allocations() - before, 0);
    // The counter works: a Vec allocates.
    let v: Vec<u8> = Vec::with_capacity(8);
    std::hint::black_box(&v);
    assert!(allocations() > before);
}
