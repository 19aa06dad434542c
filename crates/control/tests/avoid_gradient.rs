//! Collision gradient (5.4)-(5.9) on the Lola-like robot: central finite differences of the
//! cost H_C(q), descent from an overlapping arm-thigh pose, agreement of the active-pair
//! minimum with the exact all-pairs minimum, finiteness in deep overlaps, and errors.

use biped_control::avoidance::{AvoidanceError, AvoidanceParams, CollisionAvoidance, RepulsiveLaw};
use biped_control::ik::weight::Weight;
use biped_dynamics::{integrate, update_placements, Data, Jacobians};
use biped_robots::lola::{self, lola_collision_model, LolaModel, LolaType};
use nalgebra::DVector;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

struct Rig {
    lola: LolaModel,
    av: CollisionAvoidance,
    data: Data,
    jac: Jacobians,
}

impl Rig {
    fn new(law: RepulsiveLaw) -> Self {
        let lola = lola::build(LolaType::Type2).unwrap();
        let cm = lola_collision_model(&lola).unwrap().model;
        let av = CollisionAvoidance::new(&lola.model, cm, AvoidanceParams { law }).unwrap();
        let data = Data::new(&lola.model);
        let jac = Jacobians::new(&lola.model);
        Self {
            lola,
            av,
            data,
            jac,
        }
    }

    fn cost(&mut self, q: &DVector<f64>) -> f64 {
        update_placements(&self.lola.model, &mut self.data, q).unwrap();
        self.av.cost(&self.data).unwrap()
    }

    fn gradient(&mut self, q: &DVector<f64>) -> (DVector<f64>, usize) {
        let m = &self.lola.model;
        self.jac.compute(m, &mut self.data, q).unwrap();
        let mut g = DVector::zeros(m.nv());
        let s = self.av.gradient(m, &self.data, &self.jac, &mut g).unwrap();
        (g, s.active)
    }

    /// (pair, ssv_a, ssv_b) of every active pair and the smallest |c*| among them.
    fn active_set(&self) -> (Vec<(usize, usize, usize)>, f64) {
        let cm = self.av.collision_model();
        let mut set = Vec::new();
        let mut c_min = f64::INFINITY;
        for (k, r) in cm.results().iter().enumerate() {
            if let Some(c) = r.computed() {
                set.push((k, c.ssv_a, c.ssv_b));
                c_min = c_min.min(c.result.c_star().norm());
            }
        }
        (set, c_min)
    }

    fn random_q(&self, rng: &mut StdRng, joints: &dyn Fn(&str) -> bool) -> DVector<f64> {
        let mut q = self.lola.model.neutral();
        for l in self.lola.limits.iter().filter(|l| joints(&l.name)) {
            q[l.q_index] = rng.random_range(l.lower..l.upper);
        }
        q
    }
}

fn unit_direction(rng: &mut StdRng, n: usize) -> DVector<f64> {
    let v = DVector::from_fn(n, |_, _| rng.random_range(-1.0..1.0));
    v.normalize()
}

/// grad H_C . v equals the central difference of H_C along q (+) h v, for random unit v
/// (base included), at random poses with active pairs whose closest SSV pairs do not switch.
#[test]
fn gradient_matches_finite_differences() {
    for law in [
        RepulsiveLaw::Blended { s0: 1.0, t: 0.5 },
        RepulsiveLaw::Linear { m: -20.0 },
    ] {
        let mut rig = Rig::new(law);
        let mut rng = StdRng::seed_from_u64(11);
        let (nv, h) = (rig.lola.model.nv(), 1e-6);
        let (mut poses, mut checks) = (0, 0);
        for _ in 0..400 {
            let (q, _) = rig.lola.random_state(&mut |a, b| rng.random_range(a..b));
            let (grad, active) = rig.gradient(&q);
            assert!(grad.iter().all(|x| x.is_finite()));
            let (set, c_min) = rig.active_set();
            if active == 0 || c_min < 1e-3 {
                continue;
            }
            poses += 1;
            for _ in 0..4 {
                let v = unit_direction(&mut rng, nv);
                let qp = integrate(&rig.lola.model, &q, &v, h).unwrap();
                let qm = integrate(&rig.lola.model, &q, &v, -h).unwrap();
                let hp = rig.cost(&qp);
                let same_p = rig.active_set().0 == set;
                let hm = rig.cost(&qm);
                if !(same_p && rig.active_set().0 == set) {
                    continue;
                }
                let fd = (hp - hm) / (2.0 * h);
                let an = grad.dot(&v);
                assert!(
                    (fd - an).abs() <= 1e-6 * (1.0 + grad.norm()),
                    "{law:?}: fd {fd} vs {an}"
                );
                checks += 1;
            }
            if poses >= 25 {
                break;
            }
        }
        println!("{law:?}: {poses} poses, {checks} directions");
        assert!(
            poses >= 10 && checks >= 30,
            "only {poses} poses / {checks} checks"
        );
    }
}

/// A pose where the right forearm overlaps the right thigh (outer version) and that pair is
/// the closest of all.
fn overlapping_arm_thigh(rig: &mut Rig) -> DVector<f64> {
    let cm = rig.av.collision_model();
    let (arm, thigh) = (
        cm.segment_index("r_forearm").unwrap(),
        cm.segment_index("r_thigh_outer").unwrap(),
    );
    let pair = cm
        .pairs()
        .iter()
        .position(|p| (p.a, p.b) == (arm, thigh))
        .unwrap();
    let mut rng = StdRng::seed_from_u64(5);
    let joints = |n: &str| {
        n.starts_with("r_") && !n.contains("ankle") && !n.contains("foot") && !n.contains("toe")
    };
    for _ in 0..20000 {
        let q = rig.random_q(&mut rng, &joints);
        rig.cost(&q);
        if let Some((k, c)) = rig.av.global_minimum() {
            if k == pair && c.result.distance < -0.005 && c.result.c_star().norm() > 1e-3 {
                return q;
            }
        }
    }
    panic!("no overlapping arm-thigh pose found");
}

/// q <- q (+) (-eps W^-1 grad H_C) from an overlapping arm-thigh pose increases the exact
/// minimum distance over all pairs monotonically until the segments are separated.
#[test]
fn descent_separates_arm_and_thigh() {
    let mut rig = Rig::new(RepulsiveLaw::Blended { s0: 1.0, t: 0.5 });
    let mut q = overlapping_arm_thigh(&mut rig);
    let nv = rig.lola.model.nv();
    let weight = Weight::Diagonal(DVector::from_fn(nv, |i, _| 1.0 + 0.5 * (i % 3) as f64));
    let mut step = DVector::zeros(nv);
    rig.cost(&q);
    let start = rig.av.global_minimum().unwrap().1.result.distance;
    let mut last = start;
    for _ in 0..400 {
        let (grad, _) = rig.gradient(&q);
        weight.solve_into(&grad, &mut step).unwrap();
        q = integrate(&rig.lola.model, &q, &step, -2e-3).unwrap();
        rig.cost(&q);
        let d = rig.av.global_minimum().unwrap().1.result.distance;
        assert!(d >= last - 1e-9, "minimum distance fell from {last} to {d}");
        last = d;
    }
    println!("minimum distance {start} -> {last}");
    assert!(start < -0.005 && last > 0.0, "{start} -> {last}");
}

/// The summary's minimum over active pairs equals the exact all-pairs minimum whenever that
/// is below d_a (WithinActivation vs brute force), and deep overlaps give finite gradients.
#[test]
fn summary_matches_exact_minimum() {
    let mut rig = Rig::new(RepulsiveLaw::default());
    let mut rng = StdRng::seed_from_u64(3);
    let d_a = rig.av.activation_distance();
    let mut seen = 0;
    for _ in 0..200 {
        let (q, _) = rig.lola.random_state(&mut |a, b| rng.random_range(a..b));
        let m = &rig.lola.model;
        rig.jac.compute(m, &mut rig.data, &q).unwrap();
        let mut g = DVector::zeros(m.nv());
        let s = rig.av.gradient(m, &rig.data, &rig.jac, &mut g).unwrap();
        assert!(g.iter().all(|x| x.is_finite()));
        let (k, exact) = rig.av.global_minimum().unwrap();
        if exact.result.distance < d_a {
            assert_eq!(s.min_pair, Some(k));
            assert!((s.min_distance.unwrap() - exact.result.distance).abs() < 1e-12);
            seen += 1;
        } else {
            assert_eq!((s.active, s.min_distance), (0, None));
        }
    }
    assert!(seen > 20);
}

#[test]
fn errors_are_typed() {
    let mut rig = Rig::new(RepulsiveLaw::default());
    let m = &rig.lola.model;
    rig.jac.compute(m, &mut rig.data, &m.neutral()).unwrap();
    let mut short = DVector::zeros(m.nv() - 1);
    let e = rig
        .av
        .gradient(m, &rig.data, &rig.jac, &mut short)
        .unwrap_err();
    assert!(matches!(
        e,
        AvoidanceError::SizeMismatch {
            what: "gradient length",
            ..
        }
    ));

    let cm = biped_ssv::CollisionModel::new(vec!["nope".into()], 0.04).unwrap();
    let e = CollisionAvoidance::new(m, cm, AvoidanceParams::default()).unwrap_err();
    assert_eq!(e, AvoidanceError::UnknownBody("nope".into()));
    let cm = biped_ssv::CollisionModel::new(vec!["pelvis".into()], 0.0).unwrap();
    let e = CollisionAvoidance::new(m, cm, AvoidanceParams::default()).unwrap_err();
    assert_eq!(e, AvoidanceError::BadActivationDistance(0.0));
    let law = RepulsiveLaw::Quadratic { s: -1.0 };
    let cm = lola_collision_model(&rig.lola).unwrap().model;
    let e = CollisionAvoidance::new(m, cm, AvoidanceParams { law }).unwrap_err();
    assert_eq!(e, AvoidanceError::BadLaw(law));
}
