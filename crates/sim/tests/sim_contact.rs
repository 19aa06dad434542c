//! Contact layer: a falling box comes to rest at the static penetration of the contact law, a
//! sliding box stops after `v0^2 / (2 mu g)`, stiction holds, foot chains agree with the
//! dynamics kinematics, foot wrenches agree with the body wrenches.

mod common;

use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::contact::{sole_rectangle, ContactParams, FootSpec};
use biped_sim::ode::{Method, OdeSystem};
use biped_sim::plant::{Plant, PlantConfig};
use nalgebra::{DVector, Vector3};
use rand::{Rng, SeedableRng};

const SIZE: [f64; 3] = [0.3, 0.2, 0.1];
const MASS: f64 = 5.0;

fn box_plant(contact: ContactParams) -> Plant {
    let feet = [FootSpec {
        name: "sole".into(),
        body: "box".into(),
        points: sole_rectangle(Vector3::new(0.0, 0.0, -0.05), 0.3, 0.2),
        reference: Vector3::new(0.0, 0.0, -0.05),
        part_of: None,
    }];
    let config = PlantConfig {
        contact,
        ..PlantConfig::default()
    };
    Plant::new(common::free_box(MASS, SIZE), vec![], &feet, vec![], config).unwrap()
}

/// Box state at height `z` (origin) with linear velocity `vel` (world = body, no rotation).
fn box_state(plant: &Plant, z: f64, vel: [f64; 3]) -> Vec<f64> {
    let mut q = plant.model().neutral();
    q[2] = z;
    let mut v = DVector::zeros(6);
    v.fixed_rows_mut::<3>(0).copy_from_slice(&vel);
    plant.initial_state(&q, &v).unwrap()
}

fn settles_at_static_penetration(exponent: f64, stiffness: f64) {
    let params = ContactParams {
        exponent,
        stiffness,
        ..ContactParams::default()
    };
    let mut plant = box_plant(params);
    let mut z = box_state(&plant, 0.05 + 0.05, [0.0; 3]);
    common::integrate(&mut plant, Method::Rk4, 5e-4, &mut z, 6000, |_, _, _| {});
    // Independent: 8 points share m g equally, k delta^e = m g / 8.
    let delta = (MASS * 9.81 / 8.0 / stiffness).powf(1.0 / exponent);
    let height = 0.05 - delta;
    assert!(
        (z[2] - height).abs() < 1e-4 * delta,
        "z {} expected {height} (delta {delta})",
        z[2]
    );
    assert!(
        z[7..13].iter().all(|v| v.abs() < 1e-9),
        "not at rest: {:?}",
        &z[7..13]
    );
}

#[test]
fn falling_box_rests_at_the_static_penetration_linear_law() {
    settles_at_static_penetration(1.0, 2.0e5);
}

#[test]
fn falling_box_rests_at_the_static_penetration_hertz_law() {
    settles_at_static_penetration(1.5, 2.0e7);
}

#[test]
fn sliding_box_stops_after_coulomb_distance_and_then_sticks() {
    let mu = 0.5;
    let mut plant = box_plant(ContactParams {
        friction: mu,
        ..ContactParams::default()
    });
    let delta = ContactParams::default().static_penetration(MASS * 9.81 / 8.0);
    let v0 = 1.0;
    let mut z = box_state(&plant, 0.05 - delta, [v0, 0.0, 0.0]);
    let mut stop = None;
    common::integrate(&mut plant, Method::Rk4, 2.5e-4, &mut z, 8000, |t, z, _| {
        if stop.is_none() && z[7] <= 1e-6 {
            stop = Some((t, z[0]));
        }
    });
    let (t_stop, x_stop) = stop.expect("box never stopped");
    // Independent: constant Coulomb deceleration mu g.
    let (g, x_exp, t_exp) = (9.81, v0 * v0 / (2.0 * mu * 9.81), v0 / (mu * 9.81));
    assert!(
        (x_stop - x_exp).abs() < 0.01 * x_exp,
        "stop at {x_stop}, expected {x_exp}"
    );
    assert!(
        (t_stop - t_exp).abs() < 0.01 * t_exp,
        "stopped at t {t_stop}, expected {t_exp} (g {g})"
    );
    // Stiction: after stopping it stays put (bristle deflection ~ mu m g / (8 k_t) at most).
    assert!(
        (z[0] - x_stop).abs() < 1e-4,
        "drifted from {x_stop} to {}",
        z[0]
    );
    assert!(z[7].abs() < 1e-6);
}

#[test]
fn foot_chains_agree_with_the_dynamics_kinematics_and_wrenches_add_up() {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(5);
    let (mut q, v) = lp.lola.random_state(&mut |a, b| rng.random_range(a..b));
    let plant = &mut lp.plant;
    // Lowest point 1 mm below the ground: some points in contact, some above.
    q[2] -= plant.contact().lowest_point(q.as_slice(), v.len()) + 1e-3;
    let z = plant.initial_state(&q, &v).unwrap();
    let mut zdot = vec![0.0; z.len()];
    plant.rhs(0.0, &z, &mut zdot).unwrap();
    let out = plant.last_outputs().contact.clone();
    let bodies: Vec<_> = plant.contact().bodies().collect();
    let specs: Vec<_> = plant.contact().specs().cloned().collect();
    let mut in_contact = 0;
    for (k, &b) in bodies.iter().enumerate() {
        let d = plant.data();
        let st = &out.foot_states[k];
        let r = d.world_rot[b];
        assert!((st.rot - r).norm() < 1e-12);
        assert!((st.pos - d.world_pos[b]).norm() < 1e-12);
        assert!((st.omega - r * d.vel[b].ang).norm() < 1e-10);
        assert!((st.vel - r * d.vel[b].lin).norm() < 1e-10);
        // Body wrench (body frame, about the origin) vs foot wrench (world, about reference).
        let w = plant.external_wrenches()[b];
        let f = &out.feet[k];
        in_contact += f.points_in_contact;
        assert!((r * w.lin - f.force).norm() < 1e-9 * (1.0 + f.force.norm()));
        let reference = st.pos + r * specs[k].reference;
        let torque_ref = r * w.ang - (reference - st.pos).cross(&(r * w.lin));
        assert!((torque_ref - f.torque).norm() < 1e-9 * (1.0 + f.torque.norm()));
    }
    assert!(in_contact > 0, "the random state should touch the ground");
}

/// `sliding_velocity` is the point velocity minus the bristle rate of `tangential`: zero while
/// the trial force lies inside the cone, antiparallel to the force on it.
#[test]
fn sliding_velocity_is_the_velocity_the_bristle_does_not_take_up() {
    use nalgebra::Vector2;
    let p = ContactParams::default();
    let mut rng = rand::rngs::StdRng::seed_from_u64(3);
    let (mut stuck, mut slid) = (0, 0);
    for _ in 0..2000 {
        let s = Vector2::new(rng.random_range(-5e-4..5e-4), rng.random_range(-5e-4..5e-4));
        let v = Vector2::new(rng.random_range(-0.2..0.2), rng.random_range(-0.2..0.2));
        let f_n = rng.random_range(0.0..200.0);
        let (f, rate) = p.tangential(s, v, f_n);
        let u = p.sliding_velocity(s, v, f);
        assert!(
            (u - (v - rate)).norm() < 1e-9 * (1.0 + v.norm()),
            "{u} vs {}",
            v - rate
        );
        let trial = -(s * p.tangential_stiffness + v * p.tangential_damping);
        if trial.norm() <= p.friction * f_n {
            assert!(u.norm() < 1e-12, "sticking point slides at {u}");
            stuck += 1;
        } else {
            assert!(
                u.dot(&f) <= 1e-12 * u.norm() * f.norm() + 1e-300,
                "{u} vs force {f}"
            );
            slid += 1;
        }
    }
    assert!(stuck > 50 && slid > 50, "{stuck} stuck, {slid} slid");
}

/// The side's slip speed integrated over a slide is the distance the box slid (Coulomb
/// deceleration from 1 m/s on `mu = 0.5`, then stiction), up to the bristles' deflection; a box
/// at rest on the ground does not slip.
#[test]
fn side_slip_speed_integrates_to_the_sliding_distance() {
    let mut plant = box_plant(ContactParams {
        friction: 0.5,
        ..ContactParams::default()
    });
    let delta = ContactParams::default().static_penetration(MASS * 9.81 / 8.0);
    let mut z = box_state(&plant, 0.05 - delta, [1.0, 0.0, 0.0]);
    let x0 = z[0];
    let h = 2.5e-4;
    let mut slid = 0.0;
    let mut at_rest = 0.0_f64;
    common::integrate(&mut plant, Method::Rk4, h, &mut z, 8000, |t, z, p| {
        let bristles = &z[p.layout().contact()];
        let out = p.outputs(z).unwrap().contact.clone();
        let speed = p.contact().side_slip_speed(0, bristles, &out);
        slid += speed * h;
        if t > 1.0 {
            at_rest = at_rest.max(speed);
        }
    });
    let travelled = z[0] - x0;
    println!("slid {slid}, travelled {travelled}, at rest {at_rest}");
    // The sum samples the end of each step: v0 h / 2 = 1.25e-4 m short of the integral; the
    // bristles' deflection is at most mu m g / (8 k_t) = 1.5e-5 m.
    assert!(
        (slid - travelled).abs() < 2e-4,
        "slid {slid}, travelled {travelled}"
    );
    assert!(travelled > 0.09, "{travelled}");
    assert!(at_rest < 1e-6, "at rest: {at_rest}");
}
