//! Small models shared by the simulation tests.
#![allow(dead_code)]

use biped_dynamics::{BodySpec, JointModel, Model, ModelBuilder, RigidInertia};
use biped_sim::controller::JointPd;
use biped_sim::ode::{Integrator, Method, Settings};
use biped_sim::plant::Plant;
use nalgebra::{Isometry3, Matrix3, Vector3};

/// Inertia of a solid box of mass `m` and edge lengths `s`, centred at the origin.
pub fn box_inertia(m: f64, s: [f64; 3]) -> RigidInertia {
    let [a, b, c] = s.map(|x| x * x);
    let d = Vector3::new(b + c, a + c, a + b) * (m / 12.0);
    RigidInertia::new(m, Vector3::zeros(), Matrix3::from_diagonal(&d)).unwrap()
}

/// Axial inertia of the spinner's 1 kg, 0.2 m cube: `m (a^2 + b^2) / 12`.
pub const SPINNER_I_ZZ: f64 = 1.0 * (0.04 + 0.04) / 12.0;

/// One revolute joint `spin` (axis z, no gravity torque) carrying a 1 kg, 0.2 m cube `rotor`.
pub fn spinner() -> Model {
    let mut b = ModelBuilder::new();
    b.add_body(BodySpec {
        name: "rotor".into(),
        joint_name: "spin".into(),
        parent: None,
        joint: JointModel::Revolute {
            axis: Vector3::z_axis(),
        },
        placement: Isometry3::identity(),
        inertia: box_inertia(1.0, [0.2, 0.2, 0.2]),
    })
    .unwrap();
    b.build().unwrap()
}

/// One free box body named "box".
pub fn free_box(m: f64, s: [f64; 3]) -> Model {
    let mut b = ModelBuilder::new();
    b.add_body(BodySpec {
        name: "box".into(),
        joint_name: "root".into(),
        parent: None,
        joint: JointModel::FreeQuaternion,
        placement: Isometry3::identity(),
        inertia: box_inertia(m, s),
    })
    .unwrap();
    b.build().unwrap()
}

/// A chain of `n` revolute links (axis y, 0.3 m long rods hanging along -z) on the world.
pub fn pendulum(n: usize) -> Model {
    let mut b = ModelBuilder::new();
    let mut parent = None;
    for i in 0..n {
        let z = if i == 0 { 0.0 } else { -0.3 };
        let mut inertia = box_inertia(1.0, [0.03, 0.03, 0.3]);
        inertia = RigidInertia::new(
            1.0,
            Vector3::new(0.0, 0.0, -0.15),
            inertia.inertia_about_com(),
        )
        .unwrap();
        let id = b
            .add_body(BodySpec {
                name: format!("link{i}"),
                joint_name: format!("joint{i}"),
                parent,
                joint: JointModel::Revolute {
                    axis: Vector3::y_axis(),
                },
                placement: Isometry3::translation(0.0, 0.0, z),
                inertia,
            })
            .unwrap();
        parent = Some(id);
    }
    b.build().unwrap()
}

/// A PD controller without actuators (passive plants).
pub fn passive(period: f64) -> JointPd {
    JointPd::new(period, vec![], vec![], vec![]).unwrap()
}

/// Integrates the plant with held commands from `t0` for `n` steps of `h`, calling `each`
/// after every step.
pub fn integrate(
    plant: &mut Plant,
    method: Method,
    h: f64,
    z: &mut [f64],
    n: usize,
    mut each: impl FnMut(f64, &[f64], &mut Plant),
) {
    let mut integ = Integrator::new(method, z.len(), Settings::fixed(h)).unwrap();
    for k in 0..n {
        let (t0, t1) = (k as f64 * h, (k + 1) as f64 * h);
        integ.advance_split(plant, t0, t1, z).unwrap();
        each(t1, z, plant);
    }
}

/// A random state of a standing Lola plant near `z0`: joint angles moved by up to 0.05 rad,
/// the base sunk or lifted a few mm (some sole points touch, some not), a slightly
/// unnormalised quaternion (as inside an RK4 step), random velocities, bristles and currents.
pub fn random_stand_state(plant: &Plant, z0: &[f64], rng: &mut rand::rngs::StdRng) -> Vec<f64> {
    use rand::Rng;
    let l = plant.layout();
    let mut z = z0.to_vec();
    for x in &mut z[l.q().start + 7..l.q().end] {
        *x += rng.random_range(-0.05..0.05);
    }
    z[2] += rng.random_range(-0.002..0.003);
    z[6] *= 1.0 + 1e-4;
    for x in &mut z[l.v()] {
        *x = rng.random_range(-0.5..0.5);
    }
    for x in &mut z[l.contact().start..] {
        *x = rng.random_range(-1e-4..1e-4);
    }
    z
}
