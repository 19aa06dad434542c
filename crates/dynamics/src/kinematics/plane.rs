//! Body step of the first forward recursion (2.33)-(2.37) for a revolute (or geared-rotor)
//! joint about coordinate axis `K` of an unrotated placement (`Data::plane_axis == Some(K)`):
//! `A_kp = Rot_K(q)^T` has four non-trivial entries, `J_i qdot_i = [omega e_K; 0]` and
//! `Jdot_i qdot_i = 0`, so the products of the general step are written out with these zeros
//! dropped. Same results as the general step ([`super::step`]) up to the sign of zeros.

use crate::spatial::{sin_cos, Motion, SpatialTransform};
use crate::Data;
use nalgebra::{Matrix3, Vector3};

/// `A v` for `A = Rot_K(angle)^T` given by `(s, c)` (only the plane normal to `e_K` mixes).
#[inline(always)]
fn rot_mul<const K: usize>(s: f64, c: f64, v: &Vector3<f64>) -> Vector3<f64> {
    let (a, b) = ((K + 1) % 3, (K + 2) % 3);
    let mut out = *v;
    out[a] = c * v[a] + s * v[b];
    out[b] = c * v[b] - s * v[a];
    out
}

/// `(&v[p], &mut v[i])` for a parent `p < i` of body `i`: one bounds check (`i`) where
/// indexing twice checks both, and no reload of `v`'s pointer after the other stores.
#[inline(always)]
fn parent_child<T>(v: &mut [T], p: usize, i: usize) -> (&T, &mut T) {
    let (head, tail) = v[..=i].split_at_mut(i);
    (&head[p], &mut tail[0])
}

/// `C_i`, world pose, `g_i`, `v_i` (2.33) and `b_i` (2.37) of body `i` with parent `p < i`,
/// placement translation `trans`, angular joint axis `e_K` with scale `scale` at coordinate
/// and rate `(q, qd)`.
#[inline(always)]
pub(super) fn plane_revolute_step<const K: usize>(
    data: &mut Data,
    i: usize,
    p: usize,
    trans: &Vector3<f64>,
    scale: f64,
    (q, qd): (f64, f64),
) {
    let (a, b) = ((K + 1) % 3, (K + 2) % 3);
    let (s, c) = sin_cos(q * scale);
    // World rotation `W_p A^T`: columns a and b mix, column K is the parent's.
    let (wp, w_rot) = parent_child(&mut data.world_rot, p, i);
    let (pos_p, pos) = parent_child(&mut data.world_pos, p, i);
    *pos = pos_p + *wp * trans;
    let (ca, cb) = (wp.column(a).into_owned(), wp.column(b).into_owned());
    *w_rot = *wp;
    w_rot.set_column(a, &(ca * c + cb * s));
    w_rot.set_column(b, &(cb * c - ca * s));
    let (gp, g) = parent_child(&mut data.gravity_body, p, i);
    *g = rot_mul::<K>(s, c, gp);
    // C v_p = [A w_p; A v_p + (A w_p) x (A r)], plus J qd = omega e_K.
    let (vp, vel) = parent_child(&mut data.vel, p, i);
    let w = rot_mul::<K>(s, c, &vp.ang);
    let rk = rot_mul::<K>(s, c, trans);
    let lin = rot_mul::<K>(s, c, &vp.lin) + w.cross(&rk);
    let omega = scale * qd;
    let mut ang = w;
    ang[K] += omega;
    *vel = Motion::new(ang, lin);
    // b = [w x (omega e_K); w x (w x r)] (2.37) with `Jdot qd = 0`, no relative linear motion.
    let mut bias_ang = Vector3::zeros();
    bias_ang[a] = w[b] * omega;
    bias_ang[b] = -(w[a] * omega);
    data.bias_acc[i] = Motion::new(bias_ang, w.cross(&w.cross(&rk)));
    let mut rot = Matrix3::identity();
    rot[(a, a)] = c;
    rot[(a, b)] = s;
    rot[(b, a)] = -s;
    rot[(b, b)] = c;
    data.x[i] = SpatialTransform::new(rot, *trans);
}

/// `C_i`, world pose, `g_i`, `v_i` (2.33) and `b_i` (2.37) of a fixed-joint body `i` (parent
/// `p < i`) whose placement `pl` is a pure translation (`A_kp = 1`): the general step with
/// the identity products dropped, `v_i = [w_p; v_p + w_p x r]`, `b_i = [0; w_p x (w_p x r)]`.
#[inline(always)]
pub(super) fn translation_step(data: &mut Data, i: usize, p: usize, pl: &SpatialTransform) {
    let (wp, w_rot) = parent_child(&mut data.world_rot, p, i);
    let (pos_p, pos) = parent_child(&mut data.world_pos, p, i);
    *pos = pos_p + *wp * pl.trans;
    *w_rot = *wp;
    let (gp, g) = parent_child(&mut data.gravity_body, p, i);
    *g = *gp;
    let (vp, vel) = parent_child(&mut data.vel, p, i);
    let wr = vp.ang.cross(&pl.trans);
    data.bias_acc[i] = Motion::new(Vector3::zeros(), vp.ang.cross(&wr));
    *vel = Motion::new(vp.ang, vp.lin + wr);
    data.x[i] = *pl;
}

#[cfg(test)]
mod tests {
    use super::super::step::{body_kinematics, general_body_kinematics};
    use crate::model::{BodySpec, JointModel, ModelBuilder};
    use crate::spatial::RigidInertia;
    use crate::{Data, Model};
    use nalgebra::{DVector, Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};
    use proptest::prelude::*;
    use rand::{Rng, SeedableRng};

    /// Random tree: revolute joints about coordinate axes (most placements translations only,
    /// some rotated), leaf fixed frames and leaf geared rotors about coordinate axes, each beside its driver (on
    /// the driver's parent, like a Harmonic Drive rotor).
    fn plane_tree(seed: u64) -> Model {
        let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
        let axes = [Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis()];
        let inertia = RigidInertia::new(1.0, Vector3::new(0.1, 0.0, 0.0), Matrix3::identity())
            .expect("valid inertia");
        let mut b = ModelBuilder::new();
        // (body, parent) of the revolute bodies.
        let mut revolute: Vec<(usize, Option<usize>)> = Vec::new();
        for i in 0..10 {
            let t = Vector3::new(rng.random(), rng.random(), rng.random()) * 0.4;
            let rot = if rng.random_range(0..4) == 0 {
                UnitQuaternion::from_euler_angles(rng.random(), rng.random(), rng.random())
            } else {
                UnitQuaternion::identity()
            };
            let axis = axes[rng.random_range(0..3)];
            let (joint, parent) = if i > 1 && rng.random_range(0..5) == 0 {
                let parent = revolute[rng.random_range(0..revolute.len())].0;
                (JointModel::Fixed, Some(parent))
            } else if i > 1 && rng.random_range(0..3) == 0 {
                let (driver, parent) = revolute[rng.random_range(1..revolute.len())];
                let ratio = rng.random_range(-100.0..100.0);
                (
                    JointModel::GearedRotor {
                        axis,
                        ratio,
                        driver,
                    },
                    parent,
                )
            } else {
                let parent = (i > 0).then(|| revolute[rng.random_range(0..revolute.len())].0);
                (JointModel::Revolute { axis }, parent)
            };
            let geared = matches!(joint, JointModel::GearedRotor { .. } | JointModel::Fixed);
            let id = b
                .add_body(BodySpec {
                    name: format!("b{i}"),
                    joint_name: format!("j{i}"),
                    parent,
                    joint,
                    placement: Isometry3::from_parts(Translation3::from(t), rot),
                    inertia,
                })
                .expect("body");
            if !geared {
                revolute.push((id, parent));
            }
        }
        b.build().expect("model")
    }

    /// The test trees hold both kinds of fast-path bodies (so the proptest exercises them).
    #[test]
    fn plane_trees_have_fixed_translation_frames() {
        use crate::model::joint::Joint;
        let fixed = (0..64)
            .map(plane_tree)
            .flat_map(|m| m.bodies.into_iter())
            .filter(|b| matches!(b.joint, Joint::Fixed) && b.placement_x.rot == Matrix3::identity())
            .count();
        assert!(fixed > 10, "{fixed}");
    }

    /// The trees hold plane and translation step kinds (so the proptest below, which
    /// compares them with the general step, exercises both).
    #[test]
    fn plane_trees_hold_plane_and_translation_kinds() {
        use super::super::step::StepKind;
        let mut kinds = [0; 2];
        for model in (0..64).map(plane_tree) {
            for kind in &Data::new(&model).step_kind {
                match kind {
                    StepKind::PlaneX(_) | StepKind::PlaneY(_) | StepKind::PlaneZ(_) => {
                        kinds[0] += 1
                    }
                    StepKind::Translation(_) => kinds[1] += 1,
                    _ => {}
                }
            }
        }
        assert!(kinds.iter().all(|&k| k > 10), "{kinds:?}");
    }

    /// Equal up to rounding: the written-out and the general products associate differently,
    /// and with FMA contraction (the build's default) they round differently.
    fn near(a: &[f64], b: &[f64]) -> bool {
        let scale = b.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-14 * scale)
    }

    /// Every output of a body step, flattened: `C_i`, world pose, `g_i`, `v_i`, `b_i`.
    fn outputs(d: &Data, i: usize) -> [(&'static str, Vec<f64>); 6] {
        [
            ("x", d.x[i].to_matrix().as_slice().to_vec()),
            ("world_rot", d.world_rot[i].as_slice().to_vec()),
            ("world_pos", d.world_pos[i].as_slice().to_vec()),
            ("gravity", d.gravity_body[i].as_slice().to_vec()),
            ("vel", d.vel[i].to_vector().as_slice().to_vec()),
            ("bias", d.bias_acc[i].to_vector().as_slice().to_vec()),
        ]
    }

    proptest! {
        /// The written-out plane and translation steps equal the general step (up to rounding)
        /// for every body and output, at random states of random plane trees.
        #[test]
        fn plane_step_equals_general_step(
            seed in 0u64..64,
            q in prop::collection::vec(-7.0f64..7.0, 10),
            v in prop::collection::vec(-5.0f64..5.0, 10),
        ) {
            let model = plane_tree(seed);
            let n = model.nv();
            let (q, v) = (DVector::from_column_slice(&q[..n]), DVector::from_column_slice(&v[..n]));
            let (mut fast, mut general) = (Data::new(&model), Data::new(&model));
            let mut planes = 0;
            for i in 0..model.nbodies() {
                planes += usize::from(fast.plane_axis[i].is_some());
                body_kinematics(&model, &mut fast, i, &q, Some(&v));
                general_body_kinematics(&model, &mut general, i, q.as_slice(), Some(v.as_slice()));
                for ((what, a), (_, b)) in outputs(&fast, i).into_iter().zip(outputs(&general, i)) {
                    prop_assert!(near(&a, &b), "body {i} {what}: {a:?} vs {b:?}");
                }
            }
            prop_assert!(planes > 0);
        }
    }
}
