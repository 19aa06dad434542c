//! Pruning statistics of the humanoid model (ignored; prints counts for tuning).

use biped_ssv::format;
use biped_ssv::segment::{closest_ssv_pair_brute_force, closest_ssv_pair_with};
use std::cell::Cell;

#[test]
#[ignore = "prints pruning statistics"]
fn perf_counts() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/humanoid.toml");
    let loaded = format::load(path).unwrap();
    let mut model = loaded.model;
    for (name, poses) in &loaded.poses {
        model.update(poses).unwrap();
        let (mut tot, mut cur, mut sph, mut ov) = (0, 0, 0, 0);
        for p in model.pairs() {
            let (a, b) = (&model.segments()[p.a], &model.segments()[p.b]);
            if !a
                .world_obb()
                .overlaps(b.world_obb(), 0.5 * model.activation_distance())
            {
                continue;
            }
            ov += 1;
            tot += a.len() * b.len();
            let calls = Cell::new(0usize);
            closest_ssv_pair_with(a, b, f64::INFINITY, |x, y| {
                calls.set(calls.get() + 1);
                biped_ssv::distance(x, y)
            });
            cur += calls.get();
            let best = closest_ssv_pair_brute_force(a, b).result.distance;
            let mut n = 0;
            for sa in a.world_spheres() {
                for sb in b.world_spheres() {
                    if sa.distance_lower_bound(sb) < best {
                        n += 1;
                    }
                }
            }
            sph += n;
            println!(
                "  {} {} {}x{} cur {} sphere {}",
                a.name(),
                b.name(),
                a.len(),
                b.len(),
                calls.get(),
                n
            );
        }
        println!("{name}: overlapping {ov} all {tot} current {cur} sphere-oracle {sph}");
    }
}
