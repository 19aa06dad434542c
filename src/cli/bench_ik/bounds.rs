//! The joint-range check of a benchmark run, independent of the IK's own limit handling: every
//! joint keeps the IK's margin from its URDF range, or, where the start pose lies inside that
//! margin band, never comes closer than it started (the IK then moves it out).

use biped_control::whole_body::Ik;
use biped_robots::description::Robot;
use nalgebra::DVector;

/// One joint's range and the distance from it the run must keep.
struct JointBound {
    name: String,
    q_index: usize,
    range: [f64; 2],
    keep: f64,
}

/// The ranged joints of an IK with the distances to keep.
pub struct JointBounds(Vec<JointBound>);

impl JointBounds {
    /// The ranged joints of `ik` on `robot`, for a run that starts at `q0`.
    pub fn new(robot: &Robot, ik: &Ik, q0: &DVector<f64>) -> Self {
        let margin = ik.limits().settings().margin;
        let name_of = |qi: usize| {
            let mut names = robot.urdf.joints.iter().map(|j| j.name.as_str());
            let found = names.find(|n| robot.joint_index(n).map(|i| i.0) == Some(qi));
            found.map_or_else(|| format!("joint at q[{qi}]"), str::to_string)
        };
        let bounds = (ik.limits().ranges().iter())
            .map(|r| {
                let start = (q0[r.q_index] - r.lower).min(r.upper - q0[r.q_index]);
                JointBound {
                    name: name_of(r.q_index),
                    q_index: r.q_index,
                    range: [r.lower, r.upper],
                    keep: margin.min(start),
                }
            })
            .collect();
        Self(bounds)
    }

    /// Smallest distance of a joint to its range at `q`, or an error naming the first joint
    /// closer than it must keep (less `slack`).
    pub fn check(&self, q: &DVector<f64>, slack: f64) -> Result<f64, String> {
        let mut min = f64::INFINITY;
        for b in &self.0 {
            let x = q[b.q_index];
            let d = (x - b.range[0]).min(b.range[1] - x);
            if d < b.keep - slack {
                return Err(format!(
                    "{} at {x:.5} is {d:.2e} from its range [{}, {}] (must keep {:.2e})",
                    b.name, b.range[0], b.range[1], b.keep
                ));
            }
            min = min.min(d);
        }
        Ok(min)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_joint_closer_than_it_started_inside_the_margin_is_named() {
        let robot = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
        let ik = Ik::new(&robot.urdf).unwrap();
        let (qi, _) = robot.joint_index("left_knee_joint").unwrap();
        let lower = robot.joint("left_knee_joint").unwrap().range.unwrap()[0];
        let mut q0 = robot.comfort.clone();
        q0[qi] = lower + 0.005; // inside the margin of 0.01
        let bounds = JointBounds::new(&robot, &ik, &q0);
        assert!((bounds.check(&q0, 1e-12).unwrap() - 0.005).abs() < 1e-12);
        let mut q = q0.clone();
        q[qi] = lower + 0.004;
        let err = bounds.check(&q, 1e-12).unwrap_err();
        assert!(err.starts_with("left_knee_joint at"), "{err}");
        // another joint may not enter the margin band at all
        let (hip, _) = robot.joint_index("left_hip_roll_joint").unwrap();
        let hip_upper = robot.joint("left_hip_roll_joint").unwrap().range.unwrap()[1];
        let mut q = q0.clone();
        q[hip] = hip_upper - 0.009;
        assert!(bounds
            .check(&q, 1e-12)
            .unwrap_err()
            .starts_with("left_hip_roll_joint"));
    }
}
