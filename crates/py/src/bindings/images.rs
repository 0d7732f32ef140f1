//! The image measures of `lowdisc._lowdisc`: images arrive as flat,
//! C-contiguous float32 arrays of `height * width * 3` values with their
//! height and width (the Python package checks the `(h, w, 3)` shape), masks
//! as flat bool arrays of one entry per pixel.

use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::arrays::engine_error;
use crate::engine::images::{self, ImageArg};

/// A flat contiguous array's values.
fn values<'a, T: numpy::Element>(array: &'a PyReadonlyArray1<'_, T>) -> PyResult<&'a [T]> {
    array
        .as_slice()
        .map_err(|e| PyValueError::new_err(e.to_string()))
}

/// An image argument of `(height, width)`.
fn image<'a>(
    array: &'a PyReadonlyArray1<'_, f32>,
    shape: (usize, usize),
) -> PyResult<ImageArg<'a>> {
    Ok(ImageArg {
        values: values(array)?,
        height: shape.0,
        width: shape.1,
    })
}

/// The mask's flags, if any.
fn mask<'a>(array: &'a Option<PyReadonlyArray1<'_, bool>>) -> PyResult<Option<&'a [bool]>> {
    array.as_ref().map(values).transpose()
}

/// MSE, relMSE, RMSE, MAE of linear values over the kept pixels.
#[pyfunction]
fn image_errors(
    py: Python<'_>,
    test: PyReadonlyArray1<'_, f32>,
    reference: PyReadonlyArray1<'_, f32>,
    shape: (usize, usize),
    keep: Option<PyReadonlyArray1<'_, bool>>,
) -> PyResult<(f64, f64, f64, f64)> {
    let (t, r, m) = (
        image(&test, shape)?,
        image(&reference, shape)?,
        mask(&keep)?,
    );
    let e = py
        .detach(|| images::errors(t, r, m))
        .map_err(engine_error)?;
    Ok((e.mse, e.relmse, e.rmse, e.mae))
}

/// The blurred (perceptual) MSE.
#[pyfunction]
fn blurred_mse(
    py: Python<'_>,
    test: PyReadonlyArray1<'_, f32>,
    reference: PyReadonlyArray1<'_, f32>,
    shape: (usize, usize),
    keep: Option<PyReadonlyArray1<'_, bool>>,
    sigma: f64,
) -> PyResult<f64> {
    let (t, r, m) = (
        image(&test, shape)?,
        image(&reference, shape)?,
        mask(&keep)?,
    );
    py.detach(|| images::blurred(t, r, m, sigma))
        .map_err(engine_error)
}

/// The mean FLIP error.
#[pyfunction]
fn flip(
    py: Python<'_>,
    test: PyReadonlyArray1<'_, f32>,
    reference: PyReadonlyArray1<'_, f32>,
    shape: (usize, usize),
    keep: Option<PyReadonlyArray1<'_, bool>>,
    pixels_per_degree: f32,
) -> PyResult<f64> {
    let (t, r, m) = (
        image(&test, shape)?,
        image(&reference, shape)?,
        mask(&keep)?,
    );
    py.detach(|| images::flip(t, r, m, pixels_per_degree))
        .map_err(engine_error)
}

/// The per-channel error image, flat.
#[pyfunction]
fn error_image<'py>(
    py: Python<'py>,
    test: PyReadonlyArray1<'py, f32>,
    reference: PyReadonlyArray1<'py, f32>,
    shape: (usize, usize),
    kind: &str,
) -> PyResult<Bound<'py, PyArray1<f32>>> {
    let (t, r) = (image(&test, shape)?, image(&reference, shape)?);
    let v = py
        .detach(|| images::error_values(t, r, kind))
        .map_err(engine_error)?;
    Ok(PyArray1::from_vec(py, v))
}

/// The paired ratio: (ratio, low, high, n, ratio_of_means, verdict).
#[pyfunction]
fn compare(
    errors: PyReadonlyArray1<'_, f64>,
    baseline: PyReadonlyArray1<'_, f64>,
) -> PyResult<(f64, f64, f64, usize, f64, &'static str)> {
    let r = images::compare(values(&errors)?, values(&baseline)?).map_err(engine_error)?;
    Ok((r.ratio, r.low, r.high, r.n, r.ratio_of_means, r.verdict))
}

/// Adds the image measures to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(image_errors, m)?)?;
    m.add_function(wrap_pyfunction!(blurred_mse, m)?)?;
    m.add_function(wrap_pyfunction!(flip, m)?)?;
    m.add_function(wrap_pyfunction!(error_image, m)?)?;
    m.add_function(wrap_pyfunction!(compare, m)?)?;
    Ok(())
}
