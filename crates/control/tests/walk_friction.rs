//! Friction check of a planned walk ([`biped_control::walk::friction`]) against independent
//! references: the centre of pressure and free moment of point forces summed directly, the
//! mean distance over a sole by fine numerical integration, and the two pure limits of the
//! ellipsoid (sliding at `mu f_z`, spinning at `mu f_z rho`).

use biped_control::pattern::{Contact, FootGeometry, FootState};
use biped_control::walk::friction::Support;
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector2, Vector3};
use proptest::prelude::*;

fn foot(x: f64, y: f64, yaw: f64, contact: Contact) -> FootState {
    FootState {
        pose: Isometry3::from_parts(
            Translation3::new(x, y, 0.0),
            UnitQuaternion::from_euler_angles(0.0, 0.0, yaw),
        ),
        linear: Vector3::zeros(),
        angular: Vector3::zeros(),
        toe_angle: 0.0,
        toe_rate: 0.0,
        contact,
    }
}

fn flat_support() -> Support {
    let mut s = Support::new();
    let g = FootGeometry::default();
    s.update(
        &[
            foot(0.0, 0.0, 0.0, Contact::Flat),
            foot(0.0, 0.5, 0.0, Contact::Swing),
        ],
        &g,
    );
    s
}

/// Mean distance from `c` over the sole rectangle with its toe segment, by a 400 x 400 midpoint
/// rule.
fn mean_distance(g: &FootGeometry, c: Vector2<f64>) -> f64 {
    let n = 400;
    let mut sum = 0.0;
    for i in 0..n {
        for j in 0..n {
            let x = -g.back + (g.front + g.toe_length + g.back) * (i as f64 + 0.5) / n as f64;
            let y = -g.half_width + 2.0 * g.half_width * (j as f64 + 0.5) / n as f64;
            sum += (Vector2::new(x, y) - c).norm();
        }
    }
    sum / (n * n) as f64
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    /// Four ground point forces: the centre of pressure is their f_z-weighted mean and the
    /// free moment the sum of their moments about it, whatever the reference point's height.
    #[test]
    fn cop_and_free_moment_match_point_forces(
        pts in proptest::collection::vec(((-0.1f64..0.15, -0.06f64..0.06), (-50.0f64..50.0, -50.0f64..50.0, 10.0f64..300.0)), 4),
        reference in (-0.2f64..0.2, -0.2f64..0.2, 0.0f64..1.0),
    ) {
        let p = Vector3::new(reference.0, reference.1, reference.2);
        let (mut f, mut m) = (Vector3::zeros(), Vector3::zeros());
        let (mut weighted, mut fz) = (Vector2::zeros(), 0.0);
        for &((x, y), (fx, fy, fzi)) in &pts {
            let (r, fi) = (Vector3::new(x, y, 0.0), Vector3::new(fx, fy, fzi));
            f += fi;
            m += (r - p).cross(&fi);
            weighted += Vector2::new(x, y) * fzi;
            fz += fzi;
        }
        let cop = weighted / fz;
        let free: f64 = pts.iter().map(|&((x, y), (fx, fy, _))| {
            (x - cop.x) * fy - (y - cop.y) * fx
        }).sum();
        let load = flat_support().load(&f, &m, &p, 0.8);
        prop_assert!((load.cop - cop).norm() < 1e-9, "{:?} vs {:?}", load.cop, cop);
        prop_assert!((load.free_moment - free).abs() < 1e-9 * (1.0 + free.abs()));
        prop_assert!((load.normal - fz).abs() < 1e-9 && load.tangential >= 0.0);
    }
}

#[test]
fn support_radius_is_the_mean_distance_over_the_sole() {
    let g = FootGeometry::default();
    let s = flat_support();
    for c in [
        Vector2::new(0.02, 0.0),
        Vector2::new(0.1, 0.03),
        Vector2::new(-0.05, -0.02),
    ] {
        let f = Vector3::new(0.0, 0.0, 600.0);
        // Moment about the origin that puts the centre of pressure at c.
        let m = Vector3::new(c.y * 600.0, -c.x * 600.0, 0.0);
        let load = s.load(&f, &m, &Vector3::zeros(), 0.8);
        assert!((load.cop - c).norm() < 1e-12);
        let exact = mean_distance(&g, c);
        assert!(
            (load.radius - exact).abs() < 0.01 * exact,
            "{c:?}: {} vs {exact}",
            load.radius
        );
    }
}

#[test]
fn pure_sliding_and_pure_spinning_limits_are_one() {
    let (mu, n) = (0.8, 600.0);
    let s = flat_support();
    let slide = s.load(
        &Vector3::new(mu * n, 0.0, n),
        &Vector3::zeros(),
        &Vector3::zeros(),
        mu,
    );
    assert!((slide.usage - 1.0).abs() < 1e-12, "{}", slide.usage);
    let rho = s
        .load(
            &Vector3::new(0.0, 0.0, n),
            &Vector3::zeros(),
            &Vector3::zeros(),
            mu,
        )
        .radius;
    let spin = s.load(
        &Vector3::new(0.0, 0.0, n),
        &Vector3::new(0.0, 0.0, mu * n * rho),
        &Vector3::zeros(),
        mu,
    );
    assert!((spin.usage - 1.0).abs() < 1e-12, "{}", spin.usage);
    let pull = s.load(
        &Vector3::new(0.0, 0.0, -1.0),
        &Vector3::zeros(),
        &Vector3::zeros(),
        mu,
    );
    assert!(pull.usage.is_infinite());
}

#[test]
fn toe_off_supports_on_the_toe_segment_and_heel_strike_on_the_heel_edge() {
    let g = FootGeometry::default();
    let mut s = Support::new();
    s.update(
        &[
            foot(0.0, 0.0, 0.0, Contact::Toe),
            foot(1.0, 0.0, 0.0, Contact::Swing),
        ],
        &g,
    );
    assert!(!s.points().is_empty());
    for p in s.points() {
        assert!(
            p.x >= g.front - 1e-12 && p.x <= g.front + g.toe_length + 1e-12,
            "{p:?}"
        );
    }
    s.update(
        &[
            foot(0.0, 0.0, 0.0, Contact::Swing),
            foot(0.0, 0.0, 0.0, Contact::Heel),
        ],
        &g,
    );
    assert!(s.points().iter().all(|p| (p.x + g.back).abs() < 1e-12));
    s.update(
        &[
            foot(0.0, 0.0, 0.0, Contact::Swing),
            foot(0.0, 0.0, 0.0, Contact::Swing),
        ],
        &g,
    );
    assert!(s.points().is_empty());
}
