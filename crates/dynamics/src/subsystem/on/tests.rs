use super::*;
use nalgebra::{Matrix6, Vector3};

/// The one-pass `W W^T` downdate against the dense product, for one and two columns.
#[test]
fn sub_gram_matches_dense() {
    let l = Matrix6::from_fn(|i, j| ((2 * i + 5 * j) % 7) as f64 * 0.4 - 1.1);
    let start = ArticulatedInertia::from_matrix(&(l * l.transpose()));
    let w = [
        Force::new(Vector3::new(0.3, -1.1, 0.6), Vector3::new(2.0, 0.1, -0.7)),
        Force::new(Vector3::new(-0.5, 0.2, 1.4), Vector3::new(0.0, -0.9, 0.3)),
    ];
    for n in 1..=2 {
        let mut got = start;
        sub_gram(&mut got, &w, n);
        let mut expect = start.to_matrix();
        for u in &w[..n] {
            expect -= u.to_vector() * u.to_vector().transpose();
        }
        assert!((got.to_matrix() - expect).amax() < 1e-14 * expect.amax());
    }
}
