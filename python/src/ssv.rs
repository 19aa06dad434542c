//! SSV distances for Python: one query with shapes in the JSON form of `biped ssv query`
//! (parsed by `biped_ssv::query`), a vectorised query over arrays of primitives, and
//! `CollisionModel` (in `ssv/collision.rs`).

mod collision;

use crate::batch::{compute, to_array, Arg, Inputs};
use crate::error::biped_err;
use biped_ssv::query::parse_shape;
use biped_ssv::{distance, DistanceResult, Lss, Pss, Ssv, Tss};
use nalgebra::Point3;
use pyo3::prelude::*;

/// Distance, closest points and normal as plain arrays.
type Closest = (f64, [f64; 3], [f64; 3], [f64; 3]);

/// The result as a tuple.
pub(crate) fn closest(r: &DistanceResult) -> Closest {
    (
        r.distance,
        r.point_a.coords.into(),
        r.point_b.coords.into(),
        r.normal.into(),
    )
}

/// Signed distance between two shapes given as JSON text (`{"line": [..], "radius": r}`).
#[pyfunction]
fn ssv_distance_json(a: &str, b: &str) -> PyResult<Closest> {
    let a = parse_shape(a, "a").map_err(biped_err)?;
    let b = parse_shape(b, "b").map_err(biped_err)?;
    Ok(closest(&distance(&a, &b)))
}

/// Values per row of a primitive kind: coordinates, then the radius.
fn row_len(kind: &str, name: &str) -> PyResult<usize> {
    match kind {
        "point" => Ok(4),
        "line" => Ok(7),
        "triangle" => Ok(10),
        _ => Err(biped_err(format!(
            "\"{name}\": unknown kind \"{kind}\" (point, line or triangle)"
        ))),
    }
}

/// The primitive of one row (`[x, y, z, .., radius]`), errors prefixed with `"name": `.
fn primitive(row: &[f64], name: &str) -> Result<Ssv, String> {
    let p = |k: usize| Point3::new(row[k], row[k + 1], row[k + 2]);
    let r = row[row.len() - 1];
    let ssv = match row.len() {
        4 => Pss::new(p(0), r).map(Ssv::from),
        7 => Lss::new(p(0), p(3), r).map(Ssv::from),
        _ => Tss::new(p(0), p(3), p(6), r).map(Ssv::from),
    };
    ssv.map_err(|e| format!("\"{name}\": {e}"))
}

/// Distances between row `i` of `a` and row `i` of `b` (N x (4|7|10) arrays, or one row
/// each): returns `(distance (N,), point_a (N,3), point_b (N,3), normal (N,3))`.
#[pyfunction]
#[pyo3(signature = (kind_a, a, kind_b, b, threads = None))]
fn ssv_distances<'py>(
    py: Python<'py>,
    kind_a: &str,
    a: &Bound<'py, PyAny>,
    kind_b: &str,
    b: &Bound<'py, PyAny>,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    let shape = |kind, name| row_len(kind, name).map(|n| vec![n]);
    let args = [
        Arg {
            name: "a",
            value: a,
            shape: shape(kind_a, "a")?,
        },
        Arg {
            name: "b",
            value: b,
            shape: shape(kind_b, "b")?,
        },
    ];
    let inputs = Inputs::gather(&args)?;
    let out = compute(
        py,
        &inputs,
        10,
        threads,
        &mut (),
        || (),
        |_, i, out| {
            let mut state = inputs.state(i);
            let (ra, rb) = (state.next().unwrap_or(&[]), state.next().unwrap_or(&[]));
            let (d, pa, pb, n) = closest(&distance(&primitive(ra, "a")?, &primitive(rb, "b")?));
            out[0] = d;
            out[1..4].copy_from_slice(&pa);
            out[4..7].copy_from_slice(&pb);
            out[7..].copy_from_slice(&n);
            Ok(())
        },
    )?;
    to_array(py, &inputs, out, &[10])
}

/// Adds the SSV functions and classes to the native module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(ssv_distance_json, m)?)?;
    m.add_function(wrap_pyfunction!(ssv_distances, m)?)?;
    m.add_class::<collision::PyCollisionModel>()?;
    Ok(())
}
