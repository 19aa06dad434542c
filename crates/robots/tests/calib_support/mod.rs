//! Synthetic jig measurements on the bundled G1 URDF: true configurations, forward kinematics
//! for the jig targets, measured encoders `q_true - offset + noise`.
#![allow(dead_code)]

use biped_dynamics::urdf::{load_str, UrdfModel, UrdfOptions};
use biped_dynamics::{Data, Jacobians};
use biped_robots::calibration::{
    BodyFrame, CalibratedJoint, CalibrationProblem, Components, JigConstraint, JigPose,
};
use nalgebra::{DVector, Isometry3};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// The 12 leg joints of the G1.
pub const LEGS: [&str; 12] = [
    "left_hip_pitch_joint",
    "left_hip_roll_joint",
    "left_hip_yaw_joint",
    "left_knee_joint",
    "left_ankle_pitch_joint",
    "left_ankle_roll_joint",
    "right_hip_pitch_joint",
    "right_hip_roll_joint",
    "right_hip_yaw_joint",
    "right_knee_joint",
    "right_ankle_pitch_joint",
    "right_ankle_roll_joint",
];

/// The bundled G1 URDF text.
pub fn g1_xml() -> String {
    let p = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../dynamics/data/g1_29dof_rev_1_0.urdf"
    );
    std::fs::read_to_string(p).expect("bundled G1 URDF")
}

/// Loads URDF text as a fixed-base model.
pub fn load(xml: &str) -> UrdfModel {
    load_str(xml, "g1.urdf", &UrdfOptions::default()).expect("G1 loads")
}

/// Body frame of a link.
pub fn frame(u: &UrdfModel, link: &str) -> BodyFrame {
    let l = u.links.iter().find(|l| l.link == link).expect("link");
    BodyFrame {
        body: l.body,
        pose: l.pose,
    }
}

/// The jig of Fig. 3.5 for the legs: both feet fixed relative to the pelvis.
pub fn feet_jig(u: &UrdfModel, components: Components) -> Vec<JigConstraint> {
    ["left", "right"]
        .iter()
        .map(|side| JigConstraint {
            name: format!("pelvis->{side}_foot"),
            a: frame(u, "pelvis"),
            b: frame(u, &format!("{side}_ankle_roll_link")),
            components,
            position_weight: 10.0,
            orientation_weight: 1.0,
        })
        .collect()
}

/// A synthetic data set.
pub struct Synthetic {
    /// Joints to calibrate.
    pub joints: Vec<String>,
    /// True offsets.
    pub offsets: DVector<f64>,
    /// Encoder noise standard deviation \[rad] (uniform noise with this std).
    pub noise: f64,
    /// Number of poses.
    pub poses: usize,
    /// RNG seed.
    pub seed: u64,
}

/// Random true leg configuration (knees bent, moderate hip/ankle angles).
fn random_q(u: &UrdfModel, rng: &mut StdRng) -> DVector<f64> {
    let mut q = u.model.neutral();
    for name in LEGS {
        let j = CalibratedJoint::find(&u.model, name).unwrap();
        q[j.q_index] = if name.contains("knee") {
            rng.random_range(0.2..1.2)
        } else {
            rng.random_range(-0.35..0.35)
        };
    }
    q
}

/// Builds the problem on model `cal` with measurements generated on model `truth`.
pub fn problem(
    truth: &UrdfModel,
    cal: &UrdfModel,
    s: &Synthetic,
    comp: Components,
) -> CalibrationProblem {
    let mut rng = StdRng::seed_from_u64(s.seed);
    let cons_true = feet_jig(truth, comp);
    let joints: Vec<CalibratedJoint> = s
        .joints
        .iter()
        .map(|n| CalibratedJoint::find(&cal.model, n).unwrap())
        .collect();
    let mut data = Data::new(&truth.model);
    let mut jac = Jacobians::new(&truth.model);
    let half = s.noise * 3f64.sqrt();
    let poses = (0..s.poses)
        .map(|p| {
            let q_true = random_q(truth, &mut rng);
            jac.compute(&truth.model, &mut data, &q_true).unwrap();
            let targets: Vec<(usize, Isometry3<f64>)> = cons_true
                .iter()
                .enumerate()
                .map(|(i, c)| (i, c.relative_pose(&jac).unwrap()))
                .collect();
            let mut q = q_true.clone();
            for (j, x) in joints.iter().zip(s.offsets.iter()) {
                q[j.q_index] -= x;
            }
            for name in LEGS {
                let j = CalibratedJoint::find(&truth.model, name).unwrap();
                if half > 0.0 {
                    q[j.q_index] += rng.random_range(-half..half);
                }
            }
            JigPose {
                name: format!("pose {}", p + 1),
                q_measured: q,
                targets,
            }
        })
        .collect();
    CalibrationProblem::new(cal.model.clone(), joints, feet_jig(cal, comp), poses).unwrap()
}

/// Random true offsets in +-0.1 rad for `n` joints.
pub fn random_offsets(n: usize, seed: u64) -> DVector<f64> {
    let mut rng = StdRng::seed_from_u64(seed);
    DVector::from_fn(n, |_, _| rng.random_range(-0.1..0.1))
}

/// The leg joint names as owned strings.
pub fn leg_names() -> Vec<String> {
    LEGS.iter().map(|s| s.to_string()).collect()
}
