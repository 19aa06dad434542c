//! End-to-end tests of `--lola type2|type3` in `biped model`, `biped dynamics` and
//! `biped bench dynamics`.

mod common;

use biped_robots::lola::{self, LolaType};
use common::{answers, floats, json_lines, run};
use rand::{Rng, SeedableRng};
use serde_json::{json, Value};

/// Largest |a - b| relative to max(1, max |b|).
fn rel(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    let scale = b.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
        / scale
}

#[test]
fn model_json_has_subsystems() {
    let mut counts = Vec::new();
    for (kind, nv) in [("type2", 31), ("type3", 47)] {
        let out = run(&["model", "--lola", kind, "--json"], "");
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let m = json_lines(&out).remove(0);
        assert_eq!(m["nv"].as_u64(), Some(nv));
        assert_eq!(m["nq"].as_u64(), Some(nv + 1));
        assert_eq!(m["joints"][0]["name"], "root");
        let bodies: Vec<&str> = m["bodies"]
            .as_array()
            .unwrap()
            .iter()
            .map(|b| b.as_str().unwrap())
            .collect();
        let subs = m["subsystems"].as_array().unwrap();
        for s in subs {
            let members = s.as_array().unwrap();
            assert!(members.len() >= 2, "a sub-system groups a loop: {s}");
            assert!(members
                .iter()
                .all(|b| bodies.contains(&b.as_str().unwrap())));
        }
        counts.push(subs.len());
    }
    assert!(
        counts[0] > counts[1],
        "Type 3 has fewer sub-systems: {counts:?}"
    );
    let dill = json_lines(&run(&["model", "--dill", "2", "--json"], "")).remove(0);
    assert_eq!(dill["subsystems"], json!([]));
}

#[test]
fn dynamics_algorithms_agree_and_invert() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(5);
    for (kind, t) in [("type2", LolaType::Type2), ("type3", LolaType::Type3)] {
        let lm = lola::build(t).unwrap();
        let states: Vec<_> = (0..4)
            .map(|_| {
                let (q, v) = lm.random_state(&mut |a, b| rng.random_range(a..b));
                let tau: Vec<f64> = (0..lm.model.nv())
                    .map(|_| rng.random_range(-10.0..10.0))
                    .collect();
                (q.as_slice().to_vec(), v.as_slice().to_vec(), tau)
            })
            .collect();
        let fwd: Vec<Value> = states
            .iter()
            .map(|(q, v, tau)| json!({"q": q, "v": v, "tau": tau}))
            .collect();
        let base = ["dynamics", "--lola", kind];
        let on = answers(&[&base[..], &["--algorithm", "on"]].concat(), &fwd, "qdd");
        for algo in ["crba", "sparse"] {
            let other = answers(&[&base[..], &["--algorithm", algo]].concat(), &fwd, "qdd");
            for (a, b) in on.iter().zip(&other) {
                assert!(rel(a, b) < 1e-10, "{kind} on vs {algo}: {}", rel(a, b));
            }
        }
        let inv: Vec<Value> = states
            .iter()
            .zip(&on)
            .map(|((q, v, _), a)| json!({"q": q, "v": v, "a": a}))
            .collect();
        let tau = answers(&[&base[..], &["--inverse"]].concat(), &inv, "tau");
        for ((_, _, tau_in), tau_out) in states.iter().zip(&tau) {
            assert!(rel(tau_out, tau_in) < 1e-10, "{kind} RNEA round trip");
        }
        // M a = tau(a) - tau(0): the mass matrix is the linear part of inverse dynamics.
        let mm: Vec<Value> = states.iter().map(|(q, _, _)| json!({"q": q})).collect();
        let out = run(
            &[&base[..], &["--mass-matrix"]].concat(),
            &mm.iter().map(|r| format!("{r}\n")).collect::<String>(),
        );
        let zero: Vec<Value> = states
            .iter()
            .map(|(q, v, _)| json!({"q": q, "v": v, "a": vec![0.0; v.len()]}))
            .collect();
        let bias = answers(&[&base[..], &["--inverse"]].concat(), &zero, "tau");
        for (((m, a), t), h) in json_lines(&out).iter().zip(&on).zip(&tau).zip(&bias) {
            let rows: Vec<Vec<f64>> = m["M"].as_array().unwrap().iter().map(floats).collect();
            let ma: Vec<f64> = rows
                .iter()
                .map(|r| r.iter().zip(a).map(|(x, y)| x * y).sum())
                .collect();
            let diff: Vec<f64> = t.iter().zip(h).map(|(x, y)| x - y).collect();
            assert!(
                rel(&ma, &diff) < 1e-9,
                "{kind}: M a vs RNEA {}",
                rel(&ma, &diff)
            );
        }
    }
}

#[test]
fn bench_reports_relative_run_times() {
    let out = run(&["bench", "dynamics", "--lola", "type3", "--json"], "");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let t = json_lines(&out).remove(0);
    assert_eq!(t["nv"].as_u64(), Some(47));
    for key in [
        "on",
        "crba",
        "sparse",
        "fw1",
        "bw",
        "fw2",
        "eta_crba",
        "eta_sparse",
    ] {
        assert!(t[key].as_f64().is_some_and(|x| x > 0.0), "{key}: {t}");
    }
    let eta = t["eta_crba"].as_f64().unwrap();
    assert!((eta - t["crba"].as_f64().unwrap() / t["on"].as_f64().unwrap()).abs() < 1e-12 * eta);
    let text = run(&["bench", "dynamics", "--lola", "type2"], "");
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(
        text.contains("eta(O(n^3))") && text.contains("sub-systems"),
        "{text}"
    );
}

#[test]
fn bad_lola_type_is_a_usage_error() {
    let out = run(&["model", "--lola", "type9"], "");
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("type9"));
}
