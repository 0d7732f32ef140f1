//! The metric functions of `lowdisc._lowdisc`: each takes a C-contiguous
//! float64 array `(n, d)` and runs the engine with the GIL released; the
//! long ones (discrepancies, star bounds, distances, spectrum) stop at
//! Ctrl-C.

use numpy::{PyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;

use super::arrays::{contiguous_2d, engine_error, slice};
use super::interrupt::{interruptible, no_tick};
use crate::engine::metrics::{self, BoundsRequest};

/// A checked sample and its dimension count.
fn sample<'py>(obj: &Bound<'py, PyAny>) -> PyResult<(PyReadonlyArray2<'py, f64>, usize)> {
    let array = contiguous_2d::<f64>(obj, "sample")?;
    let d = array.shape()[1];
    Ok((array, d))
}

/// SciPy's L2-type discrepancy `method` of `sample`, on `workers` threads
/// (-1: all cores).
#[pyfunction]
fn discrepancy(
    py: Python<'_>,
    sample: &Bound<'_, PyAny>,
    method: &str,
    iterative: bool,
    workers: i64,
) -> PyResult<f64> {
    let (array, d) = self::sample(sample)?;
    let x = slice(&array)?;
    let work = |cancel: &_| {
        crate::engine::with_workers(workers, || {
            metrics::discrepancy(x, d, method, iterative, cancel)
        })
        .and_then(|r| r)
    };
    interruptible(py, work, no_tick)?.map_err(engine_error)
}

/// The estimated work of the L2 discrepancies (pairs times dimensions).
#[pyfunction]
fn discrepancy_work(n: usize, d: usize) -> f64 {
    metrics::discrepancy_work(n, d)
}

/// The exact star discrepancy, refused above `max_work` estimated
/// operations; Ctrl-C stops it.
#[pyfunction]
fn star_discrepancy(py: Python<'_>, sample: &Bound<'_, PyAny>, max_work: f64) -> PyResult<f64> {
    let (array, d) = self::sample(sample)?;
    let x = slice(&array)?;
    let work = |cancel: &_| metrics::star_discrepancy(x, d, max_work, cancel);
    interruptible(py, work, no_tick)?.map_err(engine_error)
}

/// The estimated operations of the exact star discrepancy of `n` points in `d`.
#[pyfunction]
fn star_work(n: usize, d: usize) -> f64 {
    metrics::star_work(n, d)
}

/// Lower and upper star-discrepancy bounds and their methods; Ctrl-C stops
/// them.
#[pyfunction]
#[pyo3(signature = (sample, random_boxes, ta_iterations, ta_restarts, grid_cells, seed))]
fn star_bounds(
    py: Python<'_>,
    sample: &Bound<'_, PyAny>,
    random_boxes: Option<usize>,
    ta_iterations: Option<usize>,
    ta_restarts: Option<usize>,
    grid_cells: Option<usize>,
    seed: u64,
) -> PyResult<(f64, f64, String, String)> {
    let (array, d) = self::sample(sample)?;
    let x = slice(&array)?;
    let request = BoundsRequest {
        random_boxes,
        ta_iterations,
        ta_restarts,
        grid_cells,
        seed,
    };
    let work = |cancel: &_| metrics::star_bounds(x, d, &request, cancel);
    let b = interruptible(py, work, no_tick)?.map_err(engine_error)?;
    Ok((b.lower, b.upper, b.lower_method, b.upper_method))
}

/// The smallest distance between two points under `metric`; Ctrl-C stops it.
#[pyfunction]
fn min_distance(py: Python<'_>, sample: &Bound<'_, PyAny>, metric: &str) -> PyResult<f64> {
    let (array, d) = self::sample(sample)?;
    let x = slice(&array)?;
    let work = |cancel: &_| metrics::min_distance(x, d, metric, cancel);
    interruptible(py, work, no_tick)?.map_err(engine_error)
}

/// Each point's distance to its nearest other point; Ctrl-C stops it.
#[pyfunction]
fn nearest_neighbour_distances<'py>(
    py: Python<'py>,
    sample: &Bound<'py, PyAny>,
    metric: &str,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let (array, d) = self::sample(sample)?;
    let x = slice(&array)?;
    let work = |cancel: &_| metrics::nearest_neighbour_distances(x, d, metric, cancel);
    let v = interruptible(py, work, no_tick)?.map_err(engine_error)?;
    Ok(PyArray1::from_vec(py, v))
}

/// Ring radii, mean power and frequency counts of a radial spectrum.
type Spectrum<'py> = (
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<u64>>,
);

/// The radial power spectrum: (radii, power, counts); Ctrl-C stops it.
#[pyfunction]
fn power_spectrum<'py>(
    py: Python<'py>,
    sample: &Bound<'py, PyAny>,
    max_frequency: usize,
) -> PyResult<Spectrum<'py>> {
    let (array, d) = self::sample(sample)?;
    let x = slice(&array)?;
    let work = |cancel: &_| metrics::power_spectrum(x, d, max_frequency, cancel);
    let (radii, power, counts) = interruptible(py, work, no_tick)?.map_err(engine_error)?;
    let counts = counts.into_iter().map(|c| c as u64).collect();
    Ok((
        PyArray1::from_vec(py, radii),
        PyArray1::from_vec(py, power),
        PyArray1::from_vec(py, counts),
    ))
}

/// Adds the metric functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(discrepancy, m)?)?;
    m.add_function(wrap_pyfunction!(discrepancy_work, m)?)?;
    m.add_function(wrap_pyfunction!(star_discrepancy, m)?)?;
    m.add_function(wrap_pyfunction!(star_work, m)?)?;
    m.add_function(wrap_pyfunction!(star_bounds, m)?)?;
    m.add_function(wrap_pyfunction!(min_distance, m)?)?;
    m.add_function(wrap_pyfunction!(nearest_neighbour_distances, m)?)?;
    m.add_function(wrap_pyfunction!(power_spectrum, m)?)?;
    Ok(())
}
