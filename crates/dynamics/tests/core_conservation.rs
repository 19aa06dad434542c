//! Energy and momentum conservation of torque-free, gravity-free random trees under RK4 at 1 ms
//! for 10 s (Runge-Kutta-Munthe-Kaas: configuration stages advanced with `integrate`).

mod core_support;

use biped_dynamics::{forward_dynamics, integrate, update_placements, Algorithm, Data, Model};
use core_support::*;
use nalgebra::{DVector, Vector3};

/// Kinetic energy `sum_i v_i^T M_i v_i / 2`, linear and angular momentum (world, about origin).
fn invariants(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
) -> (f64, Vector3<f64>, Vector3<f64>) {
    let zero = DVector::zeros(model.nv());
    biped_dynamics::forward_kinematics(model, data, q, v, &zero).unwrap();
    let (mut e, mut p, mut l) = (0.0, Vector3::zeros(), Vector3::zeros());
    for (i, body) in model.bodies().iter().enumerate() {
        let inertia = body.inertia();
        let vel = data.vel[i];
        e += inertia.kinetic_energy(&vel);
        let r = data.world_rot[i];
        let c = inertia.com();
        let vc = r * (vel.lin + vel.ang.cross(&c)) * inertia.mass();
        let pc = data.world_pos[i] + r * c;
        p += vc;
        l += r * (inertia.inertia_about_com() * vel.ang) + pc.cross(&vc);
    }
    (e, p, l)
}

/// Lie bracket of two body twists `[nu; omega]` (matrix commutator in se(3)).
fn bracket(a: &[f64], b: &[f64]) -> [f64; 6] {
    let (na, wa) = (
        Vector3::new(a[0], a[1], a[2]),
        Vector3::new(a[3], a[4], a[5]),
    );
    let (nb, wb) = (
        Vector3::new(b[0], b[1], b[2]),
        Vector3::new(b[3], b[4], b[5]),
    );
    let n = wa.cross(&nb) - wb.cross(&na);
    let w = wa.cross(&wb);
    [n.x, n.y, n.z, w.x, w.y, w.z]
}

/// `dexp^-1` for `q(t) = q0 (+) theta(t)`: `thetadot = xi + [theta, xi]/2 + [theta, [theta, xi]]/12`
/// on quaternion free joints (the RKMK correction), identity on vector-space joints.
fn dexpinv(model: &Model, theta: &DVector<f64>, xi: &DVector<f64>) -> DVector<f64> {
    let mut out = xi.clone();
    for j in model.joints() {
        if j.nq != 7 {
            continue;
        }
        let r = j.v_index..j.v_index + 6;
        let (t, x) = (&theta.as_slice()[r.clone()], &xi.as_slice()[r.clone()]);
        let c1 = bracket(t, x);
        let c2 = bracket(t, &c1);
        for k in 0..6 {
            out[j.v_index + k] += 0.5 * c1[k] + c2[k] / 12.0;
        }
    }
    out
}

/// One Runge-Kutta-Munthe-Kaas step of order 4: classical RK4 on `(theta, v)` with
/// `q = integrate(q0, theta)`, so vector-space joints see plain RK4.
fn rk4_step(
    model: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    h: f64,
    algo: Algorithm,
) -> (DVector<f64>, DVector<f64>) {
    let tau = DVector::zeros(model.nv());
    let mut stage = |theta: &DVector<f64>, vs: &DVector<f64>| {
        let qs = integrate(model, q, theta, 1.0).unwrap();
        let a = forward_dynamics(model, data, &qs, vs, &tau, None, algo)
            .unwrap()
            .clone();
        (dexpinv(model, theta, vs), a)
    };
    let zero = DVector::zeros(model.nv());
    let (t1, a1) = stage(&zero, v);
    let (t2, a2) = stage(&(&t1 * (h / 2.0)), &(v + &a1 * (h / 2.0)));
    let (t3, a3) = stage(&(&t2 * (h / 2.0)), &(v + &a2 * (h / 2.0)));
    let (t4, a4) = stage(&(&t3 * h), &(v + &a3 * h));
    let theta = (t1 + t2 * 2.0 + t3 * 2.0 + t4) * (h / 6.0);
    let vn = v + (a1 + a2 * 2.0 + a3 * 2.0 + a4) * (h / 6.0);
    (integrate(model, q, &theta, 1.0).unwrap(), vn)
}

/// Simulates 10 s and returns the maximum relative drift of energy, momentum and angular momentum.
fn drift(model: &Model, seed: u64, algo: Algorithm) -> (f64, f64, f64) {
    let mut r = rng(seed);
    let mut q = random_q(model, &mut r);
    let mut v = random_vec(model.nv(), 1.0, &mut r);
    let mut data = Data::new(model);
    let (e0, p0, l0) = invariants(model, &mut data, &q, &v);
    let (mut de, mut dp, mut dl) = (0.0f64, 0.0f64, 0.0f64);
    for step in 1..=10_000 {
        let (qn, vn) = rk4_step(model, &mut data, &q, &v, 1e-3, algo);
        q = qn;
        v = vn;
        if step % 100 == 0 {
            let (e, p, l) = invariants(model, &mut data, &q, &v);
            de = de.max((e - e0).abs() / e0);
            dp = dp.max((p - p0).norm() / p0.norm().max(1e-3));
            dl = dl.max((l - l0).norm() / l0.norm().max(1e-3));
        }
    }
    update_placements(model, &mut data, &q).unwrap();
    (de, dp, dl)
}

fn zero_gravity(root: u8) -> TreeOptions {
    TreeOptions {
        root,
        rotors: false,
        inner_free: false,
        gravity: Vector3::zeros(),
    }
}

/// Floating-base tree (quaternion free joint): energy, momentum and angular momentum conserved.
#[test]
fn floating_tree_conserves_energy_and_momentum() {
    for seed in [1u64, 2] {
        let model = random_model(seed, 8, zero_gravity(0));
        let (de, dp, dl) = drift(&model, seed, Algorithm::On);
        println!("floating seed {seed}: energy {de:e} momentum {dp:e} angular {dl:e}");
        assert!(de <= 1e-8, "energy drift {de:e}");
        assert!(dp <= 1e-10, "momentum drift {dp:e}");
        assert!(dl <= 1e-10, "angular momentum drift {dl:e}");
    }
}

/// Fixed-base tree with geared rotors (CRBA path): energy conserved.
#[test]
fn fixed_tree_with_rotors_conserves_energy() {
    let mut opts = zero_gravity(2);
    opts.rotors = true;
    let model = random_model(5, 10, opts);
    let (de, _, _) = drift(&model, 5, Algorithm::Sparse);
    println!("fixed seed 5: energy {de:e}");
    assert!(de <= 1e-8, "energy drift {de:e}");
}
