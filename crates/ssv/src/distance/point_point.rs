//! PP: point-swept sphere to point-swept sphere, eq. (6.12).

use super::assemble::{assemble, Closest, Geom};
use crate::primitives::Pss;
use crate::result::{DistanceResult, PrimitiveParam};

/// PP: point to point, eq. (6.12): c* = p1 - p0.
#[inline]
pub fn pp(a: &Pss, b: &Pss) -> DistanceResult {
    let c = Closest {
        a: *a.center(),
        b: *b.center(),
        param_a: PrimitiveParam::Point,
        param_b: PrimitiveParam::Point,
    };
    assemble(c, a.radius(), b.radius(), Geom::Point, Geom::Point)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Point3, Vector3};

    #[test]
    fn separated_spheres_3_4_5() {
        let a = Pss::new(Point3::new(1.0, 2.0, 3.0), 0.5).unwrap();
        let b = Pss::new(Point3::new(4.0, 6.0, 3.0), 1.0).unwrap();
        let r = pp(&a, &b);
        assert!((r.distance - 3.5).abs() < 1e-15);
        let n = Vector3::new(0.6, 0.8, 0.0);
        assert!((r.normal - n).norm() < 1e-15);
        assert!((r.point_a - (Point3::new(1.0, 2.0, 3.0) + n * 0.5)).norm() < 1e-15);
        assert!((r.point_b - (Point3::new(4.0, 6.0, 3.0) - n)).norm() < 1e-15);
        assert!((r.connecting().norm() - r.distance).abs() < 1e-14);
    }

    #[test]
    fn coincident_centres_use_plus_z() {
        let a = Pss::new(Point3::new(1.0, 1.0, 1.0), 0.25).unwrap();
        let r = pp(&a, &a);
        assert_eq!(r.normal, Vector3::z());
        assert_eq!(r.distance, -0.5);
        assert_eq!(r.point_a, Point3::new(1.0, 1.0, 1.25));
        assert_eq!(r.point_b, Point3::new(1.0, 1.0, 0.75));
    }

    #[test]
    fn overlap_is_negative_and_swap_symmetric() {
        let a = Pss::new(Point3::new(0.0, 0.0, 0.0), 1.0).unwrap();
        let b = Pss::new(Point3::new(0.0, 1.0, 0.0), 1.0).unwrap();
        let r = pp(&a, &b);
        assert!((r.distance + 1.0).abs() < 1e-15);
        let s = pp(&b, &a);
        assert_eq!(s, r.swapped());
    }

    #[test]
    fn tiny_offsets_keep_a_unit_normal() {
        let a = Pss::new(Point3::new(0.0, 0.0, 0.0), 0.0).unwrap();
        let b = Pss::new(Point3::new(1e-170, -1e-170, 0.0), 0.0).unwrap();
        let r = pp(&a, &b);
        assert!((r.normal.norm() - 1.0).abs() < 1e-15);
        assert!((r.distance - 2f64.sqrt() * 1e-170).abs() < 1e-184);
    }
}
