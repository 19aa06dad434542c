//! Fitting a tight OBB to a set of SSVs: PCA and body-frame candidates, refined by local
//! rotations that minimise the exact volume (extents include the SSV radii).

use super::{support_interval, Obb};
use crate::primitives::Ssv;
use nalgebra::{Matrix3, Rotation3, SymmetricEigen, Unit, UnitQuaternion, Vector3};

/// Rotation steps (rad) of the refinement, coarse to fine.
const STEPS: [f64; 7] = [0.4, 0.15, 0.05, 0.02, 0.007, 0.002, 0.0007];
/// Maximum accepted moves per step size.
const MAX_MOVES: usize = 40;

/// Tight box around `ssvs`; an empty set gives a zero box at the origin.
pub(super) fn fit(ssvs: &[Ssv]) -> Obb {
    if ssvs.is_empty() {
        return Obb::from_frame_interval(Matrix3::identity(), Vector3::zeros(), Vector3::zeros());
    }
    let mut best = UnitQuaternion::identity();
    let mut best_cost = cost(ssvs, &best);
    if let Some(q) = pca_frame(ssvs) {
        let c = cost(ssvs, &q);
        if c < best_cost {
            best = q;
            best_cost = c;
        }
    }
    let q = refine(ssvs, best, best_cost);
    let axes = q.to_rotation_matrix().into_inner();
    let (min, max) = frame_interval(ssvs, &axes);
    Obb::from_frame_interval(axes, min, max)
}

/// Per-axis `[min, max]` of all swept volumes in the frame `axes`.
fn frame_interval(ssvs: &[Ssv], axes: &Matrix3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let mut min = Vector3::repeat(f64::INFINITY);
    let mut max = Vector3::repeat(f64::NEG_INFINITY);
    for k in 0..3 {
        let u = axes.column(k).into_owned();
        for ssv in ssvs {
            let (lo, hi) = support_interval(ssv, &u);
            min[k] = min[k].min(lo);
            max[k] = max[k].max(hi);
        }
    }
    (min, max)
}

/// Box volume in the frame `q`, regularised so that flat sets still rank by area.
fn cost(ssvs: &[Ssv], q: &UnitQuaternion<f64>) -> f64 {
    let axes = q.to_rotation_matrix().into_inner();
    let (min, max) = frame_interval(ssvs, &axes);
    let e = (max - min).add_scalar(1e-9);
    e.x * e.y * e.z
}

/// Principal axes of the vertex cloud as a right-handed frame; `None` if not finite.
fn pca_frame(ssvs: &[Ssv]) -> Option<UnitQuaternion<f64>> {
    let mut n = 0.0;
    let mut mean = Vector3::zeros();
    for v in ssvs.iter().flat_map(|s| s.vertices()) {
        mean += v.coords;
        n += 1.0;
    }
    mean /= n;
    let mut cov = Matrix3::zeros();
    for v in ssvs.iter().flat_map(|s| s.vertices()) {
        let d = v.coords - mean;
        cov += d * d.transpose();
    }
    let cov = cov / n;
    if !cov.iter().all(|x| x.is_finite()) {
        return None;
    }
    let mut axes = SymmetricEigen::try_new(cov, f64::EPSILON, 200)?.eigenvectors;
    if axes.determinant() < 0.0 {
        axes.set_column(2, &(-axes.column(2)));
    }
    if !axes.iter().all(|x| x.is_finite()) {
        return None;
    }
    let rot = Rotation3::from_matrix_unchecked(axes);
    Some(UnitQuaternion::from_rotation_matrix(&rot))
}

/// Coordinate descent over small rotations about the frame's own axes.
fn refine(ssvs: &[Ssv], mut q: UnitQuaternion<f64>, mut best: f64) -> UnitQuaternion<f64> {
    let axes = [Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis()];
    for step in STEPS {
        for _ in 0..MAX_MOVES {
            let mut moved = false;
            for axis in &axes {
                for angle in [step, -step] {
                    let trial = q * rotation(axis, angle);
                    let c = cost(ssvs, &trial);
                    if c < best {
                        best = c;
                        q = trial;
                        moved = true;
                    }
                }
            }
            if !moved {
                break;
            }
        }
    }
    q
}

fn rotation(axis: &Unit<Vector3<f64>>, angle: f64) -> UnitQuaternion<f64> {
    UnitQuaternion::from_axis_angle(axis, angle)
}
