//! End-to-end tests of `biped simulate`: outputs and their consistency (CSV vs summary, per-foot
//! forces vs total, contact force vs the weight from the model's masses), the integrators' step
//! and rhs counts, the URDF path (Unitree G1), integrator failure and one-line input errors.

mod common;

use biped_robots::lola::{self, LolaType};
use common::run;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Output;

/// Runs `biped simulate ARGS --out <tmp>/<name>`; returns the output and the folder.
fn simulate(name: &str, args: &[&str]) -> (Output, PathBuf) {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_simulate")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    let out_dir = dir.to_str().expect("utf8 path").to_string();
    let mut all = vec!["simulate", "--out", &out_dir];
    all.extend_from_slice(args);
    (run(&all, ""), dir)
}

/// Asserts success and returns `summary.json`.
fn summary(out: &Output, dir: &Path) -> Value {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(dir.join("summary.json")).expect("summary.json");
    serde_json::from_str(&text).expect("summary is JSON")
}

fn num(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} is a number: {v}"))
}

/// The CSV as header names and rows of numbers.
fn csv(dir: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(dir.join("signals.csv")).expect("signals.csv");
    let mut lines = text.lines();
    let header = lines
        .next()
        .expect("header")
        .split(',')
        .map(String::from)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(|x| x.parse().expect("number")).collect())
        .collect();
    (header, rows)
}

/// Column `name` of a parsed CSV.
fn column(csv: &(Vec<String>, Vec<Vec<f64>>), name: &str) -> Vec<f64> {
    let i = csv
        .0
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("column {name}"));
    csv.1.iter().map(|r| r[i]).collect()
}

/// Exit status non-zero, exactly one stderr line containing every piece of `expected`.
fn fails_with(name: &str, args: &[&str], expected: &[&str]) {
    let (out, _) = simulate(name, args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{args:?} succeeded");
    assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    for e in expected {
        assert!(err.contains(e), "{args:?}: {err} lacks {e}");
    }
}

#[test]
fn short_stand_writes_csv_plots_and_a_consistent_summary() {
    let (out, dir) = simulate("stand", &["--lola", "type2", "--duration", "0.2"]);
    let s = summary(&out, &dir);
    // Weight from the model's own masses, independent of the simulation.
    let model = lola::build(LolaType::Type2).unwrap().model;
    let mass: f64 = model.bodies().iter().map(|b| b.inertia().mass()).sum();
    let weight = mass * 9.81;
    assert!((num(&s, "weight") - weight).abs() < 1e-9 * weight);
    let fz = num(&s, "final_contact_force");
    assert!(
        (fz - weight).abs() < 0.01 * weight,
        "contact {fz} vs weight {weight}"
    );
    assert!(num(&s, "max_contact_force") >= fz);
    // 200 periods of 1 ms, one RK4 step (4 rhs) each.
    assert!((num(&s, "sim_time") - 0.2).abs() < 1e-12);
    assert_eq!(s["steps"].as_u64(), Some(200));
    assert_eq!(s["rhs_evaluations"].as_u64(), Some(800));
    let rtf = num(&s, "realtime_factor");
    assert!(
        (rtf * num(&s, "wall_time") - 0.2).abs() < 1e-9,
        "rtf = sim / wall"
    );
    assert_eq!(s["scenario"], "stand");
    assert_eq!(s["method"], "rk4");
    assert!(s["passed"].is_boolean() && s["checks"].as_array().unwrap().len() == 3);
    // Lola's drives have no effort or speed limits in torque mode: nothing is cut.
    assert_eq!(s["drive_limits"]["cycles"].as_u64(), Some(0));
    assert!(s["drive_limits"]["most"].is_null());
    // The CSV: one row per period plus the end, the forces of the feet and toes (each contact
    // entry on its own body) summing to the total.
    let table = csv(&dir);
    assert_eq!(table.0[0], "time");
    assert_eq!(table.1.len(), 201);
    let time = column(&table, "time");
    assert!(time.windows(2).all(|w| (w[1] - w[0] - 1e-3).abs() < 1e-12));
    let entries =
        ["left", "right", "left_toe", "right_toe"].map(|e| column(&table, &format!("{e}.fz")));
    let total = column(&table, "contact.fz");
    for k in 0..total.len() {
        let sum: f64 = entries.iter().map(|c| c[k]).sum();
        assert!((sum - total[k]).abs() < 1e-9 * weight);
    }
    assert!(entries[2][200] > 0.01 * weight, "the toes carry load");
    assert!((total[200] - fz).abs() < 1e-9 * weight, "CSV end = summary");
    let base = column(&table, "q[root.z]");
    assert!((base[200] - num(&s, "final_base_height")).abs() < 1e-15);
    let com = column(&table, "com.z");
    assert!((com[200] - num(&s, "final_com_height")).abs() < 1e-12);
    // The final state: time, and q / v equal to the CSV's last row.
    let fin = &s["final"];
    assert!((num(fin, "t") - 0.2).abs() < 1e-12);
    let (q, v) = (fin["q"].as_array().unwrap(), fin["v"].as_array().unwrap());
    assert_eq!(q[2].as_f64(), Some(base[200]));
    let shank = table.0.iter().position(|c| c == "v[l_shank]").unwrap();
    let v_names: Vec<&String> = table.0.iter().filter(|c| c.starts_with("v[")).collect();
    assert_eq!(v.len(), v_names.len());
    let k = v_names.iter().position(|c| *c == "v[l_shank]").unwrap();
    assert_eq!(v[k].as_f64(), Some(table.1[200][shank]));
    // Plots: every listed SVG exists and carries its legend labels.
    let files: Vec<&str> = s["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_str().unwrap())
        .collect();
    for (file, label) in [
        ("base_height.svg", "base z"),
        ("com_height.svg", "CoM z"),
        ("contact_forces.svg", "right.fz"),
        ("foot_shear.svg", "left.fy"),
        ("foot_torques.svg", "left.tz"),
        ("angular_momentum.svg", "L_G.z"),
        ("joint_angles.svg", "shank"),
        ("motor_currents.svg", "shank"),
    ] {
        assert!(files.contains(&file), "{file} listed");
        let svg = std::fs::read_to_string(dir.join(file)).unwrap();
        assert!(svg.starts_with("<svg") && svg.contains(label), "{file}");
    }
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("realtime factor") && stdout.contains("summary.json"));
}

#[test]
fn drop_lands_and_sway_runs() {
    let (out, dir) = simulate("drop", &["--scenario", "drop", "--duration", "0.3"]);
    let s = summary(&out, &dir);
    let base = column(&csv(&dir), "q[root.z]");
    assert!(
        base[0] - base[base.len() - 1] > 0.04,
        "fell about 5 cm: {base:?}"
    );
    assert!(
        num(&s, "max_contact_force") > num(&s, "weight"),
        "landing impact"
    );
    let (out, dir) = simulate("sway", &["--scenario", "sway", "--duration", "0.3"]);
    let s = summary(&out, &dir);
    assert_eq!(s["scenario"], "sway");
    assert!(
        num(&s, "final_contact_force") > 0.5 * num(&s, "weight"),
        "still standing"
    );
}

#[test]
fn every_integrator_is_accepted_with_its_rhs_count() {
    for (method, rhs_per_step) in [("euler", 1), ("symplectic", 1), ("rk4", 4), ("dopri5", 0)] {
        let args = ["--integrator", method, "--duration", "0.02"];
        let (out, dir) = simulate(method, &args);
        let s = summary(&out, &dir);
        assert_eq!(s["method"], method);
        let (steps, rhs) = (
            s["steps"].as_u64().unwrap(),
            s["rhs_evaluations"].as_u64().unwrap(),
        );
        if rhs_per_step > 0 {
            assert_eq!(steps, 20, "{method}: one step per 1 ms period");
            assert_eq!(rhs, rhs_per_step * steps, "{method}");
            assert_eq!(num(&s, "step"), 1e-3);
        } else {
            assert!(
                steps >= 1 && rhs >= 6 * steps,
                "dopri5: {steps} steps, {rhs} rhs"
            );
            assert_eq!(num(&s["tolerances"], "rtol"), 1e-6);
        }
    }
}

/// Without --duration, stand runs its own 3 s and comes to rest with its weight on the soles.
#[test]
fn default_stand_meets_its_pass_criteria() {
    let (out, dir) = simulate("stand_default", &["--check"]);
    let s = summary(&out, &dir);
    assert_eq!(num(&s, "sim_time"), 3.0);
    assert_eq!(s["passed"], true, "{}", s["checks"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        !text.contains("hint:") && !text.contains("fastest `"),
        "{text}"
    );
}

/// The rotor-less G1 does not come to rest (its ankle roll moves ~1e-4 kg m^2, so the 1 kHz
/// hold caps its gains): the failed rest check names the fastest joint, `summary.json` has
/// it, and a hint line gives the capped gains and points at `--armature`.
#[test]
fn failed_rest_check_names_the_joint_and_the_capped_gains() {
    let (out, dir) = simulate_g1("g1_no_rotors", &["--duration", "1", "--check"]);
    assert!(!out.status.success(), "stand --check fails without rotors");
    let text = String::from_utf8_lossy(&out.stdout);
    let s: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).expect("file"))
            .expect("JSON");
    let joint = s["final_fastest"]
        .as_str()
        .expect("fastest coordinate named");
    assert!(joint.ends_with("_joint"), "an actuated joint: {joint}");
    let failed = "FAILED: final max |v| below";
    let line = text
        .lines()
        .find(|l| l.contains(failed))
        .expect("rest check");
    assert!(line.ends_with(&format!(", fastest `{joint}`")), "{line}");
    let hint = text
        .lines()
        .find(|l| l.contains("hint:"))
        .expect("hint line");
    assert!(
        hint.contains(&format!("caps `{joint}`'s gains at k_p ")) && hint.contains("--armature"),
        "{hint}"
    );
}

#[test]
fn every_nth_period_and_the_end_are_recorded() {
    for (duration, rows, last_gap) in [("0.2", 21, 0.01), ("0.205", 22, 0.005)] {
        let args = [
            "--scenario",
            "drop",
            "--duration",
            duration,
            "--every",
            "10",
        ];
        let (out, dir) = simulate("every", &args);
        let s = summary(&out, &dir);
        let time = column(&csv(&dir), "time");
        assert_eq!(time.len(), rows, "{duration}");
        assert!(time[..rows - 1]
            .windows(2)
            .all(|w| (w[1] - w[0] - 0.01).abs() < 1e-12));
        assert!((time[rows - 1] - time[rows - 2] - last_gap).abs() < 1e-12);
        assert!((time[rows - 1] - num(&s, "sim_time")).abs() < 1e-12);
    }
}

#[test]
fn type3_defaults_to_a_tenth_of_a_millisecond() {
    let (out, dir) = simulate("type3", &["--lola", "type3", "--duration", "0.01"]);
    let s = summary(&out, &dir);
    assert_eq!(s["steps"].as_u64(), Some(100));
    assert_eq!(s["layout"]["nv"].as_u64(), Some(47));
}

/// The bundled Unitree G1.
const G1: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/crates/dynamics/data/g1_29dof_rev_1_0.urdf"
);

/// `biped simulate` on the G1 in a bent-knee pose, soles spanning its URDF contact spheres (as
/// the library's `sim_urdf` tests), with `extra` options.
fn simulate_g1(name: &str, extra: &[&str]) -> (Output, PathBuf) {
    let pose: Vec<String> = ["left", "right"]
        .iter()
        .flat_map(|s| {
            [("hip_pitch", -0.2), ("knee", 0.4), ("ankle_pitch", -0.2)]
                .map(|(j, a)| format!("{s}_{j}_joint={a}"))
        })
        .collect();
    let pose = pose.join(",");
    let mut args = vec![
        "--urdf",
        G1,
        "--floating",
        "--feet",
        "left_ankle_roll_link,right_ankle_roll_link",
        "--sole-center",
        "0.035,0,-0.035",
        "--sole-size",
        "0.17,0.055",
        "--pose",
        &pose,
    ];
    args.extend_from_slice(extra);
    simulate(name, &args)
}

#[test]
fn urdf_robot_stands_on_its_soles() {
    let (out, dir) = simulate_g1("g1", &["--duration", "0.3"]);
    let s = summary(&out, &dir);
    assert_eq!(s["actuators"].as_u64(), Some(29));
    assert_eq!(s["layout"]["ncontact"].as_u64(), Some(32));
    let w = num(&s, "weight");
    let table = csv(&dir);
    let fz = column(&table, "contact.fz");
    assert!(
        fz.iter().all(|f| (f - w).abs() < 0.3 * w),
        "the soles carry the robot without bouncing: {fz:?}"
    );
    assert!((fz[fz.len() - 1] - w).abs() < 0.05 * w);
    let knee = column(&table, "q[left_knee_joint]");
    assert!(
        knee.iter().all(|q| (q - 0.4).abs() < 0.05),
        "knee held: {knee:?}"
    );
}

/// `--armature` adds rotor bodies and leaves the coordinates alone; the G1 with its motors'
/// rotor inertia and a 20 rad/s PD passes `stand --check` (exit status 0).
#[test]
fn urdf_rotors_from_armature() {
    let armature = "*_hip_pitch_joint=0.0102,*_hip_yaw_joint=0.0102,waist_yaw_joint=0.0102,\
                    *_hip_roll_joint=0.0251,*_knee_joint=0.0251,*_ankle_*=0.00722,\
                    waist_*=0.00722,*_wrist_pitch_joint=0.00425,*_wrist_yaw_joint=0.00425,\
                    *=0.00361";
    let extra = ["--armature", armature, "--bandwidth", "20", "--check"];
    let (out, dir) = simulate_g1("g1_rotors", &extra);
    let s = summary(&out, &dir);
    assert_eq!(s["layout"]["nv"].as_u64(), Some(35));
    assert_eq!(s["actuators"].as_u64(), Some(29));
    let checks = s["checks"].as_array().expect("checks");
    assert!(checks.iter().all(|c| c["passed"] == true), "{s}");
}

/// An SRDF's rotors (`N^2 J`) and group state give bitwise the same run as the equivalent
/// `--armature` and `--pose` (values exact in binary); its entries for joints the URDF does
/// not move are skipped with a warning, the free-flyer's value is left to the scenario.
#[test]
fn srdf_rotors_and_group_state_match_armature_and_pose() {
    let bent = [("hip_pitch", -0.25), ("knee", 0.5), ("ankle_pitch", -0.25)];
    let joints: Vec<(String, f64)> = ["left", "right"]
        .iter()
        .flat_map(|s| bent.map(|(j, a)| (format!("{s}_{j}_joint"), a)))
        .collect();
    let state: String = joints
        .iter()
        .map(|(j, a)| format!("    <joint name=\"{j}\" value=\"{a}\"/>\n"))
        .collect();
    let srdf = format!(
        "<robot name=\"g1\">\n  <group_state name=\"bent\" group=\"all\">\n    \
         <joint name=\"root_joint\" value=\"0 0 0.8 0 0 0 1\"/>\n{state}    \
         <joint name=\"no_such_joint\" value=\"1\"/>\n  </group_state>\n  <rotor_params>\n    \
         <joint name=\"left_knee_joint\" mass=\"0.015625\" gear_ratio=\"2\"/>\n    \
         <joint name=\"right_knee_joint\" mass=\"0.015625\" gear_ratio=\"2\"/>\n    \
         <joint name=\"no_such_joint\" mass=\"1\" gear_ratio=\"1\"/>\n  </rotor_params>\n</robot>\n"
    );
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_simulate");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("g1.srdf");
    std::fs::write(&file, srdf).unwrap();
    let pose: Vec<String> = joints.iter().map(|(j, a)| format!("{j}={a}")).collect();
    let base = [
        "--urdf",
        G1,
        "--floating",
        "--feet",
        "left_ankle_roll_link,right_ankle_roll_link",
        "--duration",
        "0.2",
    ];
    let by_hand = [
        "--pose",
        &pose.join(","),
        "--armature",
        "left_knee_joint=0.0625,right_knee_joint=0.0625",
    ];
    let by_srdf = ["--srdf", file.to_str().unwrap(), "--srdf-state", "bent"];
    let runs: Vec<(Value, Vec<Vec<f64>>, String)> = [&by_hand[..], &by_srdf[..]]
        .iter()
        .enumerate()
        .map(|(k, extra)| {
            let args: Vec<&str> = base.iter().chain(extra.iter()).copied().collect();
            let (out, dir) = simulate(&format!("g1_srdf_{k}"), &args);
            let stderr = String::from_utf8_lossy(&out.stderr).to_string();
            (summary(&out, &dir), csv(&dir).1, stderr)
        })
        .collect();
    assert_eq!(runs[0].1.last(), runs[1].1.last(), "same final row");
    assert_eq!(runs[0].0["final_com"], runs[1].0["final_com"]);
    let warnings = &runs[1].2;
    assert!(
        warnings.contains("g1.srdf:15: 1 rotor_params entries")
            && warnings.contains("`no_such_joint`")
            && warnings.contains("g1.srdf:2: group_state `bent` sets 1 joints"),
        "{warnings}"
    );
}

/// `--friction MU` bounds every foot's tangential force by `mu F_z` (each sole point's force
/// lies in its cone, so their sums do), and on the sway the bound is reached.
#[test]
fn ground_friction_bounds_the_foot_shear() {
    let mu = 0.05;
    let args = [
        "--lola",
        "type2",
        "--scenario",
        "sway",
        "--friction",
        "0.05",
    ];
    let (out, dir) = simulate("friction", &args);
    summary(&out, &dir);
    let table = csv(&dir);
    let mut worst = 0.0f64;
    for foot in ["left", "right"] {
        let [fx, fy, fz] = ["fx", "fy", "fz"].map(|c| column(&table, &format!("{foot}.{c}")));
        for k in 0..fz.len() {
            let shear = fx[k].hypot(fy[k]);
            assert!(shear <= mu * fz[k] * (1.0 + 1e-9) + 1e-9, "{foot} row {k}");
            if fz[k] > 1.0 {
                worst = worst.max(shear / fz[k]);
            }
        }
    }
    assert!(worst > 0.99 * mu, "the cone is reached: {worst}");
}

/// Each `--plot` writes one SVG of the columns its names and patterns match (each column
/// once, in the order asked), listed in the summary's files.
#[test]
fn chosen_signals_are_plotted() {
    let args = [
        "--lola",
        "type2",
        "--duration",
        "0.05",
        "--plot",
        "q[l_shank],com.z",
        "--plot",
        "left.f*,left.fz",
    ];
    let (out, dir) = simulate("plots", &args);
    let s = summary(&out, &dir);
    let files = s["files"].as_array().unwrap();
    for (k, labels, absent) in [
        (1, &["q[l_shank]", "com.z"][..], "left.fx"),
        (2, &["left.fx", "left.fy", "left.fz"][..], "left.tx"),
    ] {
        let file = format!("plot_{k}.svg");
        assert!(files.iter().any(|f| f == &file), "{file} listed");
        let svg = std::fs::read_to_string(dir.join(&file)).unwrap();
        for l in labels {
            assert!(svg.contains(&format!("\n{l}\n")), "{file}: legend {l}");
        }
        assert!(
            !svg.contains(&format!("\n{absent}\n")),
            "{file}: not {absent}"
        );
        assert_eq!(svg.matches("\nleft.fz\n").count(), usize::from(k == 2));
    }
}

#[test]
fn failures_and_criteria_set_the_exit_status() {
    // Explicit Euler at 1 ms on Type 3's stiff gears diverges: one line, partial CSV kept.
    let args = [
        "--lola",
        "type3",
        "--integrator",
        "euler",
        "--step",
        "1e-3",
        "--duration",
        "0.2",
    ];
    fails_with(
        "diverges",
        &args,
        &["simulation failed after t =", "signals.csv"],
    );
    // Still falling after 50 ms: the rest criterion fails; only --check turns it into status 1.
    let args = ["--scenario", "drop", "--duration", "0.05"];
    let (out, dir) = simulate("drop_check", &args);
    assert_eq!(summary(&out, &dir)["passed"], false);
    let (out, _) = simulate("drop_check", &[&args[..], &["--check"]].concat());
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stdout).contains("FAILED"));
}

#[test]
fn default_output_folder_is_per_scenario() {
    let cwd = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let dir = cwd.join("out/simulate/drop");
    let _ = std::fs::remove_dir_all(&dir);
    let out = run(
        &["simulate", "--scenario", "drop", "--duration", "0.005"],
        "",
    );
    summary(&out, &dir);
    // An output folder that cannot be created: one line naming it.
    let file = cwd.join("cli_simulate_not_a_folder");
    std::fs::write(&file, "").unwrap();
    let bad = file.join("sub");
    let out = run(
        &[
            "simulate",
            "--duration",
            "0.005",
            "--out",
            bad.to_str().unwrap(),
        ],
        "",
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && err.lines().count() == 1, "{err}");
    assert!(err.contains("cli_simulate_not_a_folder/sub"), "{err}");
}

#[test]
fn bad_inputs_fail_with_one_line() {
    let g1 = G1;
    let feet = "left_ankle_roll_link,right_ankle_roll_link";
    let cases: &[(&[&str], &[&str])] = &[
        (&["--scenario", "walk"], &["--scenario", "walk"]),
        (&["--integrator", "rk5"], &["--integrator", "rk5"]),
        (&["--lola", "type4"], &["--lola", "type4"]),
        (&["--duration", "-1"], &["--duration", "-1"]),
        (&["--duration", "soon"], &["--duration", "soon"]),
        (&["--duration", "1e-5"], &["--duration", "control period"]),
        (&["--step", "0"], &["--step"]),
        (
            &["--integrator", "dopri5", "--step", "1e-3"],
            &["--step", "dopri5"],
        ),
        (&["--tolerances", "1e-3,1e-3"], &["--tolerances"]),
        (
            &["--integrator", "dopri5", "--tolerances", "-1,0"],
            &["--tolerances", "rtol"],
        ),
        (&["--pose", "no_joint=0.1"], &["--pose", "no_joint"]),
        (&["--pose", "l_shank"], &["--pose", "JOINT=ANGLE"]),
        (&["--feet", feet], &["--feet", "--urdf"]),
        (
            &[
                "--urdf",
                "/no/such/robot.urdf",
                "--floating",
                "--feet",
                feet,
            ],
            &["/no/such/robot.urdf"],
        ),
        (&["--urdf", g1, "--feet", feet], &["--floating"]),
        (&["--urdf", g1, "--floating"], &["--feet"]),
        (
            &[
                "--urdf",
                g1,
                "--floating",
                "--feet",
                "left_toe,right_ankle_roll_link",
            ],
            &["--feet", "left_toe", "g1_29dof"],
        ),
        (
            &["--urdf", g1, "--floating", "--feet", "one_link"],
            &["--feet", "LEFT,RIGHT"],
        ),
        (&["--urdf", g1, "--lola", "type2"], &["--lola", "--urdf"]),
        (&["--every", "0"], &["--every", "whole number"]),
        (&["--every", "1.5"], &["--every"]),
        (&["--contact", "-1,0"], &["--contact", "stiffness"]),
        (&["--contact", "1e5"], &["--contact", "2 comma-separated"]),
        (&["--bandwidth", "0"], &["--bandwidth", "> 0"]),
        (
            &["--armature", "*=0.01"],
            &["--armature", "only applies with --urdf"],
        ),
        (&["--bandwidth", "-3"], &["--bandwidth", "> 0"]),
        (
            &["--no-end-stops"],
            &["--no-end-stops", "only applies with --urdf"],
        ),
        (
            &["--scenario", "sway", "--sway", "0.6,2"],
            &["sway amplitude", "l_hip_adduction", "outside its range"],
        ),
        (
            &["--scenario", "sway", "--sway", "0.1"],
            &["--sway", "2 comma"],
        ),
        (
            &["--scenario", "sway", "--sway", "0.1,0"],
            &["--sway", "period"],
        ),
        (
            &["--sway", "0.1,2"],
            &["--sway", "only applies with --scenario sway"],
        ),
        (
            &["--no-joint-friction"],
            &["--no-joint-friction", "only applies with --urdf"],
        ),
        (
            &["--srdf", "x.srdf"],
            &["--srdf", "only applies with --urdf"],
        ),
    ];
    for (args, expected) in cases {
        fails_with("bad", args, expected);
    }
    // An SRDF without group states (the G1 URDF itself is rejected as an SRDF).
    let no_states = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("no_states.srdf");
    std::fs::write(&no_states, "<robot name=\"g1\"><rotor_params/></robot>\n").unwrap();
    let no_states = no_states.to_str().unwrap();
    // The same, after `--urdf G1 --floating --feet LEFT,RIGHT`.
    let on_g1: &[(&[&str], &[&str])] = &[
        (&["--scenario", "sway"], &["--sway-joints"]),
        (&["--sole-size", "0.1"], &["--sole-size"]),
        (&["--armature", "*_knee"], &["--armature", "JOINT=KG_M2"]),
        (
            &["--armature", "*_knee_jiont=0.02"],
            &[
                "--armature",
                "*_knee_jiont",
                "matches no revolute joint",
                "g1_29dof",
            ],
        ),
        (
            &["--armature", "*_knee_joint=-0.02"],
            &["--armature", "*_knee_joint", ">= 0"],
        ),
        (
            &["--srdf-state", "half_sitting"],
            &["--srdf-state", "needs --srdf"],
        ),
        (
            &["--srdf", "/no/such.srdf"],
            &["--srdf", "/no/such.srdf", "cannot read SRDF"],
        ),
        (
            &["--srdf", no_states, "--srdf-state", "bent"],
            &["--srdf-state", "no group_state `bent`", "(it has: none)"],
        ),
        (&["--srdf", G1], &["--srdf", "looks like a URDF"]),
    ];
    for (extra, expected) in on_g1 {
        let mut args = vec!["--urdf", g1, "--floating", "--feet", feet];
        args.extend_from_slice(extra);
        fails_with("bad", &args, expected);
    }
}

/// The G1's URDF ranges become end stops (one per revolute joint of the file, reported in the
/// summary); a joint damping the 1 ms RK4 step cannot integrate is a one-line error naming the
/// joint, and `--no-joint-friction` drops it.
#[test]
fn urdf_limits_and_joint_damping() {
    let (out, dir) = simulate_g1("g1_limits", &["--duration", "0.05"]);
    let s = summary(&out, &dir);
    let text = std::fs::read_to_string(G1).unwrap();
    let revolute = text.matches("type=\"revolute\"").count() as u64;
    assert_eq!(s["passive"]["end_stops"].as_u64(), Some(revolute));
    assert_eq!(s["passive"]["friction_laws"].as_u64(), Some(0));
    let (out, dir) = simulate_g1("g1_no_stops", &["--duration", "0.05", "--no-end-stops"]);
    assert_eq!(
        summary(&out, &dir)["passive"]["end_stops"].as_u64(),
        Some(0)
    );

    // 5 N m s/rad on the wrist (free inertia ~1e-3 kg m^2): a rate of thousands per second.
    let joint = "<joint name=\"left_wrist_yaw_joint\" type=\"revolute\">";
    assert!(text.contains(joint));
    let damped = text.replacen(joint, &format!("{joint}<dynamics damping=\"5\"/>"), 1);
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_simulate");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("g1_damped_wrist.urdf");
    std::fs::write(&file, damped).unwrap();
    let file = file.to_str().unwrap();
    let args = [
        "--urdf",
        file,
        "--floating",
        "--feet",
        "left_ankle_roll_link,right_ankle_roll_link",
        "--duration",
        "0.05",
    ];
    fails_with(
        "g1_damped",
        &args,
        &[
            "joint `left_wrist_yaw_joint` damping and friction",
            "rk4 step below",
        ],
    );
    let mut outside = args.to_vec();
    outside.extend(["--no-joint-friction", "--pose", "left_knee_joint=-0.5"]);
    fails_with(
        "g1_outside",
        &outside,
        &["pose `left_knee_joint`", "outside the joint range"],
    );
    let mut quiet = args.to_vec();
    quiet.push("--no-joint-friction");
    let (out, dir) = simulate("g1_damped_off", &quiet);
    assert_eq!(
        summary(&out, &dir)["passive"]["friction_laws"].as_u64(),
        Some(0)
    );
}

/// The IMU damping through the ankles is on by default and reported; `--no-stance-damping`
/// turns it off (no report line, other commands).
#[test]
fn stance_damping_is_reported_and_can_be_turned_off() {
    let base = ["--lola", "type2", "--duration", "0.05"];
    let (on, dir_on) = simulate("stance_on", &base);
    let mut args = base.to_vec();
    args.push("--no-stance-damping");
    let (off, dir_off) = simulate("stance_off", &args);
    let text = |o: &Output| String::from_utf8_lossy(&o.stdout).to_string();
    assert!(
        text(&on).contains("stance damping: 4 ankles, gain "),
        "{}",
        text(&on)
    );
    assert!(!text(&off).contains("stance damping"), "{}", text(&off));
    let ankle = |dir: &Path| column(&csv(dir), "cmd[l_foot]");
    assert_ne!(ankle(&dir_on), ankle(&dir_off));
    let _ = (summary(&on, &dir_on), summary(&off, &dir_off));
}
