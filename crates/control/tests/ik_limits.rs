//! Hard joint limits of the differential IK (SNS, `ik::saturation`): the velocity box of
//! `ik::limits`, random RMRC problems kept inside it (diagonal and rank-one weights), tasks
//! still met exactly while free joints remain, and a closed loop on a planar chain asked for an
//! unreachable target that never leaves its joint ranges.

use biped_control::ik::{
    ClosedLoopIk, CycleInput, JointLimits, JointRange, LimitSettings, Rmrc, RmrcProblem,
    SaturatedRmrc, TaskMap, Weight,
};
use biped_control::IkError;
use nalgebra::{DMatrix, DVector, Vector2};
use proptest::prelude::*;
use rand::{Rng, SeedableRng};

fn ranges(n: usize, lo: f64, hi: f64) -> Vec<JointRange> {
    (0..n)
        .map(|i| JointRange {
            q_index: i,
            v_index: i,
            lower: lo,
            upper: hi,
        })
        .collect()
}

#[test]
fn velocity_box_brakes_before_the_bound_and_recovers_beyond_it() {
    let s = LimitSettings::default();
    let limits = JointLimits::new(ranges(4, -1.0, 1.0), s).unwrap();
    let q = DVector::from_vec(vec![0.0, 1.0 - s.margin - 1e-2, 1.0 - s.margin, 1.2]);
    let (mut lo, mut hi) = (DVector::zeros(4), DVector::zeros(4));
    limits.velocity_box(&q, 1e-3, &mut lo, &mut hi);
    assert_eq!((lo[0], hi[0]), (-s.max_velocity, s.max_velocity));
    // 1 cm left: the discrete braking curve (sqrt(a^2 dt^2 + 8 a d) - a dt) / 2, below both
    // the velocity limit and the no-overshoot speed d / dt
    let (a, dt) = (s.max_deceleration, 1e-3);
    let vb = 0.5 * ((a * a * dt * dt + 8.0 * a * 1e-2).sqrt() - a * dt);
    assert!(vb < s.max_velocity && vb < 1e-2 / dt);
    assert!((hi[1] - vb).abs() < 1e-12, "{} vs {vb}", hi[1]);
    assert_eq!(lo[1], -s.max_velocity);
    assert_eq!(hi[2], 0.0);
    // beyond the range: must move back
    assert!(hi[3] < 0.0 && lo[3] <= hi[3]);
    assert!(
        JointLimits::new(ranges(1, 0.0, 0.01), s).is_err(),
        "range < 2 margin"
    );
    let bad = LimitSettings {
        max_velocity: 0.0,
        ..s
    };
    assert!(JointLimits::new(ranges(1, -1.0, 1.0), bad).is_err());
}

#[test]
fn joint_driven_at_full_speed_brakes_within_the_deceleration_and_stops_on_the_bound() {
    let s = LimitSettings::default();
    let limits = JointLimits::new(ranges(1, -1.0, 1.0), s).unwrap();
    let (mut lo, mut hi) = (DVector::zeros(1), DVector::zeros(1));
    let (mut q, dt) = (DVector::from_element(1, 0.0), 1e-3);
    let mut v_prev = 0.0;
    for k in 0..2000 {
        limits.velocity_box(&q, dt, &mut lo, &mut hi);
        let v = (2.0 * s.max_velocity).clamp(lo[0], hi[0]);
        if k > 0 && v < v_prev {
            assert!(
                v_prev - v <= 2.0 * s.max_deceleration * dt,
                "k {k}: {v_prev} -> {v}"
            );
        }
        q[0] += v * dt;
        assert!(q[0] <= 1.0 - s.margin + 1e-12, "k {k}: {}", q[0]);
        v_prev = v;
    }
    assert!((q[0] - (1.0 - s.margin)).abs() < 1e-6, "{}", q[0]);
}

/// A random `m x n` problem with `q` near the limits of some joints.
fn problem(
    seed: u64,
    m: usize,
    n: usize,
) -> (DMatrix<f64>, DVector<f64>, DVector<f64>, DVector<f64>) {
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let j = DMatrix::from_fn(m, n, |_, _| rng.random_range(-1.0..1.0));
    let xd = DVector::from_fn(m, |_, _| rng.random_range(-3.0..3.0));
    let q = DVector::from_fn(n, |_, _| rng.random_range(-1.0..1.0));
    let g = DVector::from_fn(n, |_, _| rng.random_range(-1.0..1.0));
    (j, xd, q, g)
}

fn check_inside(s: &SaturatedRmrc, qd: &DVector<f64>) {
    let (lo, hi) = s.velocity_box();
    for i in 0..qd.len() {
        assert!(
            qd[i] >= lo[i] - 1e-9 && qd[i] <= hi[i] + 1e-9,
            "joint {i}: {} not in [{}, {}]",
            qd[i],
            lo[i],
            hi[i]
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Any problem: the solution stays in the box; with free joints to spare the tasks hold.
    #[test]
    fn saturated_solutions_stay_in_the_box(seed in 0u64..10_000, rank_one in any::<bool>(), vmax in 0.5f64..5.0) {
        let (m, n) = (6, 12);
        let (j, xd, q, g) = problem(seed, m, n);
        // undamped: with rank to spare the remaining joints meet the tasks exactly
        let settings = LimitSettings { max_velocity: vmax, regularisation: 0.0, ..LimitSettings::default() };
        let limits = JointLimits::new(ranges(n, -1.0, 1.0), settings).unwrap();
        let mut w = Weight::rank_one(n, 0.1).unwrap();
        if rank_one {
            let u: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
            w.set_rank_one(0.1, &u).unwrap();
        } else {
            w = Weight::Diagonal(DVector::from_fn(n, |i, _| 1.0 + 0.1 * i as f64));
        }
        let p = RmrcProblem { null_space: Some((&g, 0.5)), ..RmrcProblem::new(&j, m, &xd, &w) };
        let mut s = SaturatedRmrc::new(m, n, limits).unwrap();
        let mut qd = DVector::zeros(n);
        let report = s.solve(&p, &q, 1e-3, &mut qd).unwrap();
        check_inside(&s, &qd);
        if report.clamped == 0 && report.fixed + m < n {
            // rank kept (random J): the tasks still hold
            let r = &j * &qd - &xd;
            prop_assert!(r.amax() < 1e-6 * (1.0 + xd.amax()), "task residual {}", r.amax());
        }
        // without active limits the solve is plain RMRC (4.12) (undamped up to the 1e-12 floor)
        if report.fixed == 0 {
            let mut plain = DVector::zeros(n);
            Rmrc::new(m, n).solve(&p, &mut plain).unwrap();
            prop_assert!((&plain - &qd).amax() < 1e-9 * (1.0 + plain.amax()));
        }
    }
}

#[test]
fn fixed_joints_match_the_dense_restricted_problem() {
    // joint 0 at the bound it moves towards: it is held; the restricted problem of the
    // module docs, solved densely, gives the same velocities
    let (m, n) = (3, 6);
    let (j, _, _, g) = problem(5, m, n);
    let xd = DVector::from_fn(m, |i, _| [5.0, -2.0, 1.0][i]);
    let u: Vec<f64> = (0..n).map(|i| 0.3 + 0.2 * i as f64).collect();
    let mut w = Weight::rank_one(n, 0.2).unwrap();
    w.set_rank_one(0.2, &u).unwrap();
    let mut free_qd = DVector::zeros(n);
    let p0 = RmrcProblem {
        null_space: Some((&g, 0.3)),
        ..RmrcProblem::new(&j, m, &xd, &w)
    };
    Rmrc::new(m, n).solve(&p0, &mut free_qd).unwrap();
    let mut q = DVector::zeros(n);
    q[0] = free_qd[0].signum() * (1.0 - LimitSettings::default().margin);
    let limits = JointLimits::new(
        ranges(n, -1.0, 1.0),
        LimitSettings {
            max_velocity: 100.0,
            regularisation: 0.0,
            ..LimitSettings::default()
        },
    )
    .unwrap();
    let mut s = SaturatedRmrc::new(m, n, limits).unwrap();
    let p = RmrcProblem {
        null_space: Some((&g, 0.3)),
        ..RmrcProblem::new(&j, m, &xd, &w)
    };
    let mut qd = DVector::zeros(n);
    let report = s.solve(&p, &q, 1e-3, &mut qd).unwrap();
    check_inside(&s, &qd);
    assert!(s.fixed()[0], "joint 0 held: {report:?} {qd}");
    // dense: min 1/2 qd_f^T W_ff qd_f + (a g_f + W_fs s)^T qd_f  s.t.  J_f qd_f = xd - J_s s
    let fixed: Vec<usize> = (0..n).filter(|&i| s.fixed()[i]).collect();
    let free: Vec<usize> = (0..n).filter(|&i| !s.fixed()[i]).collect();
    let wd = w.to_dense(n);
    let pick = |rows: &[usize], cols: &[usize], a: &DMatrix<f64>| {
        DMatrix::from_fn(rows.len(), cols.len(), |r, c| a[(rows[r], cols[c])])
    };
    let all: Vec<usize> = (0..m).collect();
    let (jf, js) = (pick(&all, &free, &j), pick(&all, &fixed, &j));
    let sv = DVector::from_iterator(fixed.len(), fixed.iter().map(|&i| qd[i]));
    let wff = pick(&free, &free, &wd);
    let wfs = pick(&free, &fixed, &wd);
    let lin = DVector::from_iterator(free.len(), free.iter().map(|&i| 0.3 * g[i])) + &wfs * &sv;
    let winv = wff.try_inverse().unwrap();
    let z = -&winv * &lin;
    let rhs = &xd - &js * &sv - &jf * &z;
    let lambda = (&jf * &winv * jf.transpose()).lu().solve(&rhs).unwrap();
    let dense = &winv * jf.transpose() * lambda + z;
    for (k, &i) in free.iter().enumerate() {
        assert!(
            (qd[i] - dense[k]).abs() < 1e-8,
            "joint {i}: {} vs {}",
            qd[i],
            dense[k]
        );
    }
    assert!((&j * &qd - &xd).amax() < 1e-8);
}

/// Planar 3-link chain, tip position task (2 rows).
struct Chain {
    target: Vector2<f64>,
}

impl Chain {
    fn tip(q: &DVector<f64>) -> Vector2<f64> {
        let (mut th, mut p) = (0.0, Vector2::zeros());
        for i in 0..3 {
            th += q[i];
            p += Vector2::new(th.cos(), th.sin());
        }
        p
    }
}

impl TaskMap for Chain {
    fn nq(&self) -> usize {
        3
    }
    fn nv(&self) -> usize {
        3
    }
    fn max_rows(&self) -> usize {
        2
    }
    fn error_and_jacobian(
        &mut self,
        q: &DVector<f64>,
        err: &mut DVector<f64>,
        jac: &mut DMatrix<f64>,
    ) -> Result<usize, IkError> {
        let e = self.target - Chain::tip(q);
        err[0] = e.x;
        err[1] = e.y;
        let mut th = [0.0; 3];
        th[0] = q[0];
        th[1] = th[0] + q[1];
        th[2] = th[1] + q[2];
        for c in 0..3 {
            let (mut dx, mut dy) = (0.0, 0.0);
            for t in &th[c..] {
                dx -= t.sin();
                dy += t.cos();
            }
            jac[(0, c)] = dx;
            jac[(1, c)] = dy;
        }
        Ok(2)
    }
}

#[test]
fn closed_loop_keeps_the_ranges_on_an_unreachable_target() {
    // joints limited to +-0.5 rad: the tip cannot bend back to (0, 2.5)
    let mut chain = Chain {
        target: Vector2::new(0.0, 2.5),
    };
    let limits = JointLimits::new(ranges(3, -0.5, 0.5), LimitSettings::default()).unwrap();
    let mut ik = ClosedLoopIk::with_limits(&chain, limits).unwrap();
    let mut q = DVector::from_element(3, 0.1);
    let w = Weight::Identity;
    let input = CycleInput {
        gain: 100.0,
        weight: &w,
        null_space: None,
        damping: 0.0,
        dt: 1e-3,
    };
    let mut worst: f64 = f64::INFINITY;
    for _ in 0..3000 {
        ik.step(&mut chain, &mut q, &input).unwrap();
        worst = worst.min(
            q.iter()
                .map(|x| 0.5 - x.abs())
                .fold(f64::INFINITY, f64::min),
        );
        assert!(ik.qdot.amax() <= LimitSettings::default().max_velocity + 1e-9);
    }
    assert!(worst >= 0.0, "a joint left its range by {}", -worst);
    // it ends on the bounds, as close to the target as they allow
    assert!(
        q.iter()
            .all(|x| (x.abs() - (0.5 - LimitSettings::default().margin)).abs() < 1e-3),
        "{q}"
    );
    assert!(ik.limits().is_some());
    // without limits the same loop leaves the ranges
    let mut free = ClosedLoopIk::new(&chain);
    let mut q2 = DVector::from_element(3, 0.1);
    for _ in 0..3000 {
        free.step(&mut chain, &mut q2, &input).unwrap();
    }
    assert!(q2.amax() > 0.5, "{q2}");
}
