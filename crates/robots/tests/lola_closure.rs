//! Loop closure along a simulated trajectory (RK4, torque-free, 0.2 s at 1 ms), and mass and
//! height of the neutral pose, both read from the model's body poses.

use biped_dynamics::mechanism::ankle::AnkleDriveParams;
use biped_dynamics::mechanism::knee::KneeDriveParams;
use biped_dynamics::{
    center_of_mass, forward_dynamics, integrate, update_placements, Algorithm, Data, Model,
};
use biped_robots::lola::{self, LolaModel, LolaType};
use nalgebra::{DVector, Point3, Rotation3, Vector3};

/// Largest loop-closure error: knee nut pin vs. shank lever pin, ankle rod ends vs. nut and
/// foot balls (the mechanism parts are placed in closed form, so this must stay ~1e-15).
fn closure_error(m: &Model, data: &Data) -> f64 {
    let pose = |name: &str| data.body_pose(m.body_id(name).expect(name));
    let knee = KneeDriveParams::default();
    let ankle = AnkleDriveParams::default();
    // Knee frame in the shank body frame: x = -x, y = z, z = y (see `lola::assemble`).
    let rk = Rotation3::from_basis_unchecked(&[-Vector3::x(), Vector3::z(), Vector3::y()]);
    let mut err: f64 = 0.0;
    for side in ["l", "r"] {
        let pin = rk * Vector3::new(knee.pin_shank.x, knee.pin_shank.y, 0.0);
        let lever = pose(&format!("{side}_shank")) * Point3::from(pin);
        let nut = pose(&format!("{side}_shank_screw_nut")) * Point3::origin();
        err = err.max((lever - nut).norm());
        for (k, act) in ankle.actuators.iter().enumerate() {
            let foot = pose(&format!("{side}_foot")) * Point3::from(act.foot_ball);
            let rod = pose(&format!("{side}_foot_ankle_rod_{k}"));
            let nut = pose(&format!("{side}_foot_ankle_nut_{k}")) * Point3::origin();
            let rod_end = rod * Point3::new(0.0, 0.0, act.rod_length);
            err = err.max((rod_end - foot).norm());
            err = err.max((rod * Point3::origin() - nut).norm());
        }
    }
    err
}

/// Mid-range pose with small joint velocities.
fn start(lm: &LolaModel) -> (DVector<f64>, DVector<f64>) {
    let mut q = lm.model.neutral();
    let mut v = DVector::zeros(lm.model.nv());
    for (k, l) in lm.limits.iter().enumerate() {
        q[l.q_index] = 0.5 * (l.lower + l.upper);
        v[l.v_index] = 0.2 * ((k as f64) * 0.7).sin();
    }
    for g in &lm.gears {
        q[g.motor_q] = g.ratio * q[g.link_q];
        v[g.motor_v] = g.ratio * v[g.link_v];
    }
    (q, v)
}

/// One RK4 step of the torque-free dynamics on the configuration manifold.
fn rk4(
    m: &Model,
    data: &mut Data,
    q: &DVector<f64>,
    v: &DVector<f64>,
    h: f64,
) -> (DVector<f64>, DVector<f64>) {
    let tau = DVector::zeros(m.nv());
    let mut acc = |q: &DVector<f64>, v: &DVector<f64>| {
        forward_dynamics(m, data, q, v, &tau, None, Algorithm::On)
            .unwrap()
            .clone()
    };
    let a1 = acc(q, v);
    let q2 = integrate(m, q, v, h / 2.0).unwrap();
    let v2 = v + &a1 * (h / 2.0);
    let a2 = acc(&q2, &v2);
    let q3 = integrate(m, q, &v2, h / 2.0).unwrap();
    let v3 = v + &a2 * (h / 2.0);
    let a3 = acc(&q3, &v3);
    let q4 = integrate(m, q, &v3, h).unwrap();
    let v4 = v + &a3 * h;
    let a4 = acc(&q4, &v4);
    let vbar = (v + &v2 * 2.0 + &v3 * 2.0 + &v4) / 6.0;
    let abar = (a1 + a2 * 2.0 + a3 * 2.0 + a4) / 6.0;
    (integrate(m, q, &vbar, h).unwrap(), v + abar * h)
}

#[test]
fn loops_stay_closed_along_a_trajectory() {
    for kind in [LolaType::Type2, LolaType::Type3] {
        let lm = lola::build(kind).unwrap();
        let m = &lm.model;
        let mut data = Data::new(m);
        let (mut q, mut v) = start(&lm);
        let q0 = q.clone();
        let mut worst: f64 = 0.0;
        for step in 0..200 {
            (q, v) = rk4(m, &mut data, &q, &v, 1e-3);
            if step % 20 == 19 {
                update_placements(m, &mut data, &q).unwrap();
                worst = worst.max(closure_error(m, &data));
            }
        }
        let moved = lm
            .limits
            .iter()
            .map(|l| (q[l.q_index] - q0[l.q_index]).abs())
            .fold(0.0, f64::max);
        assert!(moved > 1e-3, "{kind:?}: the joints should move ({moved})");
        assert!(worst < 1e-10, "{kind:?}: loop closure error {worst:e}");
    }
}

#[test]
fn neutral_pose_is_about_60_kg_and_1_8_m() {
    for kind in [LolaType::Type2, LolaType::Type3] {
        let lm = lola::build(kind).unwrap();
        let m = &lm.model;
        let mut data = Data::new(m);
        let q = m.neutral();
        let com = center_of_mass(m, &mut data, &q, None).unwrap();
        // Independent sum of the body masses.
        let total: f64 = m.bodies().iter().map(|b| b.inertia().mass()).sum();
        assert!((com.mass - total).abs() < 1e-12);
        assert!(
            (55.0..65.0).contains(&com.mass),
            "{kind:?}: mass {}",
            com.mass
        );
        update_placements(m, &mut data, &q).unwrap();
        let z = |name: &str| {
            data.body_pose(m.body_id(name).unwrap())
                .translation
                .vector
                .z
        };
        let height = z("head_top") - z("l_sole").min(z("r_sole"));
        assert!((1.75..1.85).contains(&height), "{kind:?}: height {height}");
        assert!((z("l_sole") - z("r_sole")).abs() < 1e-12);
        // CoM between the soles and the head, around hip height.
        let rel = (com.position.z - z("l_sole")) / height;
        assert!(
            (0.45..0.65).contains(&rel),
            "{kind:?}: CoM at {rel} of the height"
        );
    }
}

/// Kinetic + gravity + gear-spring energy of a Type 3 state.
fn energy(lm: &LolaModel, data: &mut Data, q: &DVector<f64>, v: &DVector<f64>, k: f64) -> f64 {
    let m = &lm.model;
    let mass = biped_dynamics::mass_matrix(m, data, q).unwrap().clone();
    let kinetic = 0.5 * v.dot(&(&mass * v));
    let com = center_of_mass(m, data, q, None).unwrap();
    kinetic - com.mass * m.gravity().dot(&com.position) + lm.gear_energy(q, k)
}

#[test]
fn elastic_gears_conserve_energy_and_keep_loops_closed() {
    let lm = lola::build(LolaType::Type3).unwrap();
    let m = &lm.model;
    let mut data = Data::new(m);
    let (mut q, mut v) = start(&lm);
    // Deflect every gear a little so the springs work.
    for (i, g) in lm.gears.iter().enumerate() {
        q[g.motor_q] += 0.01 * g.ratio * ((i as f64) * 1.3).cos();
    }
    let k = 100.0;
    let e0 = energy(&lm, &mut data, &q, &v, k);
    let spring0 = lm.gear_energy(&q, k);
    let h = 1e-4;
    for _ in 0..500 {
        let tau_of = |q: &DVector<f64>, v: &DVector<f64>| {
            let mut tau = DVector::zeros(m.nv());
            lm.add_gear_forces(q, v, k, 0.0, &mut tau);
            tau
        };
        // RK4 with state-dependent gear forces.
        let mut acc = |q: &DVector<f64>, v: &DVector<f64>| {
            let tau = tau_of(q, v);
            forward_dynamics(m, &mut data, q, v, &tau, None, Algorithm::On)
                .unwrap()
                .clone()
        };
        let a1 = acc(&q, &v);
        let q2 = integrate(m, &q, &v, h / 2.0).unwrap();
        let v2 = &v + &a1 * (h / 2.0);
        let a2 = acc(&q2, &v2);
        let q3 = integrate(m, &q, &v2, h / 2.0).unwrap();
        let v3 = &v + &a2 * (h / 2.0);
        let a3 = acc(&q3, &v3);
        let q4 = integrate(m, &q, &v3, h).unwrap();
        let v4 = &v + &a3 * h;
        let a4 = acc(&q4, &v4);
        let vbar = (&v + &v2 * 2.0 + &v3 * 2.0 + &v4) / 6.0;
        q = integrate(m, &q, &vbar, h).unwrap();
        v += (a1 + a2 * 2.0 + a3 * 2.0 + a4) * (h / 6.0);
    }
    update_placements(m, &mut data, &q).unwrap();
    let worst = closure_error(m, &data);
    let e1 = energy(&lm, &mut data, &q, &v, k);
    assert!(worst < 1e-10, "loop closure {worst:e}");
    assert!(
        (e1 - e0).abs() < 1e-6 * e0.abs().max(1.0),
        "energy drift {} (E0 = {e0}, spring energy at start {spring0})",
        e1 - e0
    );
}
