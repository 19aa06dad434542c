//! Whole-body IK on the Unitree G1 URDF in a few lines: the left foot steps 10 cm forward and
//! lifts 5 cm while the right foot and the centre of mass stay, a soft posture task holds the
//! rest, and the URDF's joint position and velocity limits are kept (on by default). The
//! result is checked by forward kinematics.
//!
//! Run with `cargo run --release --example urdf_ik`.

use biped_control::whole_body::Ik;
use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::{center_of_mass, update_placements, Data};
use nalgebra::Translation3;

/// Loads the G1, solves, checks and prints.
pub fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/crates/dynamics/data/g1_29dof_rev_1_0.urdf"
    );
    let g1 = load_file(
        path,
        &UrdfOptions {
            floating: true,
            ..Default::default()
        },
    )?;
    let (model, mut data) = (&g1.model, Data::new(&g1.model));
    let mut ik = Ik::new(&g1)?; // the URDF's joint limits are kept

    // start with bent knees (a straight leg is singular for vertical foot motion)
    let mut q = model.neutral();
    for (joint, angle) in [("hip_pitch", -0.3), ("knee", 0.6), ("ankle_pitch", -0.3)] {
        for side in ["left", "right"] {
            q[ik.joint_index(&format!("{side}_{joint}_joint"))?.0] = angle;
        }
    }
    let com = center_of_mass(model, &mut data, &q, None)?.position; // also the body poses
    let pose = |data: &Data, link| data.body_pose(model.body_id(link).unwrap());
    let (left, right) = (
        pose(&data, "left_ankle_roll_link"),
        pose(&data, "right_ankle_roll_link"),
    );

    let step = Translation3::new(0.10, 0.0, 0.05) * left;
    ik.frame_pose("left_ankle_roll_link", step)?;
    ik.frame_pose("right_ankle_roll_link", right)?;
    ik.com(com)?;
    ik.posture(&q, 1e-2)?;
    for _ in 0..300 {
        ik.step(&mut q, 0.01)?; // 300 steps of 10 ms, half the error removed per step
    }

    update_placements(model, &mut data, &q)?;
    let miss =
        (pose(&data, "left_ankle_roll_link").translation.vector - step.translation.vector).norm();
    let knee = q[ik.joint_index("left_knee_joint")?.0];
    println!(
        "G1 ({} DoF): left foot {miss:.1e} m from its target, left knee {knee:.3} rad",
        model.nv()
    );
    println!(
        "smallest distance of a joint to its URDF limit: {:.3}",
        ik.limits().min_margin(&q)
    );
    if miss > 1e-6 || ik.limits().min_margin(&q) < ik.limits().settings().margin - 1e-9 {
        return Err("target missed or a joint limit left".into());
    }
    Ok(())
}
