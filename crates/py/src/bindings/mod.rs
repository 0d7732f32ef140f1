//! The module `lowdisc._lowdisc`: thin pyo3 functions over [`crate::engine`].
//!
//! Arguments arrive already normalised by the Python package (`python/lowdisc`:
//! integers checked, dtypes named, arrays made contiguous); this layer still
//! checks every array's type, shape and layout itself, so a direct call with
//! bad arguments raises `TypeError`/`ValueError` instead of crashing. The work
//! runs with the GIL released (`Python::detach`).

mod arrays;
mod images;
mod interrupt;
mod metrics;
mod nets;
mod render;

use numpy::{
    PyArray1, PyArray2, PyArray3, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::engine::pixel::{self, PixelSpec};
use crate::engine::points::{self as sequences, PointSpec, Sequence};
use arrays::engine_error;

/// The sequence called `name`.
fn sequence(name: &str) -> PyResult<Sequence> {
    match name {
        "sobol" => Ok(Sequence::Sobol),
        "halton" => Ok(Sequence::Halton),
        "independent" => Ok(Sequence::Independent),
        "stratified" => Ok(Sequence::Stratified),
        other => Err(PyValueError::new_err(format!("unknown sequence {other:?}"))),
    }
}

/// Fills `out`, a writeable C-contiguous `(n, d)` array of float64, float32
/// or uint32, with points `start .. start + n` of a sequence (the caller
/// allocates, so running out of memory is numpy's `MemoryError`).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn points_into(
    py: Python<'_>,
    out: &Bound<'_, PyAny>,
    sequence_name: &str,
    start: u64,
    order: &str,
    scramble: &str,
    seed: u64,
    bits: u32,
) -> PyResult<()> {
    let natural_order = match order {
        "gray" => false,
        "natural" => true,
        other => {
            return Err(PyValueError::new_err(format!(
                "order must be 'gray' or 'natural', got {other:?}"
            )));
        }
    };
    let sequence = sequence(sequence_name)?;
    arrays::fill_2d(py, out, |n, d, dtype| PointSpec {
        sequence,
        n,
        d,
        start,
        natural_order,
        scramble: scramble.to_owned(),
        seed,
        bits,
        dtype,
    })
}

/// The renderer's samples for `pixels` (an `(p, 2)` uint32 array of x, y), as
/// a float32 array `(p, spp, dims)`; `net` as [`nets::net_arg`] takes it.
#[pyfunction]
#[pyo3(signature = (sampler, spp, resolution, pixels, dims, seed, net=None))]
#[allow(clippy::too_many_arguments)]
fn pixel_samples<'py>(
    py: Python<'py>,
    sampler: &str,
    spp: u32,
    resolution: (u32, u32),
    pixels: &Bound<'py, PyAny>,
    dims: u32,
    seed: u64,
    net: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyArray3<f32>>> {
    let net = nets::net_arg(net.as_ref())?.unwrap_or_default();
    let pixels: PyReadonlyArray2<u32> = arrays::contiguous_2d(pixels, "pixels")?;
    let shape = pixels.shape();
    if shape[1] != 2 {
        return Err(PyValueError::new_err(format!(
            "pixels must have shape (p, 2), got (p, {})",
            shape[1]
        )));
    }
    let list = arrays::slice(&pixels)?
        .chunks_exact(2)
        .map(|p| [p[0], p[1]])
        .collect();
    let spec = PixelSpec {
        sampler: sampler.to_owned(),
        spp,
        resolution: [resolution.0, resolution.1],
        pixels: list,
        dims,
        seed,
        net,
    };
    let values = py
        .detach(|| pixel::pixel_samples(&spec))
        .map_err(engine_error)?;
    PyArray1::from_vec(py, values).reshape([shape[0], spp as usize, dims as usize])
}

/// The Sobol generator matrices of dimensions `0..d`, `(d, 32)` uint32.
#[pyfunction]
fn sobol_matrices(py: Python<'_>, d: u32) -> PyResult<Bound<'_, PyArray2<u32>>> {
    let m = sequences::sobol_matrices(d).map_err(engine_error)?;
    PyArray1::from_vec(py, m).reshape([d as usize, 32])
}

/// The names of the pixel samplers.
#[pyfunction]
fn sampler_names() -> Vec<&'static str> {
    pixel::sampler_names()
}

/// The extension module.
#[pymodule]
fn _lowdisc(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("SOBOL_DIMENSIONS", sequences::SOBOL_DIMENSIONS)?;
    m.add("HALTON_DIMENSIONS", sequences::HALTON_DIMENSIONS)?;
    m.add_function(wrap_pyfunction!(points_into, m)?)?;
    m.add_function(wrap_pyfunction!(pixel_samples, m)?)?;
    m.add_function(wrap_pyfunction!(sobol_matrices, m)?)?;
    m.add_function(wrap_pyfunction!(sampler_names, m)?)?;
    metrics::register(m)?;
    images::register(m)?;
    render::register(m)
}
