//! One state or a batch of states: array inputs checked and copied into flat buffers, the
//! work split into chunks over threads (one workspace per thread) without the GIL, and the
//! results returned as one numpy array.

use crate::error::{biped_err, guard};
use numpy::{AllowTypeChange, PyArray1, PyArrayLikeDyn, PyArrayMethods};
use pyo3::prelude::*;
use std::ops::Range;
use std::sync::OnceLock;

/// The inputs of a call: per argument the values of all states, row after row.
pub struct Inputs {
    /// Flat values of each argument (`n * len` entries).
    values: Vec<Vec<f64>>,
    /// Entries per state of each argument.
    lens: Vec<usize>,
    /// Number of states.
    pub n: usize,
    /// Whether the arguments had a leading batch axis.
    pub batched: bool,
}

/// One argument: its name, the array-like object and the shape of one state.
pub struct Arg<'a, 'py> {
    /// Name used in error messages.
    pub name: &'a str,
    /// The Python object (any array-like of numbers).
    pub value: &'a Bound<'py, PyAny>,
    /// Shape of one state's value, e.g. `[nq]` or `[nbodies, 6]`.
    pub shape: Vec<usize>,
}

impl Inputs {
    /// Reads and checks the arguments: all single states (ndim = shape length) or all batches
    /// of the same length (one more leading axis).
    pub fn gather(args: &[Arg<'_, '_>]) -> PyResult<Self> {
        let mut inputs = Inputs {
            values: Vec::new(),
            lens: Vec::new(),
            n: 1,
            batched: false,
        };
        for (k, arg) in args.iter().enumerate() {
            let array: PyArrayLikeDyn<f64, AllowTypeChange> =
                arg.value.extract().map_err(|_| {
                    biped_err(format!("\"{}\": expected an array of numbers", arg.name))
                })?;
            let view = array.as_array();
            let dims = view.shape();
            let batched = dims.len() == arg.shape.len() + 1;
            if !batched && dims.len() != arg.shape.len() {
                return Err(biped_err(format!(
                    "\"{}\" has {} dimensions, expected {} (one state) or {} (a batch)",
                    arg.name,
                    dims.len(),
                    arg.shape.len(),
                    arg.shape.len() + 1
                )));
            }
            let state = &dims[batched as usize..];
            if state != arg.shape.as_slice() {
                return Err(biped_err(wrong_shape(arg, state, batched)));
            }
            let n = if batched { dims[0] } else { 1 };
            if k > 0 && (batched != inputs.batched || n != inputs.n) {
                return Err(biped_err(format!(
                    "\"{}\" does not match \"{}\": give one state each or batches of equal length",
                    arg.name, args[0].name
                )));
            }
            (inputs.batched, inputs.n) = (batched, n);
            let values: Vec<f64> = view.iter().copied().collect();
            if let Some(i) = values.iter().position(|x| !x.is_finite()) {
                let len = arg.shape.iter().product::<usize>().max(1);
                return Err(biped_err(non_finite(arg.name, batched, i / len, i % len)));
            }
            inputs.lens.push(arg.shape.iter().product());
            inputs.values.push(values);
        }
        Ok(inputs)
    }

    /// The arguments of state `i`.
    pub fn state(&self, i: usize) -> impl Iterator<Item = &[f64]> {
        let lens = self.lens.iter();
        self.values
            .iter()
            .zip(lens)
            .map(move |(v, &len)| &v[i * len..(i + 1) * len])
    }
}

/// The message for a state shape `got` other than the expected one (for vectors worded as
/// the command line's: `"q" has 5 entries, expected 7`).
fn wrong_shape(arg: &Arg<'_, '_>, got: &[usize], batched: bool) -> String {
    let rows = if batched { "rows of " } else { "" };
    match (got, arg.shape.as_slice()) {
        ([n], [len]) => format!("\"{}\" has {rows}{n} entries, expected {len}", arg.name),
        _ => format!(
            "\"{}\" has {rows}shape {got:?}, expected {:?}",
            arg.name, arg.shape
        ),
    }
}

/// The message for a NaN or infinity at flat index `entry` of state `state`.
fn non_finite(name: &str, batched: bool, state: usize, entry: usize) -> String {
    match batched {
        true => format!("state {state}: \"{name}\"[{entry}] is not finite"),
        false => format!("\"{name}\"[{entry}] is not finite"),
    }
}

/// Number of threads for `n` states: `threads` if given (>= 1), else the available cores.
pub fn thread_count(threads: Option<usize>, n: usize) -> PyResult<usize> {
    // asked once: on Linux the answer comes from cgroup files (tens of microseconds)
    static CORES: OnceLock<usize> = OnceLock::new();
    let t = match threads {
        Some(0) => return Err(biped_err("threads: must be at least 1")),
        Some(t) => t,
        None if n <= 1 => 1,
        None => *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, |p| p.get())),
    };
    Ok(t.min(n).max(1))
}

/// Runs `kernel(work, i, out_i)` for the states in `range`, stopping at the first error.
fn run_range<W>(
    work: &mut W,
    range: Range<usize>,
    out: &mut [f64],
    out_len: usize,
    kernel: &(impl Fn(&mut W, usize, &mut [f64]) -> Result<(), String> + Sync),
) -> Result<(), (usize, String)> {
    for i in range.clone() {
        let k = i - range.start;
        let slot = &mut out[k * out_len..(k + 1) * out_len];
        guard(|| kernel(work, i, slot)).map_err(|e| (i, e))?;
    }
    Ok(())
}

/// Computes every state of `inputs` into one flat output (`out_len` values per state) with
/// the GIL released. A single state uses `single` (the caller's cached workspace); a batch is
/// split into contiguous chunks, one thread and one fresh workspace (`make`) each.
pub fn compute<W: Send>(
    py: Python<'_>,
    inputs: &Inputs,
    out_len: usize,
    threads: Option<usize>,
    single: &mut W,
    make: impl Fn() -> W + Sync,
    kernel: impl Fn(&mut W, usize, &mut [f64]) -> Result<(), String> + Sync,
) -> PyResult<Vec<f64>> {
    let n = inputs.n;
    let nthreads = thread_count(threads, n)?;
    let mut out = vec![0.0; n * out_len];
    let result = py.detach(|| {
        if nthreads == 1 {
            return run_range(single, 0..n, &mut out, out_len, &kernel);
        }
        let chunk = n.div_ceil(nthreads);
        std::thread::scope(|s| {
            let mut rest = out.as_mut_slice();
            let mut handles = Vec::new();
            for start in (0..n).step_by(chunk) {
                let end = (start + chunk).min(n);
                let (head, tail) = std::mem::take(&mut rest).split_at_mut((end - start) * out_len);
                rest = tail;
                let (make, kernel) = (&make, &kernel);
                handles.push(s.spawn(move || {
                    let mut work = guard(|| Ok(make())).map_err(|e| (start, e))?;
                    run_range(&mut work, start..end, head, out_len, kernel)
                }));
            }
            let results = handles.into_iter().map(|h| h.join());
            let joined: Vec<_> = results
                .map(|r| r.unwrap_or_else(|_| Err((0, "internal error: thread panicked".into()))))
                .collect();
            joined.into_iter().collect::<Result<(), _>>()
        })
    });
    result.map_err(|(i, e)| match inputs.batched {
        true => biped_err(format!("state {i}: {e}")),
        false => biped_err(e),
    })?;
    Ok(out)
}

/// The flat output as a numpy array of shape `[n] + shape` (batch) or `shape` (one state).
pub fn to_array<'py>(
    py: Python<'py>,
    inputs: &Inputs,
    values: Vec<f64>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    let mut dims = Vec::with_capacity(shape.len() + 1);
    if inputs.batched {
        dims.push(inputs.n);
    }
    dims.extend_from_slice(shape);
    let flat = PyArray1::from_vec(py, values);
    match dims.len() {
        1 => Ok(flat.into_any()),
        _ => Ok(flat.reshape(dims)?.into_any()),
    }
}
