//! Memory is bounded by the query: `Data::new` plus O(n) forward dynamics on a long chain need
//! memory linear in its length (the dense `nv x nv` matrices of the O(n^3) methods are
//! allocated only by the calls that use them), measured with the byte-counting allocator.

use biped_dynamics::{
    forward_dynamics, mass_matrix, Algorithm, BodySpec, Data, JointModel, Model, ModelBuilder,
    RigidInertia,
};
use biped_test_support::alloc::{allocated_bytes, Counting};
use nalgebra::{DVector, Isometry3, Matrix3, Vector3};

#[global_allocator]
static GLOBAL: Counting = Counting;

/// A chain of `n` revolute links (axes alternating about z and y, 0.1 m apart).
fn chain(n: usize) -> Model {
    let mut b = ModelBuilder::new();
    let inertia = RigidInertia::new(
        1.0,
        Vector3::new(0.05, 0.0, 0.0),
        Matrix3::identity() * 1e-2,
    )
    .unwrap();
    for i in 0..n {
        let axis = if i % 2 == 0 {
            Vector3::z_axis()
        } else {
            Vector3::y_axis()
        };
        let placement = if i == 0 {
            Isometry3::identity()
        } else {
            Isometry3::translation(0.1, 0.0, 0.0)
        };
        let parent = i.checked_sub(1);
        let joint = JointModel::Revolute { axis };
        let spec = BodySpec::named(&format!("link{i}"), parent, joint, placement, inertia);
        b.add_body(spec).unwrap();
    }
    b.build().unwrap()
}

/// A smooth test state `(q, v, tau)` of the chain.
fn state(model: &Model) -> (DVector<f64>, DVector<f64>, DVector<f64>) {
    let n = model.nv();
    (
        DVector::from_fn(n, |i, _| 0.3 * (i as f64 * 0.7).sin()),
        DVector::from_fn(n, |i, _| 0.2 * (i as f64 * 0.3).cos()),
        DVector::from_fn(n, |i, _| 0.1 * (i as f64 * 1.1).sin()),
    )
}

/// Bytes requested by `Data::new` and one O(n) forward-dynamics call on `chain(n)`.
fn on_bytes(n: usize) -> usize {
    let model = chain(n);
    let (q, v, tau) = state(&model);
    let before = allocated_bytes();
    let mut data = Data::new(&model);
    let ddq = forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::On).unwrap();
    assert!(ddq.iter().all(|x| x.is_finite()));
    allocated_bytes() - before
}

#[test]
fn o_n_forward_dynamics_memory_grows_linearly() {
    let (small, large) = (on_bytes(2000), on_bytes(8000));
    // Linear: about 4 kB per body, constant in n. A dense 2000 x 2000 matrix alone is 32 MB,
    // and Data::new used to allocate two.
    assert!(small < 2000 * 6000, "{small} bytes for n = 2000");
    let dense = 8000 * 8000 * 8;
    assert!(large < dense / 10, "{large} bytes for n = 8000");
    // Four times the chain, four times the memory (a quadratic term would give 16).
    let ratio = large as f64 / small as f64;
    assert!((3.6..4.4).contains(&ratio), "{small} -> {large} bytes");
}

#[test]
fn dense_methods_size_their_workspace_on_first_use() {
    // nv = 300 is above the size whose dense matrices Data::new allocates up front.
    let model = chain(300);
    let (q, v, tau) = state(&model);
    let mut data = Data::new(&model);
    assert_eq!(data.mass.shape(), (0, 0));
    let on = forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::On)
        .unwrap()
        .clone();
    for algo in [Algorithm::Crba, Algorithm::Sparse] {
        let ddq = forward_dynamics(&model, &mut data, &q, &v, &tau, None, algo).unwrap();
        let err = (ddq - &on).amax() / on.amax();
        assert!(err < 1e-8, "{algo:?}: relative difference {err}");
    }
    // Sized once: the next calls allocate nothing.
    let before = allocated_bytes();
    forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::Crba).unwrap();
    let m = mass_matrix(&model, &mut data, &q).unwrap();
    assert_eq!(m.shape(), (300, 300));
    assert_eq!(allocated_bytes(), before);
}
