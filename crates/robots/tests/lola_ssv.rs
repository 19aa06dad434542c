//! The shipped SSV collision model of the Lola-like robot (`data/lola_ssv.toml`): body binding,
//! clearance at the neutral pose, mirror symmetry, pair structure and located file errors.

use biped_dynamics::{update_placements, Data};
use biped_robots::lola::collision::{collision_model_from_str, LOLA_SSV_TOML};
use biped_robots::lola::{self, lola_collision_model, LolaCollisionError, LolaModel, LolaType};
use biped_ssv::format::FormatErrorKind;
use biped_ssv::segment::closest_ssv_pair;
use biped_ssv::CollisionModel;
use nalgebra::DVector;
use rand::{Rng, SeedableRng};

/// Exact distance of every pair at configuration `q` (brute force over the pruned search).
fn pair_distances(
    lola: &LolaModel,
    cm: &mut CollisionModel,
    bodies: &[usize],
    q: &DVector<f64>,
) -> Vec<f64> {
    let mut data = Data::new(&lola.model);
    update_placements(&lola.model, &mut data, q).unwrap();
    let poses: Vec<_> = bodies.iter().map(|&b| data.body_pose(b)).collect();
    cm.set_poses(&poses).unwrap();
    let s = cm.segments();
    cm.pairs()
        .iter()
        .map(|p| closest_ssv_pair(&s[p.a], &s[p.b]).result.distance)
        .collect()
}

fn pair_name(cm: &CollisionModel, k: usize) -> String {
    let p = cm.pairs()[k];
    format!(
        "{} - {}",
        cm.segments()[p.a].name(),
        cm.segments()[p.b].name()
    )
}

#[test]
fn binds_every_body_for_both_model_types() {
    for variant in [LolaType::Type2, LolaType::Type3] {
        let lola = lola::build(variant).unwrap();
        let c = lola_collision_model(&lola).unwrap();
        assert_eq!(c.model_bodies.len(), c.model.bodies().len());
        for (name, &id) in c.model.bodies().iter().zip(&c.model_bodies) {
            assert_eq!(lola.model.bodies()[id].name(), name);
        }
        assert!(c.model.pairs().len() >= 20);
        assert!(c.model.activation_distance() > 0.0);
    }
}

#[test]
fn neutral_pose_has_clearance_in_every_pair() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let mut c = lola_collision_model(&lola).unwrap();
    let q = lola.model.neutral();
    let d = pair_distances(&lola, &mut c.model, &c.model_bodies, &q);
    for (k, d) in d.iter().enumerate() {
        println!("{:40} {:.4}", pair_name(&c.model, k), d);
        assert!(
            *d > c.model.activation_distance(),
            "{} is active or overlaps at the neutral pose: {d}",
            pair_name(&c.model, k)
        );
    }
}

/// Left segments are mirror images of the right ones and the Lola model is mirror symmetric,
/// so at the neutral pose a right pair and its left counterpart are equally far apart.
#[test]
fn left_and_right_pairs_mirror_each_other() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let mut c = lola_collision_model(&lola).unwrap();
    let d = pair_distances(&lola, &mut c.model, &c.model_bodies, &lola.model.neutral());
    let swap = |n: &str| n.replace("r_", "#").replace("l_", "r_").replace('#', "l_");
    let mut checked = 0;
    for k in 0..d.len() {
        let name = pair_name(&c.model, k);
        let (a, b) = name.split_once(" - ").unwrap();
        let (ma, mb) = (swap(a), swap(b));
        let twin = (0..d.len()).find(|&j| {
            let n = pair_name(&c.model, j);
            n == format!("{ma} - {mb}") || n == format!("{mb} - {ma}")
        });
        if let Some(j) = twin {
            assert!((d[k] - d[j]).abs() < 1e-12, "{name}: {} vs {}", d[k], d[j]);
            checked += 1;
        }
    }
    assert!(checked >= 20, "only {checked} mirrored pairs");
}

/// Pairs never join a body with its joint parent (adjacent bodies touch by construction).
#[test]
fn no_pair_joins_joint_neighbours() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let c = lola_collision_model(&lola).unwrap();
    let m = &c.model;
    for (k, p) in m.pairs().iter().enumerate() {
        let ba = c.model_bodies[m.segment_bodies()[p.a]];
        let bb = c.model_bodies[m.segment_bodies()[p.b]];
        assert_ne!(ba, bb);
        let bodies = lola.model.bodies();
        assert_ne!(bodies[ba].parent(), Some(bb), "{}", pair_name(m, k));
        assert_ne!(bodies[bb].parent(), Some(ba), "{}", pair_name(m, k));
    }
}

/// Small random postures about the neutral pose (+-0.02 rad per joint) stay collision free,
/// while full-range random postures do produce genuine collisions in arm-leg and leg-leg pairs.
#[test]
fn random_postures() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let mut c = lola_collision_model(&lola).unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    for _ in 0..50 {
        let mut q = lola.model.neutral();
        for l in &lola.limits {
            q[l.q_index] = rng.random_range(-0.02..0.02);
        }
        let d = pair_distances(&lola, &mut c.model, &c.model_bodies, &q);
        for (k, d) in d.iter().enumerate() {
            assert!(*d > 0.0, "{} overlaps: {d}", pair_name(&c.model, k));
        }
    }
    let mut hit = vec![false; c.model.pairs().len()];
    for _ in 0..1500 {
        let mut q = lola.model.neutral();
        for l in &lola.limits {
            q[l.q_index] = rng.random_range(l.lower..l.upper);
        }
        let d = pair_distances(&lola, &mut c.model, &c.model_bodies, &q);
        for (k, d) in d.iter().enumerate() {
            assert!(d.is_finite());
            hit[k] |= *d < 0.0;
        }
    }
    let names: Vec<_> = (0..hit.len())
        .filter(|&k| hit[k])
        .map(|k| pair_name(&c.model, k))
        .collect();
    println!("pairs colliding in full-range postures: {names:?}");
    assert!(names
        .iter()
        .any(|n| n.contains("forearm") && n.contains("thigh")));
    assert!(names
        .iter()
        .any(|n| n.contains("thigh_inner") && n.contains("l_")));
}

#[test]
fn unknown_body_names_the_segment_and_line() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let text = LOLA_SSV_TOML
        .replace("\"r_thigh\", \"r_shank\",", "\"r_thigh\", \"r_shin\",")
        .replace(
            "name = \"r_shank\"\nbody = \"r_shank\"",
            "name = \"r_shank\"\nbody = \"r_shin\"",
        );
    let err = collision_model_from_str(&text, "x.toml", &lola).unwrap_err();
    let line = 1 + text.lines().position(|l| l == "body = \"r_shin\"").unwrap();
    match &err {
        LolaCollisionError::UnknownBody {
            file,
            line: l,
            segment,
            body,
        } => {
            assert_eq!(
                (file.as_str(), *l, segment.as_str(), body.as_str()),
                ("x.toml", line, "r_shank", "r_shin")
            );
        }
        e => panic!("unexpected {e:?}"),
    }
    assert!(err
        .to_string()
        .contains(&format!("x.toml:{line}: segment `r_shank`")));
}

#[test]
fn format_errors_are_located() {
    let lola = lola::build(LolaType::Type2).unwrap();
    let bad = "{ point = [0.0, 0.0, -0.42], radius = -0.055 },";
    let text = LOLA_SSV_TOML.replace("{ point = [0.0, 0.0, -0.42], radius = 0.055 },", bad);
    let line = 1 + text.lines().position(|l| l.contains(bad)).unwrap();
    match collision_model_from_str(&text, "y.toml", &lola).unwrap_err() {
        LolaCollisionError::Format(e) => {
            assert_eq!((e.file.as_str(), e.line), ("y.toml", line));
            assert!(e.field.ends_with("ssvs[3].radius"), "{}", e.field);
            assert!(matches!(e.kind, FormatErrorKind::Ssv(_)));
        }
        e => panic!("unexpected {e:?}"),
    }
    let text = LOLA_SSV_TOML.replace("keep = [0, 2]", "keep = [0, 9]");
    let line = 1 + text.lines().position(|l| l == "keep = [0, 9]").unwrap();
    match collision_model_from_str(&text, "z.toml", &lola).unwrap_err() {
        LolaCollisionError::Format(e) => assert_eq!(e.line, line, "{e}"),
        e => panic!("unexpected {e:?}"),
    }
}
