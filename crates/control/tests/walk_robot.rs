//! [`WalkRobot`]: the Lola robot keeps the Lola walk's pattern; the bundled G1 description gives
//! a robot with sole frames on its soles, a pattern geometry from its legs, and a short walk
//! that keeps every verdict; a description the walk cannot use fails naming its file.

use biped_control::pattern::WalkingPattern;
use biped_control::walk::{
    run_walk_robot, walk_pattern_params, Method, WalkError, WalkParams, WalkRobot,
};
use biped_dynamics::{update_placements, Data};
use biped_robots::description::Robot;
use biped_robots::lola::{build, LolaType};

#[test]
fn lola_robot_keeps_the_lola_pattern() {
    let lola = build(LolaType::Type2).unwrap();
    let robot = WalkRobot::lola(&lola).unwrap();
    let params = robot.pattern_params(4, 0.4, 0.8);
    assert_eq!(params, walk_pattern_params(&lola, 4, 0.4, 0.8).unwrap());
    assert_eq!(robot.natural_step_length, 0.4);
    assert_eq!(robot.joints.len(), lola.limits.len());
}

#[test]
fn g1_robot_walks_with_its_own_geometry() {
    let g1 = Robot::load(Robot::bundled("g1").unwrap()).unwrap();
    let robot = WalkRobot::from_description(&g1).unwrap();
    // the sole frames lie on the sole plane in the comfort pose, level with each other
    let mut data = Data::new(&robot.model);
    update_placements(&robot.model, &mut data, &robot.posture).unwrap();
    let z = robot
        .frames
        .soles
        .map(|f| (data.world_pos[f.body] + data.world_rot[f.body] * f.offset.translation.vector).z);
    assert!((z[0] - z[1]).abs() < 1e-9);
    assert!(
        robot.com_height > 0.5 && robot.com_height < 0.8,
        "{}",
        robot.com_height
    );
    assert!(
        robot.step_width > 0.15 && robot.step_width < 0.3,
        "{}",
        robot.step_width
    );
    let step = robot.natural_step_length;
    assert!(
        step > 0.1 && step < robot.reach,
        "{step} vs {}",
        robot.reach
    );
    assert!(robot.frames.toes.is_none());
    // the three waist joints are held by joint tasks
    assert_eq!(robot.frames.joints.iter().flatten().count(), 3);

    let params = robot.pattern_params(2, step, 0.8);
    let pattern = WalkingPattern::generate(&params).unwrap();
    let run = run_walk_robot(
        &robot,
        &pattern,
        Method::Compensation,
        WalkParams::default(),
    )
    .unwrap();
    let s = &run.summary;
    assert_eq!(s.cycles, pattern.len());
    assert!(s.min_distance > 0.0 && s.min_joint_margin >= 0.0, "{s:?}");
    assert!(s.verdicts.violations().is_empty(), "{s:?}");
    assert_eq!(run.series.joint_names.len(), 14 + 3);
}

#[test]
fn a_description_without_collision_model_names_its_file() {
    let path = Robot::bundled("g1").unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let start = text.find("[collision]").unwrap();
    let end = text.find("[drives]").unwrap();
    let text = format!("{}{}", &text[..start], &text[end..]);
    let packages = biped_robots::description::search_path(Vec::new());
    let g1 = Robot::parse(&text, "bare.toml", path.parent().unwrap(), &packages).unwrap();
    match WalkRobot::from_description(&g1) {
        Err(WalkError::Description(m)) => {
            assert!(m.starts_with("bare.toml: no [collision]"), "{m}")
        }
        other => panic!("{:?}", other.map(|r| r.name)),
    }
}
