//! Products with a rotation `A_kp` of (2.36), general or about a coordinate axis `K` (a
//! revolute joint about a body axis whose placement is a pure translation): for the latter
//! only the plane normal to the axis mixes (4 instead of 9 multiplications per vector).

use super::{Force, Motion, SpatialTransform};
use nalgebra::{Matrix3, Vector3};

/// `C m = [A w; A (v + w x r)]` (motion transform, (2.36)) for a transform whose rotation is
/// about coordinate axis `axis` (`Some(k)`: plane products) or general (`None`).
#[inline(always)]
pub(crate) fn apply_motion(x: &SpatialTransform, axis: Option<usize>, m: &Motion) -> Motion {
    match axis {
        Some(0) => motion_by(&Plane::<0>(&x.rot), x, m),
        Some(1) => motion_by(&Plane::<1>(&x.rot), x, m),
        Some(_) => motion_by(&Plane::<2>(&x.rot), x, m),
        None => x.apply_motion(m),
    }
}

/// [`apply_motion`] with the products by `A` done by `r`.
#[inline(always)]
fn motion_by<R: RotationOps>(r: &R, x: &SpatialTransform, m: &Motion) -> Motion {
    Motion::new(r.mul(&m.ang), r.mul(&(m.lin + m.ang.cross(&x.trans))))
}

/// `C^T f = [A^T n + r x A^T f; A^T f]` (force transform, (2.36)) for a transform whose
/// rotation is about coordinate axis `axis` (`Some(k)`: plane products) or general (`None`).
#[inline(always)]
pub(crate) fn tr_apply_force(x: &SpatialTransform, axis: Option<usize>, f: &Force) -> Force {
    match axis {
        Some(0) => force_by(&Plane::<0>(&x.rot), x, f),
        Some(1) => force_by(&Plane::<1>(&x.rot), x, f),
        Some(_) => force_by(&Plane::<2>(&x.rot), x, f),
        None => x.tr_apply_force(f),
    }
}

/// [`tr_apply_force`] with the products by `A^T` done by `r`.
#[inline(always)]
fn force_by<R: RotationOps>(r: &R, x: &SpatialTransform, f: &Force) -> Force {
    let lin = r.tr_mul(&f.lin);
    Force::new(r.tr_mul(&f.ang) + x.trans.cross(&lin), lin)
}

/// The products of the recursions with the rotation `A` of a transform.
pub(crate) trait RotationOps {
    /// `A v`.
    fn mul(&self, v: &Vector3<f64>) -> Vector3<f64>;
    /// `A^T v`.
    fn tr_mul(&self, v: &Vector3<f64>) -> Vector3<f64>;
    /// `W A^T` (the child's world rotation from the parent's `W`).
    fn compose_tr(&self, w: &Matrix3<f64>) -> Matrix3<f64>;
}

/// A general rotation matrix.
pub(crate) struct General<'a>(pub &'a Matrix3<f64>);

/// A rotation about coordinate axis `K` (`A e_K = e_K`, `A^T e_K = e_K`).
pub(crate) struct Plane<'a, const K: usize>(pub &'a Matrix3<f64>);

impl RotationOps for General<'_> {
    #[inline(always)]
    fn mul(&self, v: &Vector3<f64>) -> Vector3<f64> {
        self.0 * v
    }
    #[inline(always)]
    fn tr_mul(&self, v: &Vector3<f64>) -> Vector3<f64> {
        self.0.tr_mul(v)
    }
    #[inline(always)]
    fn compose_tr(&self, w: &Matrix3<f64>) -> Matrix3<f64> {
        w * self.0.transpose()
    }
}

impl<const K: usize> RotationOps for Plane<'_, K> {
    #[inline(always)]
    fn mul(&self, v: &Vector3<f64>) -> Vector3<f64> {
        let (a, p, q) = (self.0, (K + 1) % 3, (K + 2) % 3);
        let mut out = *v;
        out[p] = a[(p, p)] * v[p] + a[(p, q)] * v[q];
        out[q] = a[(q, p)] * v[p] + a[(q, q)] * v[q];
        out
    }
    #[inline(always)]
    fn tr_mul(&self, v: &Vector3<f64>) -> Vector3<f64> {
        let (a, p, q) = (self.0, (K + 1) % 3, (K + 2) % 3);
        let mut out = *v;
        out[p] = a[(p, p)] * v[p] + a[(q, p)] * v[q];
        out[q] = a[(p, q)] * v[p] + a[(q, q)] * v[q];
        out
    }
    #[inline(always)]
    fn compose_tr(&self, w: &Matrix3<f64>) -> Matrix3<f64> {
        let (a, p, q) = (self.0, (K + 1) % 3, (K + 2) % 3);
        let (cp, cq) = (w.column(p).into_owned(), w.column(q).into_owned());
        let mut out = *w;
        out.set_column(p, &(cp * a[(p, p)] + cq * a[(p, q)]));
        out.set_column(q, &(cp * a[(q, p)] + cq * a[(q, q)]));
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Rotation3;

    /// The plane products against the dense ones for rotations about each coordinate axis.
    #[test]
    fn plane_products_match_dense() {
        let w = *Rotation3::from_euler_angles(0.3, -1.1, 2.0).matrix();
        let v = Vector3::new(0.7, -0.2, 1.3);
        let axes = [Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis()];
        let a: Vec<Matrix3<f64>> = axes
            .iter()
            .map(|ax| *Rotation3::from_axis_angle(ax, 0.9).matrix())
            .collect();
        let check = |r: &dyn RotationOps, a: &Matrix3<f64>| {
            assert!((r.mul(&v) - a * v).amax() < 1e-15);
            assert!((r.tr_mul(&v) - a.transpose() * v).amax() < 1e-15);
            assert!((r.compose_tr(&w) - w * a.transpose()).amax() < 1e-15);
        };
        check(&Plane::<0>(&a[0]), &a[0]);
        check(&Plane::<1>(&a[1]), &a[1]);
        check(&Plane::<2>(&a[2]), &a[2]);
        check(&General(&a[1]), &a[1]);
    }

    /// The plane motion and force transforms against the general ones, for each axis and
    /// `None`.
    #[test]
    fn plane_transforms_match_general() {
        let m = Motion::new(Vector3::new(0.7, -0.2, 1.3), Vector3::new(-0.4, 0.9, 0.25));
        let f = Force::new(Vector3::new(-0.6, 0.1, 0.8), Vector3::new(0.35, -1.2, 0.45));
        let r = Vector3::new(0.2, -0.5, 0.3);
        let axes = [Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis()];
        for (k, ax) in axes.iter().enumerate() {
            let x =
                SpatialTransform::new(*Rotation3::from_axis_angle(ax, 0.9 - k as f64).matrix(), r);
            let (fast, general) = (apply_motion(&x, Some(k), &m), x.apply_motion(&m));
            assert!((fast.ang - general.ang).amax() < 1e-15);
            assert!((fast.lin - general.lin).amax() < 1e-15);
            assert_eq!(apply_motion(&x, None, &m), general);
            let (fast, general) = (tr_apply_force(&x, Some(k), &f), x.tr_apply_force(&f));
            assert!((fast.ang - general.ang).amax() < 1e-15);
            assert!((fast.lin - general.lin).amax() < 1e-15);
            assert_eq!(tr_apply_force(&x, None, &f), general);
        }
    }
}
