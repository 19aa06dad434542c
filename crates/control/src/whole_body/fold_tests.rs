//! The folded soft posture and joint tasks (`rmrc`'s unit-row fast case) give the closed loop
//! of the stacked solve to round-off, inside the joint limits: on the G1 with random posture
//! targets and weights, task orders, foot targets far enough to saturate and each weight shape,
//! and on random tree models.

use super::Ik;
use crate::error::IkError;
use crate::ik::{
    ClosedLoopIk, CycleInput, JointLimits, JointRange, LimitSettings, TaskMap, Weight,
};
use crate::tasks::{Frame, Task, TaskKind, TaskStack};
use biped_dynamics::RigidInertia;
use biped_dynamics::{update_placements, BodySpec, Data, JointModel, Model, ModelBuilder};
use biped_robots::description::Robot;
use nalgebra::{DMatrix, DVector, Isometry3, Matrix3, Translation3, Unit, Vector3};
use proptest::prelude::*;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use std::sync::OnceLock;

/// A task stack seen without its unit rows: the solver stacks every row (the reference).
struct Stacked<'a>(&'a mut TaskStack);

impl TaskMap for Stacked<'_> {
    fn nq(&self) -> usize {
        self.0.nq()
    }
    fn nv(&self) -> usize {
        self.0.nv()
    }
    fn max_rows(&self) -> usize {
        self.0.max_rows()
    }
    fn error_and_jacobian(
        &mut self,
        q: &DVector<f64>,
        err: &mut DVector<f64>,
        jac: &mut DMatrix<f64>,
    ) -> Result<usize, IkError> {
        self.0.error_and_jacobian(q, err, jac)
    }
    fn feedforward(&self, out: &mut DVector<f64>) {
        self.0.feedforward(out)
    }
    fn softness(&self) -> Option<&[f64]> {
        self.0.softness()
    }
    fn retract(
        &self,
        q: &DVector<f64>,
        v: &DVector<f64>,
        step: f64,
        out: &mut DVector<f64>,
    ) -> Result<(), IkError> {
        self.0.retract(q, v, step, out)
    }
}

fn g1() -> &'static Robot {
    static G1: OnceLock<Robot> = OnceLock::new();
    G1.get_or_init(|| Robot::load(Robot::bundled("g1").unwrap()).unwrap())
}

/// A random joint weight of each shape on `n` joints.
fn weight(rng: &mut StdRng, n: usize) -> Weight {
    let diag = DVector::from_fn(n, |_, _| rng.random_range(0.2..5.0));
    match rng.random_range(0..3) {
        0 => Weight::Identity,
        1 => Weight::Diagonal(diag),
        _ => Weight::DiagonalRankOne {
            diag,
            u: DVector::from_fn(n, |_, _| rng.random_range(-1.0..1.0)),
        },
    }
}

/// Runs the folded and the stacked closed loop side by side from `q0` for `steps` cycles and
/// checks equal joint velocities; returns the number of cycles that held a joint.
fn compare(
    mut stack: TaskStack,
    limits: JointLimits,
    q0: &DVector<f64>,
    rng: &mut StdRng,
    steps: usize,
) -> Result<usize, TestCaseError> {
    let mut reference = stack.clone();
    let mut folded = ClosedLoopIk::with_limits(&stack, limits.clone()).unwrap();
    let mut stacked = ClosedLoopIk::with_limits(&stack, limits).unwrap();
    let n = stack.nv();
    let w = weight(rng, n);
    let grad = DVector::from_fn(n, |_, _| rng.random_range(-1.0..1.0));
    let input = CycleInput {
        gain: 500.0,
        weight: &w,
        null_space: rng.random_bool(0.5).then_some((&grad, 0.3)),
        damping: 1e-8,
        dt: 1e-3,
    };
    let (mut qa, mut qb, mut held) = (q0.clone(), q0.clone(), 0);
    for k in 0..steps {
        folded.step(&mut stack, &mut qa, &input).unwrap();
        stacked
            .step(&mut Stacked(&mut reference), &mut qb, &input)
            .unwrap();
        let (a, b) = (&folded.qdot, &stacked.qdot);
        let tol = 1e-8 * (1.0 + b.amax());
        prop_assert!((a - b).amax() <= tol, "cycle {}: {} vs {}", k, a, b);
        prop_assert!(!stack.unit_rows().is_empty());
        let report = folded.limits().unwrap().report();
        prop_assert_eq!(report, stacked.limits().unwrap().report());
        held += (report.fixed > 0) as usize;
    }
    Ok(held)
}

/// Feet (the left one moved by up to 10 cm: beyond the velocity limits in one cycle), CoM and
/// pelvis on the G1, with a soft posture towards a perturbed comfort pose and a soft joint task,
/// in random order.
fn g1_case(rng: &mut StdRng) -> (Ik, DVector<f64>) {
    let robot = g1();
    let (model, q0) = (&robot.urdf.model, robot.comfort.clone());
    let mut data = Data::new(model);
    update_placements(model, &mut data, &q0).unwrap();
    let mut ik = Ik::new(&robot.urdf).unwrap();
    let posture_first = rng.random_bool(0.5);
    let mut target = q0.clone();
    for r in ik.limits().ranges() {
        let x = q0[r.q_index] + rng.random_range(-0.4..0.4);
        target[r.q_index] = x.clamp(r.lower, r.upper);
    }
    let wp = 10f64.powf(rng.random_range(-4.0..1.0));
    if posture_first {
        ik.posture(&target, wp).unwrap();
    }
    let lift = Vector3::from_fn(|_, _| rng.random_range(0.05..0.1));
    for (i, name) in ["left_ankle_roll_link", "right_ankle_roll_link"]
        .iter()
        .enumerate()
    {
        let pose = data.body_pose(model.body_id(name).unwrap());
        let shift = if i == 0 { lift } else { Vector3::zeros() };
        ik.frame_pose(name, Translation3::from(shift) * pose)
            .unwrap();
    }
    let elbow = ik.joint("left_elbow_joint", 0.3).unwrap();
    ik.set_weight(elbow, Some(10f64.powf(rng.random_range(-3.0..1.0))))
        .unwrap();
    let pelvis = data.world_rot[model.body_id("pelvis").unwrap()];
    ik.frame_orientation("pelvis", pelvis).unwrap();
    if !posture_first {
        ik.posture(&target, wp).unwrap();
    }
    (ik, q0)
}

/// A free-floating random tree of `n` revolute joints with ranges, a soft posture and a soft
/// joint task, a position and an orientation task; and a configuration inside the ranges.
fn random_case(rng: &mut StdRng, n: usize) -> (TaskStack, JointLimits, DVector<f64>) {
    let inertia = RigidInertia::new(
        1.0,
        Vector3::new(0.0, 0.0, 0.05),
        Matrix3::identity() * 0.01,
    )
    .unwrap();
    let mut b = ModelBuilder::new();
    let spec = |name: String, parent, joint, placement| {
        BodySpec::named(&name, parent, joint, placement, inertia)
    };
    let base = spec(
        "base".into(),
        None,
        JointModel::FreeQuaternion,
        Isometry3::identity(),
    );
    let mut bodies = vec![b.add_body(base).unwrap()];
    for i in 0..n {
        let axis = Unit::new_normalize(Vector3::from_fn(|_, _| rng.random_range(-1.0..1.0)));
        let at = Isometry3::translation(0.0, rng.random_range(-0.1..0.1), 0.2);
        let parent = bodies[rng.random_range(0..bodies.len())];
        let joint = JointModel::Revolute { axis };
        bodies.push(
            b.add_body(spec(format!("b{i}"), Some(parent), joint, at))
                .unwrap(),
        );
    }
    let model: Model = b.build().unwrap();
    let mut q = model.neutral();
    let ranges: Vec<JointRange> = bodies[1..]
        .iter()
        .map(|&id| {
            let body = model.body(id).unwrap();
            let (lower, upper) = (rng.random_range(-1.5..-0.2), rng.random_range(0.2..1.5));
            q[body.q_index()] = rng.random_range(lower..upper);
            let (q_index, v_index) = (body.q_index(), body.v_index());
            JointRange {
                q_index,
                v_index,
                lower,
                upper,
            }
        })
        .collect();
    let joints: Vec<_> = ranges.iter().map(|r| (r.q_index, r.v_index)).collect();
    let mut stack = TaskStack::new(&model);
    let posture = TaskKind::Posture {
        joints,
        target: model.neutral(),
    };
    stack
        .push(Task::soft(posture, rng.random_range(0.01..1.0)))
        .unwrap();
    let (tip, mid) = (*bodies.last().unwrap(), bodies[n / 2]);
    let target = Vector3::from_fn(|_, _| rng.random_range(-0.5..0.5));
    let position = TaskKind::Position {
        frame: Frame::body(tip),
        target,
    };
    stack.push(Task::hard(position)).unwrap();
    let r = ranges[0];
    let joint = TaskKind::Joint {
        q_index: r.q_index,
        v_index: r.v_index,
        target: 0.5,
    };
    stack.push(Task::soft(joint, 2.0)).unwrap();
    let orientation = TaskKind::Orientation {
        frame: Frame::body(mid),
        target: Matrix3::identity(),
    };
    stack.push(Task::soft(orientation, 5.0)).unwrap();
    let limits = JointLimits::new(ranges, LimitSettings::default()).unwrap();
    (stack, limits, q)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn folded_posture_tracks_as_stacked_on_the_g1(seed in any::<u64>()) {
        let mut rng = StdRng::seed_from_u64(seed);
        let (ik, q0) = g1_case(&mut rng);
        let limits = ik.limits().clone();
        let held = compare(ik.tasks().clone(), limits, &q0, &mut rng, 12)?;
        prop_assert!(held > 0, "no cycle held a joint");
    }

    #[test]
    fn folded_posture_tracks_as_stacked_on_random_trees(seed in any::<u64>(), n in 3usize..12) {
        let mut rng = StdRng::seed_from_u64(seed);
        let (stack, limits, q0) = random_case(&mut rng, n);
        compare(stack, limits, &q0, &mut rng, 12)?;
    }
}
