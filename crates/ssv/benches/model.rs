//! Whole-model update of the example humanoid (`data/humanoid.toml`): transform every SSV,
//! OBB and bounding sphere to the body poses and evaluate all segment pairs (thesis 6.5, 6.7),
//! in the standing posture and with the arms close to the thighs. Also the parts (transform
//! only) and an unpruned baseline (OBB test, then every SSV pair) for comparison. Both pair
//! policies are measured: `closest` (exact closest pair whenever the enlarged OBBs overlap)
//! and `within_da` (exact closest pair only when it is closer than d_a). The update
//! warm-starts each pair with the previous closest SSV pair; `alternating` switches posture
//! on every update, so that warm start is (mostly) stale, a worst case for the pruning.

use biped_ssv::format;
use biped_ssv::segment::closest_ssv_pair_brute_force;
use biped_ssv::{CollisionModel, PairDistance, PairQuery};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::Isometry3;
use std::hint::black_box;

/// Named postures: one pose per body.
type Postures = Vec<(String, Vec<Isometry3<f64>>)>;

fn humanoid() -> (CollisionModel, Postures) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/humanoid.toml");
    let loaded = format::load(path).unwrap_or_else(|e| panic!("{e}"));
    (loaded.model, loaded.poses.into_iter().collect())
}

/// Baseline without sphere pruning: enlarged-OBB test, then every SSV pair.
fn unpruned(model: &CollisionModel) -> f64 {
    let half = 0.5 * model.activation_distance();
    let mut min = f64::INFINITY;
    for p in model.pairs() {
        let (a, b) = (&model.segments()[p.a], &model.segments()[p.b]);
        if a.world_obb().overlaps(b.world_obb(), half) {
            min = min.min(closest_ssv_pair_brute_force(a, b).result.distance);
        }
    }
    min
}

fn bench_model(c: &mut Criterion) {
    let (mut model, postures) = humanoid();
    for (name, poses) in &postures {
        model.set_pair_query(PairQuery::Closest);
        model.update(poses).unwrap();
        let computed = model
            .results()
            .iter()
            .filter(|r| r.computed().is_some())
            .count();
        let min = model.min_distance().map(|(_, p)| p.result.distance);
        eprintln!(
            "{name}: {} segments, {} SSVs, {} pairs, {computed} pairs computed, min {min:?}",
            model.segments().len(),
            model.ssv_count(),
            model.pairs().len()
        );
        for (label, query) in [
            ("closest", PairQuery::Closest),
            ("within_da", PairQuery::WithinActivation),
        ] {
            model.set_pair_query(query);
            c.bench_function(&format!("model_update/{name}/{label}"), |b| {
                b.iter(|| {
                    model.update(black_box(poses)).unwrap();
                    black_box(
                        model
                            .results()
                            .first()
                            .copied()
                            .unwrap_or(PairDistance::Beyond),
                    )
                })
            });
        }
        c.bench_function(&format!("model_transform_only/{name}"), |b| {
            b.iter(|| model.set_poses(black_box(poses)).unwrap())
        });
        model.set_poses(poses).unwrap();
        c.bench_function(&format!("model_unpruned_pairs/{name}"), |b| {
            b.iter(|| black_box(unpruned(black_box(&model))))
        });
    }
}

/// Updates alternating between two postures (stale warm starts on every update).
fn bench_alternating(c: &mut Criterion) {
    let (mut model, postures) = humanoid();
    for (label, query) in [
        ("closest", PairQuery::Closest),
        ("within_da", PairQuery::WithinActivation),
    ] {
        model.set_pair_query(query);
        let mut k = 0usize;
        c.bench_function(&format!("model_update/alternating/{label}"), |b| {
            b.iter(|| {
                k += 1;
                let poses = &postures[k % postures.len()].1;
                model.update(black_box(poses)).unwrap();
                black_box(model.results().first().copied())
            })
        });
    }
}

criterion_group!(benches, bench_model, bench_alternating);
criterion_main!(benches);
