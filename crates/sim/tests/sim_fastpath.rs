//! The plant's right-hand side (one kinematics pass shared by contact, drives and dynamics,
//! cached constant motor rows) equals the general route assembled here from public parts:
//! contact forces from the foot chains, every motor row re-evaluated from its mechanism,
//! the end stops law by law, `forward_dynamics` in one call. Lola Type 2 and Type 3, all drive modes, random states
//! with feet in and out of contact, unnormalised quaternions (as inside an RK4 step).

mod common;

use biped_dynamics::{forward_dynamics, Algorithm, Data, Wrench};
use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::controller::Commands;
use biped_sim::drive::DriveMode;
use biped_sim::ode::OdeSystem;
use biped_sim::plant::kinematics::QdotMap;
use biped_sim::plant::{Plant, PlantConfig};
use biped_sim::scenario::{build, ScenarioKind, ScenarioOptions};
use nalgebra::DVector;
use rand::{Rng, SeedableRng};

/// `zdot` and the contact/drive outputs by the general route.
fn reference(p: &Plant, z: &[f64]) -> (Vec<f64>, Vec<Wrench>) {
    let (l, m) = (p.layout(), p.model());
    let (q, v) = (&z[l.q()], &z[l.v()]);
    let mut zdot = vec![0.0; l.dim()];
    let mut fext = vec![Wrench::zero(); m.nbodies()];
    let mut out = p.contact().output();
    let (s, sdot) = (&z[l.contact()], &mut zdot[l.contact()]);
    p.contact().evaluate(q, v, s, sdot, &mut fext, &mut out);
    let mut tau = vec![0.0; l.nv];
    for (k, a) in p.actuators().iter().enumerate() {
        let row = a.motor_row(m, q).unwrap();
        let i = if p.mode() == DriveMode::Voltage {
            z[l.currents().start + k]
        } else {
            0.0
        };
        let ds = a.apply(row.as_ref(), p.mode(), p.commands()[k], i, v, &mut tau);
        if p.mode() == DriveMode::Voltage {
            zdot[l.currents().start + k] = ds.current_rate;
        }
    }
    let k = p.config().gear_stiffness;
    assert!(p.gears().is_empty() || p.config().gear_damping_ratio == 0.0);
    for g in p.gears() {
        let t = k * (q[g.motor_q] / g.ratio - q[g.link_q]);
        tau[g.link_v] += t;
        tau[g.motor_v] -= t / g.ratio;
    }
    for stop in p.passive().stops() {
        tau[stop.v] += stop.torque(q[stop.q], v[stop.v]);
    }
    let mut d = Data::new(m);
    let (qd, vd, td) = (
        DVector::from_column_slice(q),
        DVector::from_column_slice(v),
        DVector::from_column_slice(&tau),
    );
    let ddq = forward_dynamics(m, &mut d, &qd, &vd, &td, Some(&fext), Algorithm::On).unwrap();
    zdot[l.v()].copy_from_slice(ddq.as_slice());
    QdotMap::new(m).qdot(q, v, &mut zdot[l.q()]);
    (zdot, fext)
}

/// Compares at one random state; returns the number of points in contact.
fn compare(kind: LolaType, mode: DriveMode, seed: u64) -> usize {
    let config = PlantConfig {
        mode,
        gear_damping_ratio: 0.0,
        ..PlantConfig::default()
    };
    let mut lp = lola_plant(kind, config).unwrap();
    let opts = ScenarioOptions::lola();
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &opts).unwrap();
    let mut p = lp.plant;
    let l = p.layout();
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let z = common::random_stand_state(&p, &sc.z0, &mut rng);
    let cmd: Vec<f64> = (0..p.actuators().len())
        .map(|_| rng.random_range(-2.0..2.0))
        .collect();
    p.set_commands(&Commands { mode, values: cmd }).unwrap();
    let (zref, fref) = reference(&p, &z);
    let mut zdot = vec![0.0; l.dim()];
    p.rhs(0.0, &z, &mut zdot).unwrap();
    let scale = zref.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    for (i, (a, b)) in zdot.iter().zip(&zref).enumerate() {
        assert!(
            (a - b).abs() <= 1e-10 * scale,
            "{kind:?} {mode:?} zdot[{i}] {a} vs {b}"
        );
    }
    for (a, b) in p.external_wrenches().iter().zip(&fref) {
        let d = (a.ang - b.ang).norm() + (a.lin - b.lin).norm();
        assert!(d <= 1e-9 * (1.0 + b.lin.norm()), "fext {a:?} vs {b:?}");
    }
    let fast = p.last_outputs().clone();
    let general = p.outputs(&z).unwrap();
    for (a, b) in fast.contact.feet.iter().zip(&general.contact.feet) {
        assert_eq!(a.points_in_contact, b.points_in_contact);
        assert!((a.force - b.force).norm() <= 1e-9 * (1.0 + b.force.norm()));
        assert!((a.torque - b.torque).norm() <= 1e-9 * (1.0 + b.torque.norm()));
    }
    for (a, b) in fast
        .contact
        .foot_states
        .iter()
        .zip(&general.contact.foot_states)
    {
        assert!((a.rot - b.rot).norm() + (a.pos - b.pos).norm() < 1e-12);
        assert!((a.omega - b.omega).norm() + (a.vel - b.vel).norm() < 1e-12);
    }
    for (a, b) in fast.drives.iter().zip(&general.drives) {
        assert!(
            (a.speed - b.speed).abs() <= 1e-12 * (1.0 + b.speed.abs()),
            "{a:?} {b:?}"
        );
        assert!((a.friction - b.friction).abs() <= 1e-12 * (1.0 + b.friction.abs()));
        assert_eq!((a.torque, a.current), (b.torque, b.current));
        let r = (a.current_rate - b.current_rate).abs();
        assert!(r <= 1e-12 * (1.0 + b.current_rate.abs()), "{a:?} {b:?}");
    }
    fast.contact.feet.iter().map(|f| f.points_in_contact).sum()
}

#[test]
fn rhs_equals_the_general_route_type2() {
    for (s, mode) in [DriveMode::Torque, DriveMode::Current, DriveMode::Voltage]
        .into_iter()
        .enumerate()
    {
        let touching: Vec<usize> = (0..4)
            .map(|k| compare(LolaType::Type2, mode, 10 * s as u64 + k))
            .collect();
        assert!(
            touching.iter().any(|&n| n > 0) && touching.iter().any(|&n| n < 16),
            "{touching:?}"
        );
    }
}

#[test]
fn rhs_equals_the_general_route_type3() {
    let touching: usize = (0..3)
        .map(|k| compare(LolaType::Type3, DriveMode::Torque, 100 + k))
        .sum();
    assert!(touching > 0);
}

/// `zdot`, external wrenches and contact outputs of `p.rhs(z)` as bits.
fn rhs_bits(p: &mut Plant, z: &[f64]) -> Vec<u64> {
    let mut zdot = vec![0.0; p.layout().dim()];
    p.rhs(0.0, z, &mut zdot).unwrap();
    let wrenches = p.external_wrenches().iter().flat_map(|w| {
        let v = w.to_vector();
        (0..6).map(move |k| v[k])
    });
    let feet = p.last_outputs().contact.feet.iter().flat_map(|f| {
        let (a, b) = (f.force, f.torque);
        [a.x, a.y, a.z, b.x, b.y, b.z]
    });
    let points = p.last_outputs().contact.point_forces.iter();
    let points = points.flat_map(|f| [f.x, f.y, f.z]);
    zdot.into_iter()
        .chain(wrenches)
        .chain(feet)
        .chain(points)
        .map(f64::to_bits)
        .collect::<Vec<_>>()
}

/// The contact result a sensor sample (state pass) leaves for the first Runge-Kutta stage is
/// recalled only at bitwise the same state, after a command change too, and gives bitwise the
/// right-hand side of a plant that never sampled; a state differing in one bristle state, one
/// velocity or a chain-route evaluation in between make the stage evaluate the contact again.
#[test]
fn state_pass_contact_is_reused_exactly() {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &ScenarioOptions::lola()).unwrap();
    let fresh = lp.plant;
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    for _ in 0..6 {
        let z = common::random_stand_state(&fresh, &sc.z0, &mut rng);
        let mut cmd = || Commands {
            mode: DriveMode::Torque,
            values: (0..fresh.actuators().len())
                .map(|_| rng.random_range(-2.0..2.0))
                .collect(),
        };
        let (c0, c1) = (cmd(), cmd());
        let l = fresh.layout();
        let mut nudged = [z.clone(), z.clone()];
        nudged[0][l.contact().start + 3] += 1e-7;
        nudged[1][l.v().start + 7] += 1e-7;
        for (after, other) in [(None, None), (Some(&z), None), (None, Some(&nudged[0]))]
            .into_iter()
            .chain([(None, Some(&nudged[1]))])
        {
            let target = other.unwrap_or(&z);
            let mut reference = fresh.clone();
            reference.set_commands(&c1).unwrap();
            let expect = rhs_bits(&mut reference, target);
            let mut p = fresh.clone();
            p.set_commands(&c0).unwrap();
            p.state_outputs(&z).unwrap();
            if let Some(z) = after {
                p.outputs(z).unwrap();
            }
            p.set_commands(&c1).unwrap();
            assert_eq!(rhs_bits(&mut p, target), expect);
            // A second stage at the same state (the memo is used once) agrees as well.
            assert_eq!(rhs_bits(&mut p, target), expect);
        }
    }
}
