//! The tables `biped walk` writes as CSV (and returns to Python): per method its series and
//! full trajectory, the dynamic walk's signals, the recordings for replay (docs/recording.md)
//! and the plots drawn from them.

use biped_control::walk::{DynamicWalkRun, DynamicWalkSeries, WalkRun, WalkSeries};
use biped_dynamics::Model;
use biped_sim::record::replay::{frame_rows, replay, FRAME_RATE};
use biped_sim::record::RecordError;
use biped_sim::Recorder;
use std::path::Path;

/// The dynamic walk's base, tilt and per-foot signals of cycle `k` (the columns of
/// `dynamic.csv`).
fn dynamic_row(s: &DynamicWalkSeries, k: usize) -> [(&'static str, f64); 20] {
    let [x, y, z] = s.base[k];
    [
        ("base_x", x),
        ("base_y", y),
        ("base_z", z),
        ("planned_base_x", s.planned_base_x[k]),
        ("trunk_tilt", s.tilt[k]),
        ("fz_left", s.foot_fz[k][0]),
        ("fz_right", s.foot_fz[k][1]),
        ("tau_z_left", s.tau_z[k][0]),
        ("tau_z_right", s.tau_z[k][1]),
        ("toe_fz_left", s.toe_fz[k][0]),
        ("toe_fz_right", s.toe_fz[k][1]),
        ("heel_lift_left", s.heel_lift[k][0]),
        ("heel_lift_right", s.heel_lift[k][1]),
        ("friction_usage_left", s.friction_usage[k][0]),
        ("friction_usage_right", s.friction_usage[k][1]),
        ("slip_speed_left", s.slip_speed[k][0]),
        ("slip_speed_right", s.slip_speed[k][1]),
        ("points_in_contact_left", s.points_in_contact[k][0] as f64),
        ("points_in_contact_right", s.points_in_contact[k][1] as f64),
        ("tracking_error", s.tracking_error[k]),
    ]
}

/// The table of `dynamic.csv`: the dynamic walk's base, tilt and per-foot signals.
pub fn dynamic_table(run: &DynamicWalkRun) -> Result<Recorder, RecordError> {
    let s = &run.series;
    let mut rec = Recorder::with_capacity(s.t.len());
    for k in 0..s.t.len() {
        rec.sample(s.t[k])?;
        for (name, v) in dynamic_row(s, k) {
            rec.set(name, v)?;
        }
    }
    Ok(rec)
}

/// The table of `dynamic_recording.csv` (docs/recording.md): the simulated motion, every body's
/// pose and the signals of `dynamic.csv` at [`FRAME_RATE`].
pub fn dynamic_recording(run: &DynamicWalkRun) -> Result<Recorder, RecordError> {
    let s = &run.series;
    let nq = s.q_names.len();
    let mut rec = Recorder::with_capacity(s.t.len());
    let q_ids = s
        .q_names
        .iter()
        .map(|n| rec.register(&format!("q[{n}]")))
        .collect::<Result<Vec<_>, _>>()?;
    for k in 0..s.t.len() {
        rec.sample(s.t[k])?;
        let q = s.q.get(k * nq..(k + 1) * nq).unwrap_or(&[]);
        for (id, v) in q_ids.iter().zip(q) {
            rec.set_id(*id, &[*v])?;
        }
        for (name, v) in dynamic_row(s, k) {
            rec.set(name, v)?;
        }
    }
    replay(&run.model, &rec, FRAME_RATE)
}

/// The plots of the dynamic walk's table: base x/z, trunk tilt, vertical foot forces, `tau_z`.
pub fn dynamic_plots(rec: &Recorder, out: &Path) -> Result<(), RecordError> {
    let plots: [(&[&str], &str, &str, &str); 4] = [
        (
            &["base_x", "planned_base_x", "base_z"],
            "base position [m]",
            "dynamic_base.svg",
            "base x (simulated, planned) and height",
        ),
        (
            &["trunk_tilt"],
            "tilt [rad]",
            "dynamic_tilt.svg",
            "trunk tilt",
        ),
        (
            &["fz_left", "fz_right"],
            "F_z [N]",
            "dynamic_fz.svg",
            "vertical foot forces",
        ),
        (
            &["tau_z_left", "tau_z_right"],
            "tau_z [N m]",
            "dynamic_tau_z.svg",
            "vertical torque on the feet (F/T sensors)",
        ),
    ];
    for (names, unit, file, title) in plots {
        rec.plot_svg(
            &out.join(file),
            &format!("dynamic walk: {title}"),
            names,
            unit,
        )?;
    }
    Ok(())
}

/// One method's momentum, torque, distance and friction signals of cycle `k`.
fn series_row(s: &WalkSeries, k: usize) -> [(&'static str, f64); 7] {
    [
        ("L_z", s.lz[k]),
        ("dL_z", s.dlz[k]),
        ("tau_z", s.tau_z[k]),
        ("min_distance", s.min_distance[k]),
        ("friction_usage", s.friction_usage[k]),
        ("task_error", s.task_error[k]),
        ("foot_lift", s.foot_lift[k]),
    ]
}

/// The table of `METHOD.csv`: one method's momentum, torque, distance and joint series.
pub fn series_table(run: &WalkRun) -> Result<Recorder, RecordError> {
    let s = &run.series;
    let mut rec = Recorder::with_capacity(s.t.len());
    for k in 0..s.t.len() {
        rec.sample(s.t[k])?;
        for (name, v) in series_row(s, k) {
            rec.set(name, v)?;
        }
        rec.set("zmp_x", s.zmp[k][0])?;
        rec.set("zmp_y", s.zmp[k][1])?;
        for (name, v) in s.joint_names.iter().zip(&s.joints[k]) {
            rec.set(name, *v)?;
        }
    }
    Ok(rec)
}

/// The table of `METHOD_recording.csv` (docs/recording.md): one method's motion, every body's
/// pose of `model`, CoM, ZMP, soles, ground wrench and the signals of `METHOD.csv` (but the
/// joints, which are the `q[NAME]` columns) at [`FRAME_RATE`].
pub fn recording_table(run: &WalkRun, model: &Model) -> Result<Recorder, RecordError> {
    let (tr, s) = (&run.trajectory, &run.series);
    let rows = frame_rows(&tr.t, FRAME_RATE);
    let mut rec = Recorder::with_capacity(rows.len());
    let columns = tr.columns();
    for k in rows {
        rec.sample(tr.t[k])?;
        for (name, v) in columns.iter().zip(tr.row(k)) {
            rec.set(name, v)?;
        }
        if k < s.t.len() {
            for (name, v) in series_row(s, k) {
                rec.set(name, v)?;
            }
        }
    }
    replay(model, &rec, FRAME_RATE)
}

/// The table of `METHOD_trajectory.csv`: one method's full motion (see docs/walking.md).
pub fn trajectory_table(run: &WalkRun) -> Result<Recorder, RecordError> {
    let tr = &run.trajectory;
    let columns = tr.columns();
    let mut rec = Recorder::with_capacity(tr.len());
    for k in 0..tr.len() {
        rec.sample(tr.t[k])?;
        for (name, v) in columns.iter().zip(tr.row(k)) {
            rec.set(name, v)?;
        }
    }
    Ok(rec)
}

/// `L_z` and `tau_z` of all methods over time, side by side (Fig. 7.1/7.4 style).
pub fn write_plots(runs: &[WalkRun], out: &Path) -> Result<(), RecordError> {
    let Some(first) = runs.first() else {
        return Ok(());
    };
    let mut rec = Recorder::with_capacity(first.series.t.len());
    for k in 0..first.series.t.len() {
        rec.sample(first.series.t[k])?;
        for r in runs {
            rec.set(&format!("L_z {}", r.method), r.series.lz[k])?;
            rec.set(&format!("tau_z {}", r.method), r.series.tau_z[k])?;
        }
    }
    for (sig, unit, file) in [
        ("L_z", "L_z [N m s]", "lz.svg"),
        ("tau_z", "tau_z [N m]", "tau_z.svg"),
    ] {
        let names: Vec<String> = runs.iter().map(|r| format!("{sig} {}", r.method)).collect();
        let refs: Vec<&str> = names.iter().map(String::as_str).collect();
        let title = format!("{sig} during walking, arm methods compared");
        rec.plot_svg(&out.join(file), &title, &refs, unit)?;
    }
    Ok(())
}
