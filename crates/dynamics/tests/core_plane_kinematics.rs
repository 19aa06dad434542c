//! Forward kinematics of revolute joints about body coordinate axes with translation-only
//! placements (the plane-rotation products of the first recursion) against an independent
//! evaluation: world poses by composing isometries, body velocities and conventional
//! accelerations by central differences of those poses along `q(t) = q + v t + a t^2 / 2`.

mod core_support;

use biped_dynamics::{forward_kinematics, BodySpec, Data, JointModel, Model, ModelBuilder};
use core_support::{random_inertia, random_pose, random_vec, rng, vee};
use nalgebra::{DVector, Isometry3, Translation3, Unit, UnitQuaternion, Vector3};
use rand::Rng;

/// Random revolute tree: coordinate axes and pure-translation placements for most joints.
fn plane_tree(seed: u64, n: usize) -> (Model, Vec<Unit<Vector3<f64>>>) {
    let mut rng = rng(seed);
    let mut b = ModelBuilder::new();
    let mut axes = Vec::new();
    for i in 0..n {
        let axis =
            [Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis()][rng.random_range(0..3)];
        let placement = if rng.random_range(0..4) == 0 {
            random_pose(&mut rng)
        } else {
            let t = Vector3::new(rng.random(), rng.random(), rng.random()) * 0.4;
            Isometry3::from_parts(Translation3::from(t), UnitQuaternion::identity())
        };
        b.add_body(BodySpec {
            name: format!("b{i}"),
            joint_name: format!("j{i}"),
            parent: (i > 0).then(|| rng.random_range(0..i)),
            joint: JointModel::Revolute { axis },
            placement,
            inertia: random_inertia(&mut rng),
        })
        .unwrap();
        axes.push(axis);
    }
    (b.build().unwrap(), axes)
}

/// World poses by composing `placement * Rot(axis, q)` down the tree.
fn poses(model: &Model, axes: &[Unit<Vector3<f64>>], q: &DVector<f64>) -> Vec<Isometry3<f64>> {
    let mut out: Vec<Isometry3<f64>> = Vec::new();
    for (i, body) in model.bodies().iter().enumerate() {
        let joint = UnitQuaternion::from_axis_angle(&axes[i], q[body.q_index()]);
        let local = body.placement() * Isometry3::from_parts(Translation3::identity(), joint);
        out.push(body.parent().map_or(local, |p| out[p] * local));
    }
    out
}

#[test]
fn plane_rotations_match_composed_poses_and_differences() {
    for seed in 0..12 {
        let (model, axes) = plane_tree(seed, 3 + seed as usize % 8);
        let mut rng = rng(seed + 50);
        let n = model.nv();
        let (q, v, a) = (
            random_vec(n, 3.0, &mut rng),
            random_vec(n, 2.0, &mut rng),
            random_vec(n, 2.0, &mut rng),
        );
        let mut data = Data::new(&model);
        forward_kinematics(&model, &mut data, &q, &v, &a).unwrap();
        let at = |t: f64| poses(&model, &axes, &(&q + &v * t + &a * (0.5 * t * t)));
        let rot = |p: &Isometry3<f64>| *p.rotation.to_rotation_matrix().matrix();
        // Body angular velocity of body `i` at time `s` by a central difference (step `e`).
        let omega_at = |i: usize, s: f64, e: f64| {
            let (rp, rm, r) = (at(s + e), at(s - e), at(s));
            vee(&(rot(&r[i]).transpose() * (rot(&rp[i]) - rot(&rm[i])) / (2.0 * e)))
        };
        let h = 1e-4;
        let (p0, pp, pm) = (at(0.0), at(h), at(-h));
        for i in 0..model.nbodies() {
            let r0 = rot(&p0[i]);
            assert!(
                (data.world_rot[i] - r0).amax() < 1e-12,
                "seed {seed} body {i}"
            );
            assert!((data.world_pos[i] - p0[i].translation.vector).amax() < 1e-12);
            let pos = |p: &[Isometry3<f64>]| p[i].translation.vector;
            let pdot = (pos(&pp) - pos(&pm)) / (2.0 * h);
            let pddot = (pos(&pp) - pos(&p0) * 2.0 + pos(&pm)) / (h * h);
            let w = omega_at(i, 0.0, 1e-5);
            let wdot = (omega_at(i, h, 1e-5) - omega_at(i, -h, 1e-5)) / (2.0 * h);
            let tol = |x: f64| x * (1.0 + data.vel[i].to_vector().amax().powi(2));
            assert!(
                (data.vel[i].ang - w).amax() < tol(1e-6),
                "seed {seed} body {i} omega"
            );
            assert!((data.vel[i].lin - r0.transpose() * pdot).amax() < tol(1e-6));
            assert!((data.acc[i].lin - r0.transpose() * pddot).amax() < tol(1e-4));
            assert!(
                (data.acc[i].ang - wdot).amax() < tol(1e-4),
                "seed {seed} body {i} wdot"
            );
        }
    }
}
