//! Cross-check of the kinematics fast paths (the per-body step kinds chosen in `Data::new`:
//! written-out plane rotations, translation-only frames, skipped or reduced axial members)
//! against the general joint kinematics and child step for every body
//! (`general_forward_kinematics`). Shared by `kin_step_kinds` (URDF model) and
//! `biped_robots`' `lola_step_kinds` (included there with `#[path]`).

use biped_dynamics::kinematics::general_forward_kinematics;
use biped_dynamics::{forward_dynamics_kinematics, forward_kinematics, Data, Model, Motion};
use nalgebra::{DVector, Vector3};

/// The outputs of the first forward recursion for body `i`, flattened: `C_i`, world pose,
/// `g_i`, `v_i` (2.33), `b_i` (2.37).
fn outputs(d: &Data, i: usize) -> Vec<f64> {
    let mut out = d.x[i].to_matrix().as_slice().to_vec();
    out.extend(d.world_rot[i].iter());
    out.extend(d.world_pos[i].iter());
    out.extend(d.gravity_body[i].iter());
    out.extend(d.vel[i].to_vector().iter());
    out.extend(d.bias_acc[i].to_vector().iter());
    out
}

/// Largest `|fast - general| / max(1, |general|)` over the outputs of `bodies`.
fn deviation(fast: &Data, general: &Data, bodies: impl Iterator<Item = usize>) -> f64 {
    let pairs = bodies.flat_map(|i| outputs(fast, i).into_iter().zip(outputs(general, i)));
    pairs.fold(0.0, |m: f64, (a, b)| {
        m.max((a - b).abs() / b.abs().max(1.0))
    })
}

/// Deviation of `forward_kinematics` from the general path at `(q, v, a)`, over every body's
/// outputs and accelerations `a_i` (2.34).
pub fn fast_path_deviation(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
    a: &DVector<f64>,
) -> f64 {
    let (mut fast, mut general) = (Data::new(model), Data::new(model));
    forward_kinematics(model, &mut fast, q, v, a).expect("fast kinematics");
    general_forward_kinematics(model, &mut general, q, v, a).expect("general kinematics");
    let acc = (0..model.nbodies())
        .map(|i| (fast.acc[i] - general.acc[i]).to_vector().amax())
        .fold(0.0, f64::max);
    acc.max(deviation(&fast, &general, 0..model.nbodies()))
}

/// Deviation of `forward_dynamics_kinematics` from the general path at `(q, v)` over the
/// bodies that pass computes, and the bodies it leaves untouched (axial members), found by
/// poisoning every pose and velocity with NaN beforehand.
pub fn fd_pass_deviation(model: &Model, q: &DVector<f64>, v: &DVector<f64>) -> (f64, Vec<usize>) {
    let (mut fast, mut general) = (Data::new(model), Data::new(model));
    let nan = Vector3::from_element(f64::NAN);
    fast.world_pos.fill(nan);
    fast.vel.fill(Motion::new(nan, nan));
    forward_dynamics_kinematics(model, &mut fast, q, v).expect("forward-dynamics kinematics");
    let zero = DVector::zeros(model.nv());
    general_forward_kinematics(model, &mut general, q, v, &zero).expect("general kinematics");
    let skipped = |i: &usize| fast.world_pos[*i][0].is_nan() || fast.vel[*i].ang[0].is_nan();
    let computed = (0..model.nbodies()).filter(|i| !skipped(i));
    let dev = deviation(&fast, &general, computed);
    (dev, (0..model.nbodies()).filter(skipped).collect())
}
