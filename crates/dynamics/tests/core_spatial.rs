//! Spatial algebra against dense 6x6 matrices of (2.22) and (2.36).

mod core_support;

use biped_dynamics::spatial::{skew, ArticulatedInertia, Axis, JointAxis, SubspaceKind};
use biped_dynamics::{Force, Motion, SpatialTransform};
use core_support::*;
use nalgebra::{Matrix6, Vector3, Vector6};
use rand::Rng;

fn random_transform(r: &mut rand::rngs::StdRng) -> SpatialTransform {
    SpatialTransform::from_pose(&random_pose(r))
}

fn v6(r: &mut rand::rngs::StdRng) -> Vector6<f64> {
    Vector6::from_fn(|_, _| r.random_range(-1.0..1.0))
}

#[test]
fn transform_products_match_dense_matrix() {
    let mut r = rng(1);
    for _ in 0..50 {
        let x = random_transform(&mut r);
        let c = x.to_matrix();
        let m = v6(&mut r);
        let f = v6(&mut r);
        let cm = x.apply_motion(&Motion::from_vector(&m)).to_vector();
        assert!((cm - c * m).amax() < 1e-12);
        let ctf = x.tr_apply_force(&Force::from_vector(&f)).to_vector();
        assert!((ctf - c.transpose() * f).amax() < 1e-12);
        let cinv = c.try_inverse().unwrap();
        let im = x.inv_apply_motion(&Motion::from_vector(&m)).to_vector();
        assert!((im - cinv * m).amax() < 1e-12);
        let itf = x.inv_tr_apply_force(&Force::from_vector(&f)).to_vector();
        assert!((itf - cinv.transpose() * f).amax() < 1e-12);
        let y = random_transform(&mut r);
        assert!((x.compose(&y).to_matrix() - c * y.to_matrix()).amax() < 1e-12);
        // Power is frame invariant: (C m) . (C^-T f) = m . f.
        assert!((cm.dot(&itf) - m.dot(&f)).abs() < 1e-12);
    }
}

#[test]
fn inertia_products_match_dense_matrix() {
    let mut r = rng(2);
    for _ in 0..50 {
        let inertia = random_inertia(&mut r);
        let dense = inertia.to_matrix();
        // (2.22): [I_O, m r~; m r~^T, m E].
        let h = inertia.com() * inertia.mass();
        assert!((dense.fixed_view::<3, 3>(0, 3) - skew(&h)).amax() < 1e-14);
        assert!((dense - dense.transpose()).amax() < 1e-14);
        let m = v6(&mut r);
        assert!((inertia.apply(&Motion::from_vector(&m)).to_vector() - dense * m).amax() < 1e-12);
        let x = random_transform(&mut r);
        let c = x.to_matrix();
        let art = ArticulatedInertia::from_matrix(&dense);
        let t = art.tr_transform(&x).to_matrix();
        assert!((t - c.transpose() * dense * c).amax() < 1e-12);
        let u = Force::from_vector(&v6(&mut r));
        let mut s = art;
        s.sub_outer(&u, 0.7);
        let uu = u.to_vector();
        assert!((s.to_matrix() - (dense - uu * uu.transpose() * 0.7)).amax() < 1e-12);
        // Bias force of (2.56) against the dense formula with conventional accelerations.
        let w = Vector3::new(0.3, -1.2, 0.7);
        let hb = inertia.bias_force(&w).to_vector();
        let io = inertia.inertia_about_origin();
        let expect_ang = w.cross(&(io * w));
        let expect_lin = w.cross(&w.cross(&h));
        assert!(
            (hb - Vector6::new(
                expect_ang.x,
                expect_ang.y,
                expect_ang.z,
                expect_lin.x,
                expect_lin.y,
                expect_lin.z
            ))
            .amax()
                < 1e-12
        );
    }
}

#[test]
fn pruned_axes_match_general_axes() {
    let mut r = rng(3);
    let art = ArticulatedInertia::from_matrix(&{
        let a = Matrix6::from_fn(|_, _| r.random_range(-1.0..1.0));
        a * a.transpose()
    });
    let m = nalgebra::Matrix3::from_fn(|_, _| r.random_range(-1.0..1.0));
    for (pruned, general) in [
        (Axis::X, Vector3::x()),
        (Axis::Y, Vector3::y()),
        (Axis::Z, Vector3::z()),
    ] {
        let g = Axis::General(general);
        let (s, c) = 0.7f64.sin_cos();
        assert!((pruned.rotation(s, c) - g.rotation(s, c)).amax() < 1e-15);
        assert!((pruned.rot_tr_mul(s, c, &m) - g.rotation(s, c).transpose() * m).amax() < 1e-15);
        for kind in [SubspaceKind::Angular, SubspaceKind::Linear] {
            let jp = JointAxis {
                axis: pruned,
                kind,
                scale: 3.0,
            };
            let jg = JointAxis {
                axis: g,
                kind,
                scale: 3.0,
            };
            let s6 = jg.motion(1.0).to_vector();
            assert_eq!(jp.motion(1.0).to_vector(), s6);
            let u = jp.apply_inertia(&art).to_vector();
            assert!((u - art.to_matrix() * s6).amax() < 1e-14);
            assert!((jp.dot_force(&Force::from_vector(&u)) - s6.dot(&u)).abs() < 1e-13);
        }
    }
}
