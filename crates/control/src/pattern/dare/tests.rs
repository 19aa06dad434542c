use super::*;
use nalgebra::{Matrix4, Vector4};

/// The cart-table servo's augmented `(A~, b~)` (as `PreviewController::new` builds them).
fn servo(dt: f64) -> (Matrix4<f64>, Vector4<f64>) {
    let w = -0.96 / 9.81;
    let (d2, d3) = (0.5 * dt * dt, dt * dt * dt / 6.0);
    let a = Matrix4::new(
        1.0,
        1.0,
        dt,
        d2 + w, //
        0.0,
        1.0,
        dt,
        d2, //
        0.0,
        0.0,
        1.0,
        dt, //
        0.0,
        0.0,
        0.0,
        1.0,
    );
    (a, Vector4::new(d3 + w * dt, d3, d2, dt))
}

/// The balanced path on its own (no unbalanced attempt first) returns the stabilising
/// solution of the original problem over periods and weights of walking controllers
/// (`Q_e / r` up to 1e9); its `P` agrees with the unbalanced solver's where both succeed.
#[test]
fn balanced_path_alone_solves_the_servo() {
    for dt in [0.001, 0.002, 0.005, 0.01] {
        let (a, b) = servo(dt);
        for (qe, qx) in [(1.0, 0.0), (100.0, 0.0), (1.0, 1e-3)] {
            for r in [1e-9, 1e-7, 1e-5].map(|r| r * qe) {
                let q = Matrix4::from_diagonal(&Vector4::new(qe, qx, qx, qx));
                let dare = Dare {
                    a: &a,
                    b: &b,
                    q: &q,
                    r,
                };
                let what = format!("dt {dt} qe {qe} qx {qx} r {r}");
                let s = solve_balanced(&dare).unwrap_or_else(|e| panic!("{what}: {e}"));
                assert!(s.residual < 1e-9, "{what}: residual {}", s.residual);
                assert!(
                    dare.closed_loop_decay(&s.p) < 1e-6,
                    "{what}: not stabilising"
                );
                if let Ok(u) = dare.solve() {
                    let d = (u.p - s.p).norm() / u.p.norm();
                    assert!(
                        d < 1e-8,
                        "{what}: balanced and unbalanced P differ by {d:e}"
                    );
                }
            }
        }
    }
}
