//! IK algorithms on a planar serial chain with analytic forward kinematics: an independent
//! reference for Newton-Raphson, optimisation, RMRC (dense formulas), DLS/manipulability
//! (SVD), closed-loop tracking, Jacobian transpose, resolved acceleration and blending.

use biped_control::ik::{
    jacobian_transpose, AccelerationInput, Activation, ClosedLoopIk, CycleInput, IkSettings,
    PositionIk, ResolvedAcceleration, Rmrc, RmrcProblem, StopReason, TaskBuffers, TaskMap, Weight,
};
use biped_control::IkError;
use nalgebra::{DMatrix, DVector, Vector2};

/// Planar chain with link lengths `l`; tasks: tip position (2 rows) and, optionally, the tip
/// angle `sum q` (1 row) with an activation ramp.
struct Chain {
    l: Vec<f64>,
    target: Vector2<f64>,
    target_angle: f64,
    velocity: Vector2<f64>,
    angle: Option<Activation>,
    soft: [f64; 3],
}

impl Chain {
    fn new(l: &[f64], target: [f64; 2]) -> Self {
        Self {
            l: l.to_vec(),
            target: Vector2::new(target[0], target[1]),
            target_angle: 0.0,
            velocity: Vector2::zeros(),
            angle: None,
            soft: [0.0; 3],
        }
    }
    /// Tip position (analytic FK).
    fn tip(&self, q: &DVector<f64>) -> Vector2<f64> {
        let mut th = 0.0;
        let mut p = Vector2::zeros();
        for (i, l) in self.l.iter().enumerate() {
            th += q[i];
            p += Vector2::new(th.cos(), th.sin()) * *l;
        }
        p
    }
    /// Analytic tip acceleration at qdd = 0: `sum l_i thd_i^2 (-cos, -sin)`.
    fn tip_bias(&self, q: &DVector<f64>, qd: &DVector<f64>) -> Vector2<f64> {
        let (mut th, mut thd) = (0.0, 0.0);
        let mut a = Vector2::zeros();
        for (i, l) in self.l.iter().enumerate() {
            th += q[i];
            thd += qd[i];
            a -= Vector2::new(th.cos(), th.sin()) * (*l * thd * thd);
        }
        a
    }
}

impl TaskMap for Chain {
    fn nq(&self) -> usize {
        self.l.len()
    }
    fn nv(&self) -> usize {
        self.l.len()
    }
    fn max_rows(&self) -> usize {
        3
    }
    fn error_and_jacobian(
        &mut self,
        q: &DVector<f64>,
        err: &mut DVector<f64>,
        jac: &mut DMatrix<f64>,
    ) -> Result<usize, IkError> {
        let n = self.l.len();
        let e = self.target - self.tip(q);
        err[0] = e.x;
        err[1] = e.y;
        for c in 0..n {
            let (mut th, mut jx, mut jy) = (0.0, 0.0, 0.0);
            for (i, l) in self.l.iter().enumerate() {
                th += q[i];
                if i >= c {
                    jx -= l * th.sin();
                    jy += l * th.cos();
                }
            }
            jac[(0, c)] = jx;
            jac[(1, c)] = jy;
        }
        match self.angle {
            Some(a) if a.is_active() => {
                err[2] = self.target_angle - q.sum();
                jac.row_mut(2).fill(1.0);
                self.soft[2] = a.softness();
                Ok(3)
            }
            _ => Ok(2),
        }
    }
    fn feedforward(&self, out: &mut DVector<f64>) {
        out.fill(0.0);
        out[0] = self.velocity.x;
        out[1] = self.velocity.y;
    }
    fn softness(&self) -> Option<&[f64]> {
        Some(&self.soft)
    }
}

fn q0(n: usize) -> DVector<f64> {
    DVector::from_fn(n, |i, _| 0.3 + 0.2 * i as f64)
}

#[test]
fn newton_raphson_reaches_reachable_target() {
    let mut chain = Chain::new(&[1.0, 0.8, 0.5], [0.9, 1.2]);
    let mut q = q0(3);
    let mut ik = PositionIk::new(&chain, IkSettings::default());
    let r = ik.newton_raphson(&mut chain, &mut q).unwrap();
    assert_eq!(r.stop, StopReason::Converged, "{r:?}");
    assert!((chain.tip(&q) - chain.target).norm() < 1e-10);
    assert!(r.iterations < 20);
}

#[test]
fn optimisation_with_wolfe_reaches_reachable_target() {
    let mut chain = Chain::new(&[1.0, 0.8, 0.5], [-0.4, 1.5]);
    let mut q = q0(3);
    let mut ik = PositionIk::new(
        &chain,
        IkSettings {
            delta: 1e-3,
            ..Default::default()
        },
    );
    let r = ik
        .optimize(&mut chain, &mut q)
        .unwrap()
        .require_reached()
        .unwrap();
    assert!((chain.tip(&q) - chain.target).norm() < 1e-10, "{r:?}");
}

#[test]
fn unreachable_target_is_reported_and_optimum_is_closest_point() {
    let reach = 2.3;
    let far = Vector2::new(3.0, 2.0);
    let mut chain = Chain::new(&[1.0, 0.8, 0.5], [far.x, far.y]);
    let mut q = q0(3);
    let mut ik = PositionIk::new(
        &chain,
        IkSettings {
            delta: 1e-4,
            ..Default::default()
        },
    );
    let rep = ik.optimize(&mut chain, &mut q).unwrap();
    let err = rep.require_reached();
    assert!(matches!(err, Err(IkError::Unreachable { .. })), "{err:?}");
    // The minimiser of (4.4) stretches the arm towards the target (slow near the singular
    // stretched pose, so compare the residual with its geometric minimum |far| - reach).
    assert!(rep.error_norm - (far.norm() - reach) < 1e-3, "{rep:?}");
    assert!((chain.tip(&q).norm() - reach).abs() < 1e-3);
    assert!(chain.tip(&q).normalize().dot(&far.normalize()) > 1.0 - 1e-3);
    let mut q = q0(3);
    let r = ik.newton_raphson(&mut chain, &mut q).unwrap();
    assert!(!r.reached());
    assert!(r.error_norm > far.norm() - reach - 1e-6);
}

#[test]
fn iteration_limit_and_singular_start_are_reported() {
    let mut chain = Chain::new(&[1.0, 0.8, 0.5], [0.9, 1.2]);
    let mut ik = PositionIk::new(
        &chain,
        IkSettings {
            max_iterations: 1,
            ..Default::default()
        },
    );
    let r = ik.newton_raphson(&mut chain, &mut q0(3)).unwrap();
    assert_eq!((r.stop, r.iterations), (StopReason::IterationLimit, 1));
    // Stretched along x: J has rank 1, J J^T is singular.
    let mut chain = Chain::new(&[1.0, 0.8, 0.5], [1.0, 1.0]);
    let r = ik
        .newton_raphson(&mut chain, &mut DVector::zeros(3))
        .unwrap();
    assert_eq!(r.stop, StopReason::Singular);
    let nan = DVector::from_element(3, f64::NAN);
    assert!(matches!(
        ik.newton_raphson(&mut chain, &mut nan.clone()),
        Err(IkError::NonFinite(_))
    ));
}

/// Dense reference of (4.12): `J#_W xd - alpha (E - J#_W J) W^-1 g`.
fn dense_rmrc(
    j: &DMatrix<f64>,
    w: &DMatrix<f64>,
    xd: &DVector<f64>,
    g: &DVector<f64>,
    a: f64,
) -> DVector<f64> {
    let wi = w.clone().try_inverse().unwrap();
    let jw = &wi * j.transpose() * (j * &wi * j.transpose()).try_inverse().unwrap();
    let n = DMatrix::identity(j.ncols(), j.ncols()) - &jw * j;
    jw * xd - n * wi * g * a
}

fn chain_jacobian(q: &DVector<f64>) -> (Chain, TaskBuffers) {
    let mut chain = Chain::new(&[1.0, 0.7, 0.6, 0.4, 0.3], [0.0, 0.0]);
    let mut buf = TaskBuffers::new(&chain);
    buf.evaluate(&mut chain, q).unwrap();
    (chain, buf)
}

#[test]
fn klein_huang_matches_dense_weighted_inverse_and_null_space_is_invisible() {
    let q = q0(5);
    let (_, buf) = chain_jacobian(&q);
    let j = buf.jac.rows(0, 2).into_owned();
    let xd = DVector::from_vec(vec![0.3, -0.2]);
    let g = DVector::from_vec(vec![1.0, -2.0, 0.5, 0.3, -0.7]);
    let d = DVector::from_vec(vec![1.0, 2.0, 0.5, 3.0, 1.5]);
    let u = DVector::from_vec(vec![0.4, -0.3, 0.9, 0.1, 0.2]);
    let weights = [
        Weight::Identity,
        Weight::Diagonal(d.clone()),
        Weight::DiagonalRankOne { diag: d, u },
    ];
    let mut rmrc = Rmrc::new(3, 5);
    for w in &weights {
        let mut qd = DVector::zeros(5);
        let mut p = RmrcProblem::new(&buf.jac, 2, &xd, w);
        p.null_space = Some((&g, 0.8));
        rmrc.solve(&p, &mut qd).unwrap();
        let reference = dense_rmrc(&j, &w.to_dense(5), &xd, &g, 0.8);
        assert!((&qd - &reference).norm() < 1e-12, "{w:?}");
        // J N = 0: the primary task is tracked exactly despite the gradient.
        assert!((&j * &qd - &xd).norm() < 1e-12);
        let mut qd0 = DVector::zeros(5);
        rmrc.solve(&RmrcProblem::new(&buf.jac, 2, &xd, w), &mut qd0)
            .unwrap();
        assert!((&j * (&qd - &qd0)).norm() < 1e-12);
        assert!((&qd - &qd0).norm() > 1e-3, "null-space term must act");
    }
}

#[test]
fn damped_least_squares_and_manipulability_match_svd() {
    let q = q0(5);
    let (_, buf) = chain_jacobian(&q);
    let j = buf.jac.rows(0, 2).into_owned();
    let xd = DVector::from_vec(vec![0.5, 0.1]);
    let svd = j.clone().svd(true, true);
    let (u, vt) = (svd.u.unwrap(), svd.v_t.unwrap());
    let lam2 = 0.05;
    let mut reference = DVector::zeros(5);
    for (i, s) in svd.singular_values.iter().enumerate() {
        let c = s / (s * s + lam2) * u.column(i).dot(&xd);
        reference += vt.row(i).transpose() * c;
    }
    let mut rmrc = Rmrc::new(3, 5);
    let mut p = RmrcProblem::new(&buf.jac, 2, &xd, &Weight::Identity);
    p.damping = lam2;
    let mut qd = DVector::zeros(5);
    rmrc.solve(&p, &mut qd).unwrap();
    assert!((&qd - &reference).norm() < 1e-12);
    let w = rmrc.manipulability(&buf.jac, 2).unwrap();
    let prod: f64 = svd.singular_values.iter().product();
    assert!((w - prod).abs() < 1e-12 * prod.max(1.0), "{w} vs {prod}");
    let (_, stretched) = chain_jacobian(&DVector::zeros(5));
    assert_eq!(rmrc.manipulability(&stretched.jac, 2).unwrap(), 0.0);
}

#[test]
fn closed_loop_tracking_converges_on_a_moving_target() {
    let mut chain = Chain::new(&[1.0, 0.8, 0.5], [0.0, 0.0]);
    let mut q = q0(3);
    let mut cl = ClosedLoopIk::new(&chain);
    let (dt, gain) = (1e-3, 50.0);
    let centre = Vector2::new(0.8, 0.9);
    let mut errs = Vec::new();
    for k in 0..3000 {
        let t = k as f64 * dt;
        let w = 2.0;
        chain.target = centre + Vector2::new((w * t).cos(), (w * t).sin()) * 0.3;
        chain.velocity = Vector2::new(-(w * t).sin(), (w * t).cos()) * (0.3 * w);
        let input = CycleInput {
            gain,
            weight: &Weight::Identity,
            null_space: None,
            damping: 0.0,
            dt,
        };
        cl.step(&mut chain, &mut q, &input).unwrap();
        errs.push((chain.target - chain.tip(&q)).norm());
    }
    // Start error decays like exp(-K t); with feed-forward the residual is O(dt).
    assert!(errs[0] > 0.1);
    assert!(
        errs[200] < errs[0] * (-gain * 0.15f64).exp() + 1e-3,
        "{}",
        errs[200]
    );
    assert!(errs[2999] < 1e-3, "{}", errs[2999]);
}

#[test]
fn jacobian_transpose_reduces_the_error() {
    let mut chain = Chain::new(&[1.0, 0.8, 0.5], [0.9, 1.2]);
    let mut q = q0(3);
    let mut buf = TaskBuffers::new(&chain);
    let mut qd = DVector::zeros(3);
    buf.evaluate(&mut chain, &q).unwrap();
    let e0 = buf.error_norm();
    for _ in 0..5000 {
        buf.evaluate(&mut chain, &q).unwrap();
        jacobian_transpose(&buf.jac, buf.rows, &buf.err, 10.0, &mut qd).unwrap();
        q.axpy(1e-3, &qd, 1.0);
    }
    buf.evaluate(&mut chain, &q).unwrap();
    assert!(buf.error_norm() < 1e-3 * e0, "{}", buf.error_norm());
}

#[test]
fn resolved_acceleration_bias_matches_analytic_and_tracks() {
    let mut chain = Chain::new(&[1.0, 0.8, 0.5], [0.9, 1.2]);
    let mut q = q0(3);
    let mut qd = DVector::from_vec(vec![0.7, -1.1, 0.4]);
    let mut rac = ResolvedAcceleration::new(&chain);
    rac.bias(&mut chain, &q, &qd).unwrap();
    let exact = chain.tip_bias(&q, &qd);
    assert!(
        (rac.jdot_qd.rows(0, 2) - exact).norm() < 1e-7,
        "{} vs {exact}",
        rac.jdot_qd
    );
    let zero = DVector::zeros(3);
    let input = AccelerationInput {
        xdot: &zero,
        xddot: &zero,
        kp: 100.0,
        kd: 20.0,
        weight: &Weight::Identity,
        dt: 1e-3,
    };
    for _ in 0..3000 {
        rac.step(&mut chain, &mut q, &mut qd, &input).unwrap();
    }
    // The initial null-space velocity is never damped (no null-space term), so the chain keeps
    // moving and an O(dt) tracking offset remains.
    assert!((chain.tip(&q) - chain.target).norm() < 1e-4);
}

#[test]
fn switching_a_task_off_with_ramp_keeps_qdot_continuous() {
    let run = |ramp: f64| {
        let mut chain = Chain::new(&[1.0, 0.8, 0.5], [0.9, 1.2]);
        chain.angle = Some(Activation::new(true, ramp));
        chain.target_angle = 2.0;
        let mut q = q0(3);
        let mut cl = ClosedLoopIk::new(&chain);
        let g = DVector::from_vec(vec![1.0, -1.0, 0.5]);
        let dt = 1e-3;
        let mut max_jump: f64 = 0.0;
        let mut prev: Option<DVector<f64>> = None;
        for k in 0..1500 {
            if k == 500 {
                chain.angle.as_mut().unwrap().switch(false);
            }
            chain.angle.as_mut().unwrap().advance(dt);
            let t = k as f64 * dt;
            chain.target = Vector2::new(0.9 + 0.2 * t.sin(), 1.2);
            chain.velocity = Vector2::new(0.2 * t.cos(), 0.0);
            let input = CycleInput {
                gain: 20.0,
                weight: &Weight::Identity,
                null_space: Some((&g, 0.5)),
                damping: 0.0,
                dt,
            };
            cl.step(&mut chain, &mut q, &input).unwrap();
            if let Some(p) = &prev {
                if k > 400 {
                    max_jump = max_jump.max((&cl.qdot - p).norm());
                }
            }
            prev = Some(cl.qdot.clone());
        }
        max_jump
    };
    let abrupt = run(0.0);
    let ramped = run(0.3);
    assert!(abrupt > 0.1, "abrupt switch must jump: {abrupt}");
    assert!(ramped < abrupt / 20.0, "ramped {ramped} vs abrupt {abrupt}");
}
