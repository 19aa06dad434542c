//! `stand` on Lola Type 2 with RK4 at the 1 kHz control period (issue item 9): wall time of
//! 0.2 s simulated (real-time factor = 0.2 s / time), and the parts of one right-hand side:
//! the whole rhs (alternating two states, and at one state, where the kinematics pass of the
//! previous call is reused as by RK4's first stage after the sensors' state pass), the state
//! pass, the forward dynamics alone, contact + drives without dynamics, and the contact layer
//! alone; the recorder's share: the same run with every signal recorded each
//! cycle (as `biped simulate` does) and writing its CSV. Beside it, 0.2 s of `stand` on the
//! bundled G1 URDF without and with its 29 drive rotors (`Armature`, Harmonic Drive rotor
//! bodies), to show what the rotor sub-systems cost.

use biped_dynamics::{forward_dynamics, Algorithm, Data, Wrench};
use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::contact::ContactParams;
use biped_sim::contact::ContactSet;
use biped_sim::ode::{Method, OdeSystem};
use biped_sim::plant::{urdf_plant, Armature, Plant, PlantConfig, UrdfFeet};
use biped_sim::record::Recorder;
use biped_sim::scenario::{build, Scenario, ScenarioKind, ScenarioOptions};
use biped_sim::simulation::Signals;
use criterion::{criterion_group, criterion_main, BatchSize, Criterion};
use nalgebra::DVector;
use std::hint::black_box;

const SIM_TIME: f64 = 0.2;

fn setup() -> (Plant, Scenario) {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let opts = ScenarioOptions {
        duration: Some(SIM_TIME),
        ..ScenarioOptions::lola()
    };
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &opts).unwrap();
    (lp.plant, sc)
}

/// The G1 in its bent-knee pose on soft sole points, with a rotor of reflected inertia 0.01 kg
/// m^2 on every joint when `rotors`, and a 20 rad/s PD.
fn setup_g1(rotors: bool) -> (Plant, Scenario) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../dynamics/data/g1_29dof_rev_1_0.urdf");
    let mut feet = UrdfFeet::new("left_ankle_roll_link", "right_ankle_roll_link");
    (feet.center, feet.length, feet.width) =
        (nalgebra::Vector3::new(0.035, 0.0, -0.035), 0.17, 0.055);
    let config = PlantConfig {
        contact: ContactParams::light_feet(),
        ..PlantConfig::default()
    };
    let armature = rotors.then(|| Armature {
        pattern: "*".into(),
        inertia: 0.01,
        required: true,
    });
    let mut plant = urdf_plant(&path, &feet, armature.as_slice(), config).unwrap();
    let pose = ["left", "right"]
        .iter()
        .flat_map(|s| {
            [("hip_pitch", -0.2), ("knee", 0.4), ("ankle_pitch", -0.2)]
                .map(|(j, a)| (format!("{s}_{j}_joint"), a))
        })
        .collect();
    let opts = ScenarioOptions {
        duration: Some(SIM_TIME),
        bandwidth: 20.0,
        pose,
        ..ScenarioOptions::default()
    };
    let sc = build(ScenarioKind::Stand, &mut plant, &opts).unwrap();
    (plant, sc)
}

/// 0.2 s of `stand` on the G1 without and with drive rotors.
fn stand_g1(c: &mut Criterion) {
    let mut g = c.benchmark_group("stand_g1_urdf_rk4_1khz");
    g.sample_size(10);
    for (name, rotors) in [
        ("0.2 s simulated", false),
        ("0.2 s simulated, 29 rotors", true),
    ] {
        g.bench_function(name, |b| {
            b.iter_batched(
                || setup_g1(rotors),
                |(plant, sc)| black_box(sc.run(plant, Method::Rk4, &mut |_| Ok(())).unwrap().0),
                BatchSize::LargeInput,
            )
        });
    }
    g.finish();
}

fn stand(c: &mut Criterion) {
    let mut g = c.benchmark_group("stand_lola_type2_rk4_1khz");
    g.sample_size(10);
    g.bench_function("0.2 s simulated", |b| {
        b.iter_batched(
            setup,
            |(plant, sc)| black_box(sc.run(plant, Method::Rk4, &mut |_| Ok(())).unwrap().0),
            BatchSize::LargeInput,
        )
    });
    g.bench_function("0.2 s simulated, signals recorded", |b| {
        b.iter_batched(
            || recording(setup()),
            |(plant, sc, signals, rec)| black_box(recorded(plant, sc, signals, rec)),
            BatchSize::LargeInput,
        )
    });
    let (plant, sc, signals, rec) = recording(setup());
    let rec = recorded(plant, sc, signals, rec);
    let path = std::env::temp_dir().join(format!("biped_bench_{}.csv", std::process::id()));
    g.bench_function("CSV of 0.2 s recorded (201 rows)", |b| {
        b.iter(|| rec.write_csv(black_box(&path)).unwrap())
    });
    let _ = std::fs::remove_file(&path);
    g.finish();

    let (mut plant, sc) = setup();
    let z = sc.z0.clone();
    let l = plant.layout();
    // A second state (one joint speed moved) alternated with the first, so that no call finds
    // the kinematics pass of the previous one at its (q, v) (which it would reuse).
    let mut z2 = z.clone();
    z2[l.v().start + 7] += 1e-6;
    let states = [z.clone(), z2];
    let mut zdot = vec![0.0; z.len()];
    let mut g = c.benchmark_group("rhs_parts_lola_type2");
    let mut k = 0;
    g.bench_function("plant rhs", |b| {
        b.iter(|| {
            k ^= 1;
            plant.rhs(0.0, black_box(&states[k]), &mut zdot).unwrap()
        })
    });
    g.bench_function("plant rhs, kinematics pass reused (RK4 stage 1)", |b| {
        b.iter(|| plant.rhs(0.0, black_box(&z), &mut zdot).unwrap())
    });
    g.bench_function(
        "state pass: kinematics + contact + drives (Plant::state_outputs)",
        |b| {
            b.iter(|| {
                k ^= 1;
                plant.state_outputs(black_box(&states[k])).unwrap();
            })
        },
    );
    g.bench_function("contact + drives, no dynamics (Plant::outputs)", |b| {
        b.iter(|| {
            plant.outputs(black_box(&z)).unwrap();
        })
    });
    let qv = |z: &[f64]| {
        (
            DVector::from_column_slice(&z[l.q()]),
            DVector::from_column_slice(&z[l.v()]),
        )
    };
    let qvs = [qv(&states[0]), qv(&states[1])];
    let (q, v) = qvs[0].clone();
    let model = plant.model().clone();
    let mut data = Data::new(&model);
    let tau = DVector::zeros(model.nv());
    let fext = vec![Wrench::zero(); model.nbodies()];
    g.bench_function("forward dynamics O(n)", |b| {
        b.iter(|| {
            k ^= 1;
            let (q, v) = &qvs[k];
            forward_dynamics(&model, &mut data, q, v, &tau, Some(&fext), Algorithm::On).unwrap();
        })
    });
    let contact: ContactSet = plant.contact().clone();
    let mut out = contact.output();
    let mut fext = fext.clone();
    let mut sdot = vec![0.0; l.ncontact];
    g.bench_function("contact layer (16 points)", |b| {
        b.iter(|| {
            contact.evaluate(
                q.as_slice(),
                v.as_slice(),
                &z[l.contact()],
                &mut sdot,
                &mut fext,
                &mut out,
            )
        })
    });
    g.finish();
}

/// Set-up of a recorded run as `biped simulate` does it before its timed loop: every signal
/// (with CoM and `L_G`) registered and the recorder's buffer mapped ([`Recorder::prefault`]).
fn recording((plant, sc): (Plant, Scenario)) -> (Plant, Scenario, Signals, Recorder) {
    let mut signals = Signals::new(&plant, true);
    let mut rec = Recorder::with_capacity(256);
    signals.register(&mut rec).unwrap();
    rec.prefault();
    (plant, sc, signals, rec)
}

/// Runs the scenario recording every signal each cycle.
fn recorded(plant: Plant, sc: Scenario, mut signals: Signals, mut rec: Recorder) -> Recorder {
    sc.run(plant, Method::Rk4, &mut |f| signals.record(f, &mut rec))
        .unwrap();
    rec
}

criterion_group!(benches, stand, stand_g1);
criterion_main!(benches);
