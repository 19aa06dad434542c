//! Criterion benchmark of the six SSV distance functions (Table 6.9) against the equivalent
//! parry3d-f64 queries, on a fixed pool of 1024 random queries cycled per iteration:
//! coordinates in a 1 m box, radii 0.01-0.1 m.

use biped_ssv::distance::{ll, lt, pl, pp, pt, tt};
use biped_ssv::{Lss, Pss, Tss};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::Point3;
use parry3d_f64::math::{Pose, Vector};
use parry3d_f64::query;
use parry3d_f64::shape::{Ball, Capsule, Shape, Triangle};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use std::hint::black_box;

const POOL: usize = 1024;

/// One random SSV of the pool with its parry twin (shape, pose, radius to subtract).
struct Sample<T> {
    ssv: T,
    shape: Box<dyn Shape>,
    pose: Pose,
    extra_radius: f64,
}

fn point(rng: &mut StdRng) -> Point3<f64> {
    Point3::new(rng.random(), rng.random(), rng.random())
}

fn radius(rng: &mut StdRng) -> f64 {
    rng.random_range(0.01..0.1)
}

fn vec(p: &Point3<f64>) -> Vector {
    Vector::new(p.x, p.y, p.z)
}

fn sphere(rng: &mut StdRng) -> Sample<Pss> {
    let (c, r) = (point(rng), radius(rng));
    Sample {
        ssv: Pss::new(c, r).unwrap(),
        shape: Box::new(Ball::new(r)),
        pose: Pose::translation(c.x, c.y, c.z),
        extra_radius: 0.0,
    }
}

fn capsule(rng: &mut StdRng) -> Sample<Lss> {
    let (a, b, r) = (point(rng), point(rng), radius(rng));
    Sample {
        ssv: Lss::new(a, b, r).unwrap(),
        shape: Box::new(Capsule::new(vec(&a), vec(&b), r)),
        pose: Pose::identity(),
        extra_radius: 0.0,
    }
}

fn triangle(rng: &mut StdRng) -> Sample<Tss> {
    let (a, b, c, r) = (point(rng), point(rng), point(rng), radius(rng));
    Sample {
        ssv: Tss::new(a, b, c, r).unwrap(),
        shape: Box::new(Triangle::new(vec(&a), vec(&b), vec(&c))),
        pose: Pose::identity(),
        extra_radius: r,
    }
}

fn pool<A, B>(
    seed: u64,
    fa: fn(&mut StdRng) -> Sample<A>,
    fb: fn(&mut StdRng) -> Sample<B>,
) -> Vec<(Sample<A>, Sample<B>)> {
    let mut rng = StdRng::seed_from_u64(seed);
    (0..POOL).map(|_| (fa(&mut rng), fb(&mut rng))).collect()
}

/// Times `ours` and the parry equivalent side by side on the same queries; each side reads
/// its own compact array, so neither pays for the other's data in the cache.
fn pair<A: Copy, B: Copy>(
    c: &mut Criterion,
    name: &str,
    pool: &[(Sample<A>, Sample<B>)],
    ours: fn(&A, &B) -> biped_ssv::DistanceResult,
) {
    let inputs: Vec<(A, B)> = pool.iter().map(|(x, y)| (x.ssv, y.ssv)).collect();
    let shapes: Vec<(&dyn Shape, Pose, &dyn Shape, Pose, f64)> = pool
        .iter()
        .map(|(x, y)| {
            let r = x.extra_radius + y.extra_radius;
            (&*x.shape, x.pose, &*y.shape, y.pose, r)
        })
        .collect();
    let mut g = c.benchmark_group(name);
    let mut i = 0usize;
    g.bench_function("biped_ssv", |b| {
        b.iter(|| {
            i = (i + 1) & (POOL - 1);
            let (x, y) = &inputs[i];
            black_box(ours(black_box(x), black_box(y)))
        })
    });
    let mut i = 0usize;
    g.bench_function("parry3d_f64", |b| {
        b.iter(|| {
            i = (i + 1) & (POOL - 1);
            let (s1, p1, s2, p2, r) = &shapes[i];
            let d = query::distance(p1, *s1, p2, *s2).unwrap();
            black_box(d.distance - r)
        })
    });
    g.finish();
}

fn benches(c: &mut Criterion) {
    pair(c, "PP", &pool(1, sphere, sphere), pp);
    pair(c, "PL", &pool(2, sphere, capsule), pl);
    pair(c, "PT", &pool(3, sphere, triangle), pt);
    pair(c, "LL", &pool(4, capsule, capsule), ll);
    pair(c, "LT", &pool(5, capsule, triangle), lt);
    pair(c, "TT", &pool(6, triangle, triangle), tt);
}

criterion_group!(distance_benches, benches);
criterion_main!(distance_benches);
