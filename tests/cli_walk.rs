//! `biped walk`: summary.json with the four methods and their fields, CSV and SVG files; bad
//! arguments fail with one line.

use std::process::Command;

fn biped() -> Command {
    Command::new(env!("CARGO_BIN_EXE_biped"))
}

#[test]
fn two_steps_write_summary_csv_and_svg() {
    let dir = std::env::temp_dir().join(format!("biped_walk_{}", std::process::id()));
    let out = biped()
        .args(["walk", "--steps", "2", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    for m in ["none", "reference", "compensation", "minimization"] {
        for key in [
            "peak_abs_Lz",
            "peak_abs_dLz",
            "peak_abs_tau_z",
            "min_distance",
            "ik_us_median",
            "ik_us_p99",
        ] {
            let x = v[m][key].as_f64().unwrap_or(f64::NAN);
            assert!(x.is_finite(), "{m}.{key} = {x}");
        }
        let csv = std::fs::read_to_string(dir.join(format!("{m}.csv"))).unwrap();
        assert!(csv.lines().next().unwrap().contains("tau_z"));
        assert!(csv.lines().count() > 1000);
    }
    for svg in ["lz.svg", "tau_z.svg"] {
        let s = std::fs::read_to_string(dir.join(svg)).unwrap();
        assert!(s.contains("<svg"));
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_arguments_fail_with_one_line() {
    for args in [
        vec!["walk", "--method", "foo"],
        vec!["walk", "--steps", "0"],
        vec!["walk", "--step-time=-1"],
        vec!["walk", "--step-length=nan"],
        vec!["walk", "--dynamic"],
    ] {
        let out = biped().args(&args).output().unwrap();
        assert!(!out.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
    }
}
