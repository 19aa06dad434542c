//! Recorder: CSV round trip, vector expansion, NaN back-fill, SVG output and error paths.

use biped_sim::record::{write_whole, RecordError, Recorder};
use std::path::PathBuf;

/// Fresh scratch directory for this test binary.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("biped_record_{}_{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// Parses CSV text into its header and rows (independent of the writer).
fn parse(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines
        .next()
        .expect("header")
        .split(',')
        .map(str::to_string)
        .collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|v| v.parse::<f64>().expect("number"))
                .collect()
        })
        .collect();
    (header, rows)
}

/// A recorder with a scalar, a vector and a late signal, values with awkward digits.
fn sample_recorder() -> Recorder {
    let mut r = Recorder::with_capacity(8);
    let q = r.register_vector("q", 3).expect("register");
    for k in 0..5 {
        let t = 0.1 * k as f64;
        r.sample(t).expect("sample");
        r.set("energy", (t + 1.0 / 3.0).exp() * 1e-7).expect("set");
        r.set_id(q, &[t.sin(), std::f64::consts::PI * t, -1e300 * t])
            .expect("set_id");
        if k >= 3 {
            r.set("late", 1.0 / 7.0 + t).expect("late");
        }
    }
    r
}

#[test]
fn csv_round_trips_bit_exactly() {
    let r = sample_recorder();
    let dir = scratch("csv");
    let path = dir.join("nested/run.csv");
    r.write_csv(&path).expect("write");
    let (header, rows) = parse(&std::fs::read_to_string(&path).expect("read"));
    assert_eq!(header, ["time", "q[0]", "q[1]", "q[2]", "energy", "late"]);
    assert_eq!(rows.len(), 5);
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(row[0].to_bits(), r.time()[i].to_bits());
        for (c, name) in header[1..].iter().enumerate() {
            let col = r.column(name).expect("column");
            let same = row[c + 1].to_bits() == col[i].to_bits()
                || (row[c + 1].is_nan() && col[i].is_nan());
            assert!(same, "{name}[{i}]: {} vs {}", row[c + 1], col[i]);
        }
    }
    // The late signal is NaN before its first sample, set afterwards.
    let late = r.column("late").expect("late");
    assert!(late[..3].iter().all(|v| v.is_nan()) && late[3..].iter().all(|v| v.is_finite()));
    assert_eq!(r.signal_columns("q").expect("q").len(), 3);
    std::fs::remove_dir_all(dir).expect("cleanup");
}

#[test]
fn svg_plot_is_written_with_series_names() {
    let r = sample_recorder();
    let dir = scratch("svg");
    let path = dir.join("plot.svg");
    r.plot_svg(&path, "Test run", &["q[0]", "q[1]", "late"], "value [1]")
        .expect("plot");
    let svg = std::fs::read_to_string(&path).expect("read");
    assert!(
        svg.starts_with("<svg") || svg.contains("<svg"),
        "not an SVG"
    );
    for s in ["Test run", "q[0]", "q[1]", "late", "time [s]", "value [1]"] {
        assert!(svg.contains(s), "SVG lacks {s:?}");
    }
    assert!(svg.matches("<polyline").count() >= 3, "one line per signal");
    std::fs::remove_dir_all(dir).expect("cleanup");
}

#[test]
fn errors_are_typed() {
    let mut r = Recorder::new();
    assert!(matches!(r.set("x", 1.0), Err(RecordError::Empty)));
    assert!(matches!(
        r.write_csv(&scratch("e").join("x.csv")),
        Err(RecordError::Empty)
    ));
    r.sample(1.0).expect("sample");
    assert!(matches!(
        r.sample(0.5),
        Err(RecordError::InvalidTime { .. })
    ));
    assert!(matches!(
        r.sample(f64::NAN),
        Err(RecordError::InvalidTime { .. })
    ));
    r.set_vector("v", &[1.0, 2.0]).expect("vector");
    assert!(matches!(
        r.set_vector("v", &[1.0]),
        Err(RecordError::LengthMismatch {
            expected: 2,
            got: 1,
            ..
        })
    ));
    for bad in ["", "a,b", "time", "q\"", "v[0]"] {
        assert!(
            matches!(r.set(bad, 1.0), Err(RecordError::InvalidName(_))),
            "{bad:?}"
        );
    }
    assert!(matches!(
        r.column("nope"),
        Err(RecordError::UnknownSignal(_))
    ));
    let dir = scratch("err");
    assert!(matches!(
        r.plot_svg(&dir.join("p.svg"), "t", &["nope"], "y"),
        Err(RecordError::UnknownSignal(_))
    ));
    assert!(matches!(
        r.plot_svg(&dir.join("p.svg"), "t", &[], "y"),
        Err(RecordError::NoSignals)
    ));
    // A directory path cannot be created as a file: IO error naming the path.
    std::fs::create_dir_all(dir.join("d.csv")).expect("mkdir");
    match r.write_csv(&dir.join("d.csv")) {
        Err(RecordError::Io { path, .. }) => assert!(path.ends_with("d.csv")),
        other => panic!("{other:?}"),
    }
    std::fs::remove_dir_all(dir).expect("cleanup");
}

/// One recorder operation of the property test.
#[derive(Debug, Clone)]
enum Op {
    /// New row after a time step.
    Sample(f64),
    /// Register signal `k` (`s<k>`) with this length (1: scalar).
    Register(usize, usize),
    /// Set signal `k` in the current row to values starting at this number.
    Set(usize, f64),
    /// Map the reserved buffer ahead (`Recorder::prefault`): changes no value.
    Prefault,
}

fn op() -> impl proptest::strategy::Strategy<Value = Op> {
    use proptest::prelude::*;
    prop_oneof![
        (0.0f64..1.0).prop_map(Op::Sample),
        (0usize..5, 1usize..4).prop_map(|(k, n)| Op::Register(k, n)),
        (0usize..5, -9.0f64..9.0).prop_map(|(k, v)| Op::Set(k, v)),
        Just(Op::Prefault),
    ]
}

proptest::proptest! {
    /// Against a column-per-`Vec` reference model: random interleavings of registering
    /// (also after rows exist), sampling and setting give the same columns, NaN where unset,
    /// and the CSV holds the same rows bit for bit; prefaulting the reserved rows at any point
    /// changes nothing.
    #[test]
    fn matches_a_column_model(ops in proptest::collection::vec(op(), 1..60)) {
        let mut rec = Recorder::with_capacity(6);
        let mut lens: Vec<Option<usize>> = vec![None; 5];
        // Reference: column names in registration order and their values.
        let (mut names, mut cols): (Vec<String>, Vec<Vec<f64>>) = (Vec::new(), Vec::new());
        let mut t = 0.0;
        for op in ops {
            match op {
                Op::Sample(dt) => {
                    t += dt;
                    rec.sample(t).unwrap();
                    cols.iter_mut().for_each(|c| c.push(f64::NAN));
                }
                Op::Register(k, n) if lens[k].is_none() => {
                    rec.register_vector(&format!("s{k}"), n).unwrap();
                    lens[k] = Some(n);
                    for i in 0..n {
                        names.push(if n == 1 { format!("s{k}") } else { format!("s{k}[{i}]") });
                        cols.push(vec![f64::NAN; rec.len()]);
                    }
                }
                Op::Prefault => rec.prefault(),
                Op::Set(k, v) if lens[k].is_some() && !rec.is_empty() => {
                    let n = lens[k].unwrap();
                    let values: Vec<f64> = (0..n).map(|i| v + i as f64).collect();
                    rec.set_vector(&format!("s{k}"), &values).unwrap();
                    let first = names.iter().position(|c| c.starts_with(&format!("s{k}"))).unwrap();
                    for (i, x) in values.iter().enumerate() {
                        *cols[first + i].last_mut().unwrap() = *x;
                    }
                }
                _ => {}
            }
        }
        proptest::prop_assert_eq!(rec.column_names(), &names[..]);
        for (name, expect) in names.iter().zip(&cols) {
            let got = rec.column(name).unwrap();
            let same = got.iter().zip(expect).all(|(a, b)| a.to_bits() == b.to_bits());
            proptest::prop_assert!(same && got.len() == expect.len(), "{name}: {got:?} vs {expect:?}");
        }
        if !rec.is_empty() {
            let dir = scratch("prop");
            let path = dir.join("r.csv");
            rec.write_csv(&path).unwrap();
            let (_, rows) = parse(&std::fs::read_to_string(&path).unwrap());
            proptest::prop_assert_eq!(rows.len(), rec.len());
            for (r, row) in rows.iter().enumerate() {
                for (c, expect) in cols.iter().enumerate() {
                    let (a, b) = (row[c + 1], expect[r]);
                    proptest::prop_assert!(a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()));
                }
            }
        }
    }
}

#[test]
fn a_failed_write_leaves_the_previous_file_and_no_leftover() {
    let dir = scratch("whole");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("r.csv");
    std::fs::write(&path, "previous").unwrap();
    let failed: Result<(), std::io::Error> = write_whole(&path, |tmp| {
        std::fs::write(tmp, "half a fi")?;
        Err(std::io::Error::other("disk full"))
    });
    assert!(failed.is_err());
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "previous");
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert_eq!(left.len(), 1, "the partial sibling is removed");
    let mut rec = Recorder::new();
    rec.sample(0.0).unwrap();
    rec.set("x", 1.5).unwrap();
    rec.write_csv(&path).unwrap();
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "time,x\n0.0,1.5\n");
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
}
