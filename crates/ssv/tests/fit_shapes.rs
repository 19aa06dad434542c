//! SSV fits of the analytic shapes: exact for spheres and capsules, containing for cylinders
//! and boxes (checked with the distance of a radius-0 point SSV to the fit), volumes by hand,
//! a property test over random boxes and rotations, and the sampled choice of pairs.

use biped_ssv::fit::pairs::{candidates, count, PairCount};
use biped_ssv::fit::{fit, FitKind, Geometry};
use biped_ssv::{distance, CollisionModel, ModelError, Pss, Segment, Ssv};
use nalgebra::{Isometry3, Point3, Vector3};
use proptest::prelude::*;
use std::f64::consts::PI;

/// Largest signed distance of `points` to the union of `ssvs`, computed here independently
/// of the fit's own check.
fn worst(ssvs: &[Ssv], points: &[Point3<f64>]) -> f64 {
    points
        .iter()
        .map(|p| {
            let probe = Ssv::from(Pss::new(*p, 0.0).unwrap());
            ssvs.iter()
                .map(|s| distance(&probe, s).distance)
                .fold(f64::INFINITY, f64::min)
        })
        .fold(f64::NEG_INFINITY, f64::max)
}

/// Corners, edge midpoints and face centres of a box of `size` at `pose`.
fn box_points(pose: &Isometry3<f64>, size: [f64; 3]) -> Vec<Point3<f64>> {
    let mut out = Vec::new();
    for i in 0..27 {
        let s = |k: u32| (i / 3usize.pow(k) % 3) as f64 - 1.0;
        out.push(
            pose * Point3::new(
                s(0) * size[0] / 2.0,
                s(1) * size[1] / 2.0,
                s(2) * size[2] / 2.0,
            ),
        );
    }
    out
}

fn pose(t: [f64; 3], rpy: [f64; 3]) -> Isometry3<f64> {
    Isometry3::new(Vector3::from(t), Vector3::zeros())
        * nalgebra::UnitQuaternion::from_euler_angles(rpy[0], rpy[1], rpy[2])
}

#[test]
fn spheres_and_capsules_are_exact() {
    let at = pose([0.1, 0.2, 0.3], [0.0, PI / 2.0, 0.0]);
    let s = fit(&Geometry::Sphere { radius: 0.05 }, &at).unwrap();
    assert_eq!(s.kind, FitKind::Point);
    assert_eq!(s.ssvs[0].vertices()[0], Point3::new(0.1, 0.2, 0.3));
    assert_eq!((s.ssvs[0].radius(), s.overhead()), (0.05, Some(1.0)));
    let c = fit(
        &Geometry::Capsule {
            radius: 0.03,
            length: 0.2,
        },
        &at,
    )
    .unwrap();
    assert_eq!(c.kind, FitKind::Line);
    // pitch by 90 degrees turns z into x: the axis runs along x
    let v = c.ssvs[0].vertices();
    assert!((v[0] - Point3::new(0.0, 0.2, 0.3)).norm() < 1e-15, "{v:?}");
    assert!((v[1] - Point3::new(0.2, 0.2, 0.3)).norm() < 1e-15, "{v:?}");
    assert!((c.overhead().unwrap() - 1.0).abs() < 1e-12);
}

#[test]
fn cylinders_are_contained_by_their_axis_capsule() {
    let at = pose([0.0, 0.0, 1.0], [0.3, -0.2, 0.7]);
    let f = fit(
        &Geometry::Cylinder {
            radius: 0.04,
            length: 0.3,
        },
        &at,
    )
    .unwrap();
    assert_eq!(f.kind, FitKind::Line);
    let mut points = Vec::new();
    for k in 0..400 {
        let (phi, rho, z) = (
            k as f64 * 0.7,
            0.04 * ((k % 5) as f64 / 4.0),
            0.15 * ((k % 7) as f64 / 3.0 - 1.0),
        );
        points.push(at * Point3::new(rho * phi.cos(), rho * phi.sin(), z));
    }
    assert!(worst(&f.ssvs, &points) <= 1e-9);
    // capsule pi r^2 l + 4/3 pi r^3 over cylinder pi r^2 l = 1 + 4 r / (3 l)
    let expected = 1.0 + 4.0 * 0.04 / (3.0 * 0.3);
    assert!((f.overhead().unwrap() - expected).abs() < 1e-12);
}

#[test]
fn boxes_by_hand() {
    let id = Isometry3::identity();
    // flat plate 1 x 0.5 x 0.1: rectangle swept by 0.05
    let plate = fit(
        &Geometry::Cuboid {
            size: [0.5, 1.0, 0.1],
        },
        &id,
    )
    .unwrap();
    assert_eq!((plate.kind, plate.ssvs.len()), (FitKind::Rectangle, 2));
    let r: f64 = 0.05;
    let v = 2.0 * r * 0.5 + PI * r * r * 1.5 + 4.0 / 3.0 * PI * r.powi(3);
    assert!((plate.volume - v).abs() < 1e-12, "{} {v}", plate.volume);
    // long bar 1 x 0.1 x 0.1: capsule of radius sqrt(0.05^2 + 0.05^2)
    let bar = fit(
        &Geometry::Cuboid {
            size: [0.1, 0.1, 1.0],
        },
        &id,
    )
    .unwrap();
    assert_eq!(bar.kind, FitKind::Line);
    assert!((bar.ssvs[0].radius() - 0.05 * 2f64.sqrt()).abs() < 1e-12);
    // cube: the circumscribed sphere is smallest
    let cube = fit(&Geometry::Cuboid { size: [1.0; 3] }, &id).unwrap();
    assert_eq!(cube.kind, FitKind::Point);
    assert!((cube.volume - 4.0 / 3.0 * PI * 0.75f64.powf(1.5)).abs() < 1e-12);
    for f in [&plate, &bar, &cube] {
        assert!(f.overhead().unwrap() > 1.0);
    }
    assert!(fit(
        &Geometry::Cuboid {
            size: [1.0, 0.0, 1.0]
        },
        &id
    )
    .is_err());
    assert!(fit(&Geometry::Sphere { radius: f64::NAN }, &id).is_err());
    assert!(fit(
        &Geometry::Points {
            points: &[],
            volume: None
        },
        &id
    )
    .is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]
    /// Random boxes at random poses: every corner, edge midpoint and face centre is inside the
    /// fit, and the fit is at least as large as the box.
    #[test]
    fn random_boxes_are_contained(
        size in proptest::array::uniform3(1e-3f64..2.0),
        t in proptest::array::uniform3(-1.0f64..1.0),
        rpy in proptest::array::uniform3(-PI..PI),
    ) {
        let at = pose(t, rpy);
        let f = fit(&Geometry::Cuboid { size }, &at).unwrap();
        prop_assert!(worst(&f.ssvs, &box_points(&at, size)) <= 1e-9);
        prop_assert!(f.overhead().unwrap() >= 1.0 - 1e-9);
        // the same box as a point cloud (its corners) is contained too
        let corners = box_points(&Isometry3::identity(), size);
        let g = fit(&Geometry::Points { points: &corners, volume: Some(size.iter().product()) }, &at).unwrap();
        prop_assert!(worst(&g.ssvs, &box_points(&at, size)) <= 1e-9);
        prop_assert!(g.overhead().unwrap() >= 1.0 - 1e-9);
    }
}

/// Three spheres on bodies 0, 1, 2 (body 1 the child of 0): 0-1 adjacent; 0-2 always in
/// contact; 1-2 close in one sample of four only; body 3's sphere never comes close.
#[test]
fn pairs_by_sampling() {
    let bodies: Vec<String> = (0..4).map(|k| format!("b{k}")).collect();
    let mut model = CollisionModel::new(bodies, 0.05).unwrap();
    for k in 0..4 {
        let ball = Ssv::from(Pss::new(Point3::origin(), 0.1).unwrap());
        model
            .add_segment(Segment::new(format!("s{k}"), vec![ball]).unwrap(), k)
            .unwrap();
    }
    let pairs = candidates(&[0, 1, 2, 3], |a, b| a == 1 && b == 0);
    assert_eq!(pairs, [(0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]);
    for &(a, b) in &pairs {
        model.add_pair(a, b).unwrap();
    }
    let counts = count::<ModelError>(&mut model, 4, |k, poses| {
        poses[0] = Isometry3::translation(0.0, 0.0, 0.0);
        poses[1] = Isometry3::translation(if k == 2 { 0.42 } else { 0.5 }, 0.0, 0.0);
        poses[2] = Isometry3::translation(0.19, 0.0, 0.0);
        poses[3] = Isometry3::translation(5.0, 0.0, 0.0);
        Ok(())
    })
    .unwrap();
    let c = |a, b, close, contact| PairCount {
        a,
        b,
        close,
        contact,
    };
    // 1-2 at 0.23 apart in sample 2: distance 0.03 < d_a; else 0.31 - 0.2 = 0.11
    assert_eq!(
        counts,
        [
            c(0, 2, 4, 4),
            c(0, 3, 0, 0),
            c(1, 2, 1, 0),
            c(1, 3, 0, 0),
            c(2, 3, 0, 0)
        ]
    );
    let kept: Vec<bool> = counts.iter().map(|p| p.kept(4)).collect();
    assert_eq!(kept, [false, false, true, false, false]);
}

/// Points on the surface of a capsule (axis x from -0.5 to 0.5, radius 0.1): the fit to the
/// cloud is that capsule, its segment shortened from the extent 1.2 to the axis length 1.0.
#[test]
fn a_sampled_capsule_is_recovered() {
    let mut points = Vec::new();
    for i in 0..=20 {
        for k in 0..16 {
            let phi = 2.0 * PI * k as f64 / 16.0;
            let (s, c) = phi.sin_cos();
            points.push(Point3::new(-0.5 + i as f64 / 20.0, 0.1 * c, 0.1 * s));
            // the caps: latitude theta from the rim (0) to the tip (pi/2)
            let theta = PI / 2.0 * i as f64 / 20.0;
            let (st, ct) = theta.sin_cos();
            for side in [-1.0, 1.0] {
                points.push(Point3::new(
                    side * (0.5 + 0.1 * st),
                    0.1 * ct * c,
                    0.1 * ct * s,
                ));
            }
        }
    }
    let at = pose([0.3, 0.1, -0.2], [0.5, 0.2, -1.0]);
    let f = fit(
        &Geometry::Points {
            points: &points,
            volume: None,
        },
        &at,
    )
    .unwrap();
    assert_eq!(f.kind, FitKind::Line);
    let v = f.ssvs[0].vertices();
    assert!(
        ((v[1] - v[0]).norm() - 1.0).abs() < 1e-9,
        "length {}",
        (v[1] - v[0]).norm()
    );
    assert!((f.ssvs[0].radius() - 0.1).abs() < 1e-9);
    let mid = at * Point3::origin();
    assert!((nalgebra::center(&v[0], &v[1]) - mid).norm() < 1e-9);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]
    /// Random clouds of 1 to 40 points in an anisotropic box at a random pose: every point is
    /// inside the fit, whose volume is at most that of the bounding sphere about the centroid.
    #[test]
    fn random_clouds_are_contained(
        raw in proptest::collection::vec(proptest::array::uniform3(-1.0f64..1.0), 1..40),
        scale in proptest::array::uniform3(1e-3f64..1.0),
        rpy in proptest::array::uniform3(-PI..PI),
    ) {
        let points: Vec<Point3<f64>> = raw
            .iter()
            .map(|p| Point3::new(p[0] * scale[0], p[1] * scale[1], p[2] * scale[2]))
            .collect();
        let at = pose([0.2, -0.1, 0.4], rpy);
        let f = fit(&Geometry::Points { points: &points, volume: None }, &at).unwrap();
        let placed: Vec<_> = points.iter().map(|p| at * p).collect();
        prop_assert!(worst(&f.ssvs, &placed) <= 1e-9);
        let c = placed.iter().map(|p| p.coords).sum::<Vector3<f64>>() / placed.len() as f64;
        let r = placed.iter().map(|p| (p.coords - c).norm()).fold(0.0, f64::max);
        prop_assert!(f.volume <= 4.0 / 3.0 * PI * r.powi(3) * (1.0 + 1e-9) + 1e-15);
    }
}
