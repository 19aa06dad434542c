//! Energy behaviour of frictionless, contact-free plants: RK4 drift is small and shrinks with
//! h^4; symplectic Euler's error stays bounded while explicit Euler's grows; Type 3 elastic
//! gears exchange energy with the links without loss.

mod common;

use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::drive::FrictionParams;
use biped_sim::ode::Method;
use biped_sim::plant::{Plant, PlantConfig};
use nalgebra::DVector;
use rand::{Rng, SeedableRng};

/// Lola high above the ground with random joint angles and velocities, lossless drives and
/// no end stops (the random velocities carry joints out of their ranges, where the stops'
/// dampers would take energy out).
fn flying_lola(variant: LolaType, gear_damping_ratio: f64) -> (Plant, Vec<f64>) {
    let mut config = PlantConfig {
        friction: FrictionParams::none(),
        gear_damping_ratio,
        ..PlantConfig::default()
    };
    config.passive.end_stops = false;
    let lp = lola_plant(variant, config).unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(11);
    let (mut q, v) = lp.lola.random_state(&mut |a, b| rng.random_range(a..b));
    q[2] = 3.0; // feet ~2 m up: no contact during the 0.5 s runs
    let z = lp.plant.initial_state(&q, &(v * 2.0)).unwrap();
    (lp.plant, z)
}

/// Largest `|E(t) - E(0)|` over `n` steps of `h`, and the energy scale `E_kin(0)`.
fn drift(plant: &mut Plant, z0: &[f64], method: Method, h: f64, n: usize) -> (f64, f64) {
    let mut z = z0.to_vec();
    let e0 = plant.energy(&z).unwrap();
    let mut worst = 0.0f64;
    common::integrate(plant, method, h, &mut z, n, |_, z, p| {
        let e = p.energy(z).unwrap().total();
        worst = worst.max((e - e0.total()).abs());
    });
    (worst, e0.kinetic)
}

#[test]
fn rk4_energy_drift_is_small_and_fourth_order_on_lola_type2() {
    let (mut plant, z0) = flying_lola(LolaType::Type2, 0.0);
    let (d1, scale) = drift(&mut plant, &z0, Method::Rk4, 2e-3, 250);
    let (d2, _) = drift(&mut plant, &z0, Method::Rk4, 1e-3, 500);
    println!("RK4 energy drift over 0.5 s: h=2ms {d1:.3e}, h=1ms {d2:.3e}, E_kin {scale:.3}");
    assert!(d2 < 1e-9 * scale, "drift {d2} vs kinetic energy {scale}");
    let ratio = d1 / d2;
    assert!(
        ratio > 8.0 && ratio < 40.0,
        "halving h should cut the drift ~16x, got {ratio}"
    );
}

#[test]
fn type3_elastic_gears_conserve_energy_without_damping() {
    let (mut plant, z0) = flying_lola(LolaType::Type3, 0.0);
    let e0 = plant.energy(&z0).unwrap();
    assert!(e0.gears > 0.0, "random gear deflections store energy");
    // The toe's gear mode (~9000 rad/s) needs small steps; check 4th-order convergence.
    let (d1, scale) = drift(&mut plant, &z0, Method::Rk4, 5e-5, 400);
    let (d2, _) = drift(&mut plant, &z0, Method::Rk4, 2.5e-5, 800);
    println!("Type 3 RK4 drift over 20 ms: h=50us {d1:.3e}, h=25us {d2:.3e}, E_kin {scale:.3}, E_gear {:.3}", e0.gears);
    assert!(d2 < 1e-6 * scale);
    assert!(d1 / d2 > 8.0, "not converging at 4th order: {d1} -> {d2}");
    // With gear damping the energy must decrease.
    let (mut damped, z0) = flying_lola(LolaType::Type3, 0.05);
    let mut z = z0.clone();
    let e_start = damped.energy(&z).unwrap().total();
    common::integrate(&mut damped, Method::Rk4, 2.5e-4, &mut z, 400, |_, _, _| {});
    assert!(damped.energy(&z).unwrap().total() < e_start - 1e-3 * e0.gears);
}

#[test]
fn symplectic_euler_energy_error_stays_bounded_explicit_euler_drifts() {
    let config = PlantConfig::default();
    let mut plant = Plant::new(common::pendulum(2), vec![], &[], vec![], config).unwrap();
    let q = DVector::from_vec(vec![0.3, -0.2]);
    let z0 = plant.initial_state(&q, &DVector::zeros(2)).unwrap();
    let e0 = plant.energy(&z0).unwrap().total();
    let (h, n) = (1e-3, 20_000);
    let mut err = vec![0.0; n];
    let mut z = z0.clone();
    common::integrate(&mut plant, Method::Symplectic, h, &mut z, n, |t, z, p| {
        let k = ((t / h).round() as usize).saturating_sub(1);
        err[k] = (p.energy(z).unwrap().total() - e0).abs();
    });
    let max = |s: &[f64]| s.iter().fold(0.0f64, |m, x| m.max(*x));
    let (first, last) = (max(&err[..n / 4]), max(&err[3 * n / 4..]));
    println!("symplectic Euler |dE|: first quarter {first:.3e}, last quarter {last:.3e}");
    assert!(
        last < 1.5 * first,
        "symplectic Euler energy error grew: {first} -> {last}"
    );
    let mut z = z0.clone();
    common::integrate(&mut plant, Method::Euler, h, &mut z, n, |_, _, _| {});
    let euler = (plant.energy(&z).unwrap().total() - e0).abs();
    println!("explicit Euler |dE| after 20 s: {euler:.3e}");
    assert!(
        euler > 10.0 * last,
        "explicit Euler should drift: {euler} vs {last}"
    );
}
