//! Position IK on the Unitree G1 humanoid (the URDF bundled with `biped_dynamics`, pelvis
//! welded to the world): lift the left foot 10 cm and move it 5 cm forward while the right
//! foot keeps its pose, by Newton-Raphson (Algorithm 4.1), then check the result with the
//! forward kinematics.
//!
//! Run with `cargo run -p biped_control --example g1_ik`.
//!
//! The ready-made task set of `biped_control` (`tasks::LolaTasks`) describes the Lola-like
//! biped; for any other robot the IK solvers take a task map of one's own, an implementation
//! of `ik::TaskMap` (task error and Jacobian at `q`). `FeetTasks` below is a compact one: the
//! pose (position and angle-axis orientation error) of two foot bodies.

use biped_control::ik::orientation::orientation_error;
use biped_control::ik::{IkSettings, PositionIk, TaskMap};
use biped_control::IkError;
use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{update_placements, Data, JacobianFrame, Jacobians, Model};
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};

/// World pose targets of two bodies: 12 task rows, `[position; orientation]` per body.
struct FeetTasks {
    model: Model,
    data: Data,
    jac: Jacobians,
    j6: DMatrix<f64>,
    feet: [usize; 2],
    targets: [(Vector3<f64>, Matrix3<f64>); 2],
}

impl TaskMap for FeetTasks {
    fn nq(&self) -> usize {
        self.model.nq()
    }
    fn nv(&self) -> usize {
        self.model.nv()
    }
    fn max_rows(&self) -> usize {
        12
    }
    fn error_and_jacobian(
        &mut self,
        q: &DVector<f64>,
        err: &mut DVector<f64>,
        jac: &mut DMatrix<f64>,
    ) -> Result<usize, IkError> {
        let kin = |e: biped_dynamics::JacobianError| IkError::Kinematics(e.to_string());
        self.jac
            .compute(&self.model, &mut self.data, q)
            .map_err(kin)?;
        for (k, (&body, (pos_d, rot_d))) in self.feet.iter().zip(&self.targets).enumerate() {
            let (rot, pos) = self
                .jac
                .body_pose(body)
                .ok_or(IkError::UnknownName("foot".into()))?;
            err.rows_mut(6 * k, 3).copy_from(&(pos_d - pos));
            err.rows_mut(6 * k + 3, 3)
                .copy_from(&orientation_error(rot_d, &rot));
            // body Jacobian rows are [omega; rdot] (world axes, velocity of the body origin)
            self.jac
                .body_jacobian(body, JacobianFrame::WorldAligned, &mut self.j6)
                .map_err(kin)?;
            jac.rows_mut(6 * k, 3).copy_from(&self.j6.rows(3, 3));
            jac.rows_mut(6 * k + 3, 3).copy_from(&self.j6.rows(0, 3));
        }
        Ok(12)
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../dynamics/data/g1_29dof_rev_1_0.urdf"
    );
    let model = load_file(path, &UrdfOptions::default())?.model; // fixed base at the pelvis
    let joint_q = |name: &str| {
        let body = model.bodies().iter().find(|b| b.joint_name() == name);
        body.map(|b| b.q_index())
    };
    // Start with bent knees, feet flat: a straight leg is singular for vertical foot motion.
    let mut q0 = model.neutral();
    for side in ["left", "right"] {
        for (joint, angle) in [("hip_pitch", -0.3), ("knee", 0.6), ("ankle_pitch", -0.3)] {
            let name = format!("{side}_{joint}_joint");
            q0[joint_q(&name).ok_or(name)?] = angle;
        }
    }
    let feet = ["left_ankle_roll_link", "right_ankle_roll_link"]
        .map(|n| model.body_id(n).expect("G1 foot link"));

    let mut data = Data::new(&model);
    update_placements(&model, &mut data, &q0)?;
    let start = feet.map(|b| (data.world_pos[b], data.world_rot[b]));
    let lift = Vector3::new(0.05, 0.0, 0.10);
    let mut tasks = FeetTasks {
        jac: Jacobians::new(&model),
        data: Data::new(&model),
        j6: DMatrix::zeros(6, model.nv()),
        feet,
        targets: [(start[0].0 + lift, start[0].1), start[1]],
        model: model.clone(),
    };

    let mut q = q0.clone();
    let mut ik = PositionIk::new(&tasks, IkSettings::default());
    let report = ik.newton_raphson(&mut tasks, &mut q)?.require_reached()?;
    println!(
        "G1, {} joints: left foot target reached in {} Newton-Raphson iterations, |dx| = {:.1e}",
        model.nv(),
        report.iterations,
        report.error_norm
    );

    update_placements(&model, &mut data, &q)?;
    for (k, name) in ["left foot ", "right foot"].iter().enumerate() {
        let moved = data.world_pos[feet[k]] - start[k].0;
        let turned = orientation_error(&start[k].1, &data.world_rot[feet[k]]).norm();
        println!(
            "{name} moved by [{:+.4} {:+.4} {:+.4}] m, turned by {turned:.1e} rad",
            moved.x + 0.0, // + 0.0 prints -0 as 0
            moved.y + 0.0,
            moved.z + 0.0
        );
    }
    for b in model.bodies() {
        let dq = q[b.q_index()] - q0[b.q_index()];
        if b.owns_coordinates() && dq.abs() > 1e-9 {
            println!(
                "  {:28} {:+.4} -> {:+.4} rad",
                b.joint_name(),
                q0[b.q_index()],
                q[b.q_index()]
            );
        }
    }
    Ok(())
}
