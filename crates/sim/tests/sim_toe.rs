//! Toe contact points of the Lola plant (`PlantConfig::toe_contacts`) and the side wrenches
//! (`ContactOutput::sides`, `FootWrench::with_part`): where the toe points are, that a
//! standing robot's toes carry load, and that a side's wrench is the direct sum of its points'
//! forces and moments.

mod common;

use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::contact::{sole_rectangle, FootSpec, FootWrench};
use biped_sim::ode::{Method, OdeSystem};
use biped_sim::plant::{Plant, PlantConfig};
use biped_sim::scenario::{build, ScenarioKind, ScenarioOptions};
use nalgebra::{DVector, Vector3};
use rand::{Rng, SeedableRng};

/// Entries of the default Lola plant: the two feet, then their toes, each a part of its foot.
#[test]
fn the_toes_are_entries_of_their_own_and_parts_of_their_feet() {
    let plant = lola_plant(LolaType::Type2, PlantConfig::default())
        .unwrap()
        .plant;
    let c = plant.contact();
    let specs: Vec<_> = c.specs().cloned().collect();
    let got: Vec<_> = specs
        .iter()
        .map(|s| (s.name.as_str(), s.body.as_str(), s.part_of.as_deref()))
        .collect();
    assert_eq!(
        got,
        [
            ("left", "l_foot", None),
            ("right", "r_foot", None),
            ("left_toe", "l_toe", Some("left")),
            ("right_toe", "r_toe", Some("right")),
        ]
    );
    assert_eq!(c.side_names().collect::<Vec<_>>(), ["left", "right"]);
    assert_eq!(c.side_entries(0), [0, 2]);
    assert_eq!(c.side_entries(1), [1, 3]);
    assert_eq!(
        (c.side_index("right"), c.side_index("left_toe")),
        (Some(1), None)
    );
    assert_eq!(c.npoints(), 2 * 5 + 2 * 8);
    let off = PlantConfig {
        toe_contacts: false,
        ..PlantConfig::default()
    };
    let plant = lola_plant(LolaType::Type2, off).unwrap().plant;
    // Without toes: the 16 sole points of Table 2.3, 32 bristle states.
    assert_eq!(plant.layout().table_2_3(), [31, 32, 0, 95]);
    assert_eq!(plant.contact().nsides(), 2);
}

/// At the neutral pose the toe points lie on the toe box's sole rectangle at the height of the
/// foot's sole; the toe joint line (the sole's front edge) is the toe's, the foot keeps the
/// rest of its rectangle. Expected from the parameter file (`l_toe` origin [0.13, 0, -0.07] in
/// the foot frame, box 0.06 x 0.12 with its CoM 0.03 ahead of the joint, `l_foot` box 0.22 long
/// with its CoM at x = 0.02, `l_sole` at z = -0.09): toe points at foot-frame x in
/// {0.13, 0.16, 0.19}, foot points at x in {-0.09, 0.02}.
#[test]
fn toe_points_are_flat_with_the_sole_at_the_neutral_pose() {
    let mut plant = lola_plant(LolaType::Type2, PlantConfig::default())
        .unwrap()
        .plant;
    let q = plant.model().neutral();
    let z = plant
        .initial_state(&q, &DVector::zeros(plant.layout().nv))
        .unwrap();
    let out = plant.outputs(&z).unwrap().contact.clone();
    let specs: Vec<_> = plant.contact().specs().cloned().collect();
    let world = |k: usize| -> Vec<Vector3<f64>> {
        let st = out.foot_states[k];
        specs[k].points.iter().map(|c| st.point(c).0).collect()
    };
    for (foot, toe) in [(0, 2), (1, 3)] {
        let (sole, toes) = (world(foot), world(toe));
        let st = out.foot_states[foot];
        // Foot-frame coordinates (the frames are parallel to the world at the neutral pose).
        let mut local: Vec<[f64; 3]> = toes
            .iter()
            .map(|p| {
                let l = st.rot.transpose() * (p - st.pos);
                [l.x, l.y, l.z].map(|x| (x * 1e6).round() / 1e6)
            })
            .collect();
        local.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let expected = [
            [0.13, -0.06, -0.09],
            [0.13, 0.0, -0.09],
            [0.13, 0.06, -0.09],
            [0.16, -0.06, -0.09],
            [0.16, 0.06, -0.09],
            [0.19, -0.06, -0.09],
            [0.19, 0.0, -0.09],
            [0.19, 0.06, -0.09],
        ];
        assert_eq!(local, expected, "entry {toe}");
        let mut xs: Vec<f64> = sole
            .iter()
            .map(|p| ((st.rot.transpose() * (p - st.pos)).x * 1e6).round() / 1e6)
            .collect();
        xs.sort_by(f64::total_cmp);
        assert_eq!(xs, [-0.09, -0.09, -0.09, 0.02, 0.02], "entry {foot}");
        let sole_z = sole[0].z;
        assert!(sole
            .iter()
            .chain(&toes)
            .all(|p| (p.z - sole_z).abs() < 1e-12));
        for p in &toes {
            assert!(
                sole.iter().all(|s| (s - p).norm() > 0.01),
                "{p} on the sole"
            );
        }
    }
}

/// A standing robot rests on sole and toes: each toe carries a share of the weight, and the
/// entries, the sides and the F/T sensors all sum to it.
#[test]
fn a_standing_robot_carries_load_on_its_toes() {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default()).unwrap();
    let opts = ScenarioOptions {
        duration: Some(0.5),
        ..ScenarioOptions::lola()
    };
    let sc = build(ScenarioKind::Stand, &mut lp.plant, &opts).unwrap();
    let (s, sim) = sc.run(lp.plant, Method::Rk4, &mut |_| Ok(())).unwrap();
    let out = &sim.plant().last_outputs().contact;
    for toe in [2, 3] {
        let w = &out.feet[toe];
        assert!(w.force.z > 0.02 * s.weight, "toe {toe}: {w:?}");
        assert_eq!(w.points_in_contact, 8, "toe {toe}");
    }
    let entries: f64 = out.feet.iter().map(|w| w.force.z).sum();
    let sides: f64 = out.sides.iter().map(|w| w.force.z).sum();
    assert!((entries - s.weight).abs() < 1e-3 * s.weight, "{entries}");
    assert!((sides - entries).abs() < 1e-9 * entries);
    let ft = &sim.sensors().foot_wrenches;
    assert_eq!(ft.len(), 4);
    assert!(ft[2].lin.z > 0.02 * s.weight && ft[3].lin.z > 0.02 * s.weight);
}

/// A state of the default plant where both entries of some side touch the ground.
fn state_touching_foot_and_toe(plant: &mut Plant) -> Vec<f64> {
    let lola = biped_robots::lola::build(LolaType::Type2).unwrap();
    for seed in 0..200 {
        let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
        let (mut q, mut v) = lola.random_state(&mut |a, b| rng.random_range(a..b));
        v *= 0.2;
        q[2] -= plant.contact().lowest_point(q.as_slice(), v.len()) + 3e-3;
        let z = plant.initial_state(&q, &v).unwrap();
        let out = &plant.outputs(&z).unwrap().contact;
        let touching = |k: usize| out.feet[k].points_in_contact > 0;
        if (touching(0) && touching(2)) || (touching(1) && touching(3)) {
            return z;
        }
    }
    panic!("no random state touches foot and toe");
}

/// Each side's wrench equals the direct sum over the points of its foot and toe: force
/// `sum f_j`, moment `sum (p_j - r_ref) x f_j` about the foot's sole reference point, centre
/// of pressure `sum p_j f_jz / sum f_jz`; also with bristle deflections (tangential forces).
#[test]
fn side_wrench_is_the_direct_sum_of_its_point_forces() {
    let mut plant = lola_plant(LolaType::Type2, PlantConfig::default())
        .unwrap()
        .plant;
    let mut z = state_touching_foot_and_toe(&mut plant);
    let mut rng = rand::rngs::StdRng::seed_from_u64(11);
    for x in &mut z[plant.layout().contact()] {
        *x = rng.random_range(-2e-4..2e-4);
    }
    let mut zdot = vec![0.0; z.len()];
    plant.rhs(0.0, &z, &mut zdot).unwrap();
    let out = plant.last_outputs().contact.clone();
    let c = plant.contact();
    let specs: Vec<_> = c.specs().cloned().collect();
    let first: Vec<usize> = specs
        .iter()
        .scan(0, |n, s| {
            let f = *n;
            *n += s.points.len();
            Some(f)
        })
        .collect();
    for side in 0..c.nsides() {
        let entries = c.side_entries(side);
        let foot = entries[0];
        let r_ref = out.foot_states[foot].point(&specs[foot].reference).0;
        let (mut f, mut m, mut cop, mut fz) =
            (Vector3::zeros(), Vector3::zeros(), Vector3::zeros(), 0.0);
        for &e in entries {
            for (j, c) in specs[e].points.iter().enumerate() {
                let p = out.foot_states[e].point(c).0;
                let fj = out.point_forces[first[e] + j];
                f += fj;
                m += (p - r_ref).cross(&fj);
                if fj.z > 0.0 {
                    cop += Vector3::new(p.x, p.y, 0.0) * fj.z;
                    fz += fj.z;
                }
            }
        }
        let w = &out.sides[side];
        let tol = 1e-9 * (1.0 + f.norm());
        assert!(
            (w.force - f).norm() < tol,
            "side {side}: {} vs {f}",
            w.force
        );
        assert!(
            (w.torque - m).norm() < tol,
            "side {side}: {} vs {m}",
            w.torque
        );
        assert!((w.reference - r_ref).norm() < 1e-12);
        match w.cop {
            Some(p) => assert!((p - cop / fz).norm() < 1e-9, "{p} vs {}", cop / fz),
            None => assert_eq!(fz, 0.0),
        }
        let points: usize = entries.iter().map(|&e| out.feet[e].points_in_contact).sum();
        assert_eq!(w.points_in_contact, points);
    }
}

/// `with_part` on hand-computed numbers: `M = M_a + M_b + (r_b - r_a) x F_b`, centre of
/// pressure weighted by the normal forces, a part without contact leaves the foot's.
#[test]
fn with_part_shifts_the_part_moment_to_the_foot_reference() {
    let foot = FootWrench {
        force: Vector3::new(0.0, 0.0, 10.0),
        torque: Vector3::new(1.0, 2.0, 3.0),
        reference: Vector3::zeros(),
        cop: Some(Vector3::new(0.1, 0.0, 0.0)),
        points_in_contact: 2,
    };
    let toe = FootWrench {
        force: Vector3::new(1.0, 2.0, 5.0),
        torque: Vector3::new(0.0, 0.0, 1.0),
        reference: Vector3::new(0.2, 0.0, 0.0),
        cop: Some(Vector3::new(0.3, 0.0, 0.0)),
        points_in_contact: 3,
    };
    let s = foot.with_part(&toe);
    // (0.2, 0, 0) x (1, 2, 5) = (0, -1, 0.4)
    assert!((s.torque - Vector3::new(1.0, 1.0, 4.4)).norm() < 1e-15);
    assert_eq!(s.force, Vector3::new(1.0, 2.0, 15.0));
    assert_eq!(s.reference, foot.reference);
    assert!((s.cop.unwrap() - Vector3::new(2.5 / 15.0, 0.0, 0.0)).norm() < 1e-15);
    assert_eq!(s.points_in_contact, 5);
    let lifted = FootWrench {
        cop: None,
        force: Vector3::zeros(),
        points_in_contact: 0,
        ..toe
    };
    let s = foot.with_part(&lifted);
    assert_eq!(s.cop, foot.cop);
    assert_eq!(s.force, foot.force);
    let s = lifted.with_part(&foot);
    assert_eq!(s.cop, foot.cop);
}

/// `part_of` must name a foot entry: an unknown name or another part is a typed error.
#[test]
fn a_part_of_an_unknown_foot_is_rejected() {
    let spec = |name: &str, part_of: Option<&str>| FootSpec {
        name: name.into(),
        body: "box".into(),
        points: sole_rectangle(Vector3::new(0.0, 0.0, -0.05), 0.2, 0.1),
        reference: Vector3::new(0.0, 0.0, -0.05),
        part_of: part_of.map(String::from),
    };
    let model = || common::free_box(5.0, [0.3, 0.2, 0.1]);
    let build = |feet: &[FootSpec]| {
        Plant::new(model(), vec![], feet, vec![], PlantConfig::default()).map(|_| ())
    };
    assert!(build(&[spec("sole", None), spec("tip", Some("sole"))]).is_ok());
    for feet in [
        vec![spec("sole", None), spec("tip", Some("heel"))],
        vec![
            spec("sole", None),
            spec("tip", Some("sole")),
            spec("nail", Some("tip")),
        ],
        vec![spec("tip", Some("tip"))],
    ] {
        let e = build(&feet).unwrap_err().to_string();
        assert!(e.contains("part_of"), "{e}");
    }
}
