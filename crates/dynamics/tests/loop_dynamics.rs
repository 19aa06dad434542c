//! O(n) with sub-systems against CRBA and sparse LTL, and RNEA as inverse, on random trees
//! with injected loops (drive-train leaves sharing coordinates, sections 2.6-2.9).

mod loop_support;

use biped_dynamics::{inverse_dynamics, Data, Model, NodeKind};
use loop_support::*;

/// Accelerations of the three methods agree and RNEA inverts them.
fn check_model(model: &Model, seed: u64) {
    let mut rng = rng(seed);
    let mut data = Data::new(model);
    for _ in 0..3 {
        let q = random_q(model, &mut rng);
        let v = random_vec(model.nv(), 2.0, &mut rng);
        let tau = random_vec(model.nv(), 5.0, &mut rng);
        let on = check_methods(seed, model, &mut data, &q, &v, &tau, None);
        let back = inverse_dynamics(model, &mut data, &q, &v, &on, None).unwrap();
        assert!(
            rel_diff(back, &tau) < 1e-9,
            "seed {seed}: RNEA(O(n)) {}",
            rel_diff(back, &tau)
        );
    }
}

#[test]
fn rotors_on_random_trees_all_methods_agree() {
    let mut with_subsystems = 0;
    for seed in 0..60 {
        let model = random_loop_model(seed, 4 + (seed as usize % 20), seed % 2 == 0, rotor);
        with_subsystems += usize::from(!model.subsystems().is_empty());
        check_model(&model, seed);
    }
    assert!(
        with_subsystems > 30,
        "only {with_subsystems} models had loops"
    );
}

/// Sub-system invariants: members share or connect coordinates, the parent is outside and an
/// ancestor of every member, the node list is parent-before-child with continuous brothers.
#[test]
fn generated_subsystems_are_well_formed() {
    for seed in 0..60 {
        let model = random_loop_model(seed, 4 + (seed as usize % 20), seed % 2 == 1, rotor);
        let bodies = model.bodies();
        let mut covered = vec![0; model.nbodies()];
        for s in model.subsystems() {
            for &m in s.members() {
                covered[m] += 1;
                let mut k = bodies[m].parent();
                while k != s.parent() {
                    let b = k.expect("parent must be an ancestor of every member");
                    assert!(
                        s.members().contains(&b),
                        "path body {b} outside the sub-system"
                    );
                    k = bodies[b].parent();
                }
            }
            assert!(s.parent().is_none_or(|p| !s.members().contains(&p)));
        }
        assert!(covered.iter().all(|&c| c <= 1));
        let nodes = model.nodes();
        for (k, node) in nodes.iter().enumerate() {
            if let Some(p) = node.parent {
                assert!(p < k);
            }
            // Children of a node: first_child then brothers, exactly those with parent k.
            let mut listed = Vec::new();
            let mut c = node.first_child;
            while let Some(ch) = c {
                listed.push(ch);
                c = nodes[ch].brother;
            }
            let expect: Vec<usize> = (0..nodes.len())
                .filter(|&j| nodes[j].parent == Some(k))
                .collect();
            assert_eq!(listed, expect);
            if let NodeKind::Subsystem(s) = node.kind {
                assert_eq!(
                    model.subsystems()[s].members()[0],
                    (0..model.nbodies())
                        .find(|&b| covered[b] == 1 && model.subsystems()[s].members().contains(&b))
                        .unwrap()
                );
            }
        }
        // Every body appears exactly once: as a node or as a sub-system member.
        let plain = nodes
            .iter()
            .filter(|n| matches!(n.kind, NodeKind::Body(_)))
            .count();
        let inside: usize = model.subsystems().iter().map(|s| s.members().len()).sum();
        assert_eq!(plain + inside, model.nbodies());
    }
}

/// Loop-free models are untouched: no sub-system, one body node per body with the body links.
#[test]
fn loop_free_models_are_untouched() {
    for seed in 0..30 {
        let model = random_loop_model(seed, 3 + seed as usize, seed % 2 == 0, |_, _| None);
        assert!(model.subsystems().is_empty());
        assert_eq!(model.nodes().len(), model.nbodies());
        for (i, (node, body)) in model.nodes().iter().zip(model.bodies()).enumerate() {
            assert_eq!(node.kind, NodeKind::Body(i));
            assert_eq!(node.parent, body.parent());
            assert_eq!(node.first_child, body.first_child());
            assert_eq!(node.brother, body.brother());
        }
        check_model(&model, seed);
    }
}
