use super::*;
use nalgebra::{Isometry3, Vector3};

/// `sub_outer` (`self -= w u u^T`) against dense matrices.
#[test]
fn sub_outer_matches_dense() {
    let sym = |k: usize| {
        let l = Matrix6::from_fn(|i, j| ((k + 3 * i + 5 * j) % 7) as f64 * 0.3 - 0.8);
        l * l.transpose()
    };
    let a = sym(1);
    let u = Force::new(Vector3::new(0.3, -1.1, 0.6), Vector3::new(2.0, 0.1, -0.7));
    let (uv, w) = (u.to_vector(), 0.37);
    let mut got = ArticulatedInertia::from_matrix(&a);
    got.sub_outer(&u, w);
    let expect = a - uv * uv.transpose() * w;
    assert!((got.to_matrix() - expect).amax() < 1e-14 * expect.amax());
}

/// Against the dense `C^T I C` for a general (not rigid-body) symmetric inertia.
#[test]
fn tr_transform_matches_dense_congruence() {
    let l = Matrix6::from_fn(|i, j| {
        if j <= i {
            0.6 + ((3 * i + 7 * j) % 5) as f64 * 0.3
        } else {
            0.0
        }
    });
    let dense = l * l.transpose();
    let art = ArticulatedInertia::from_matrix(&dense);
    for (t, w) in [(0.3, -0.1, 0.7), (-1.2, 0.4, 0.05)]
        .into_iter()
        .zip([0.9, -2.1])
    {
        let pose = Isometry3::new(Vector3::new(t.0, t.1, t.2), Vector3::new(w, 0.4 * w, 1.2));
        let x = SpatialTransform::from_pose(&pose);
        let c = x.to_matrix();
        let expect = c.transpose() * dense * c;
        let got = art.tr_transform(&x).to_matrix();
        assert!((got - expect).amax() < 1e-12 * expect.amax());
        assert_eq!(got, got.transpose());
    }
    // Rotations about each coordinate axis (with a translation): the plane fast path.
    for (k, axis) in [Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis()]
        .iter()
        .enumerate()
    {
        let rot = nalgebra::Rotation3::from_axis_angle(axis, 0.7 - k as f64);
        let x = SpatialTransform::new(*rot.matrix(), Vector3::new(0.2, -0.5, 0.3));
        let general = art.tr_transform(&x).to_matrix();
        let mut set = art; // Overwritten, not accumulated.
        art.tr_transform_axis_into::<false>(k, &x, (), &mut set);
        let set = set.to_matrix();
        assert!((set - general).amax() < 1e-13 * general.amax());
        assert_eq!(set, set.transpose());
        // Accumulated onto a nonzero inertia, fast and general paths.
        let (mut acc_fast, mut acc_general) = (art, art);
        art.add_tr_transform_axis_to(k, &x, &mut acc_fast);
        art.add_tr_transform_to(&x, &mut acc_general);
        let expect = dense + general;
        assert!((acc_fast.to_matrix() - expect).amax() < 1e-13 * expect.amax());
        assert!((acc_general.to_matrix() - expect).amax() < 1e-13 * expect.amax());
        // With the rank-one term folded in, against the congruence then `sub_outer`, for
        // the axis path and the general path, and with offsets zero, on one axis, general.
        let b = Force::new(Vector3::new(0.3, -1.1, 0.6), Vector3::new(2.0, 0.1, -0.7));
        for t in [Vector3::zeros(), Vector3::new(0.0, -0.4, 0.0), x.trans] {
            let x = SpatialTransform::new(*rot.matrix(), t);
            for axis in [Some(k), None] {
                let (mut fused, mut apart) = (art, art);
                art.add_tr_transform_sub_outer_to(axis, &x, (&b, 0.37), &mut fused);
                art.add_tr_transform_to(&x, &mut apart);
                apart.sub_outer(&b, 0.37);
                let (fused, apart) = (fused.to_matrix(), apart.to_matrix());
                assert!((fused - apart).amax() < 1e-13 * apart.amax());
                assert!((fused - art.to_matrix()).amax() > 0.1);
            }
        }
    }
}
