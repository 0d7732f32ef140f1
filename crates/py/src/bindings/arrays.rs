//! Array conversions of the bindings: checked views of numpy inputs and
//! numpy outputs of engine values.

use numpy::{
    Element, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

use crate::engine::points::{self, Output, PointSpec};
use crate::engine::{Dtype, EngineError};

/// The Python exception of an engine error.
pub fn engine_error(e: EngineError) -> PyErr {
    match e {
        EngineError::Value(m) => PyValueError::new_err(m),
        EngineError::Type(m) => PyTypeError::new_err(m),
    }
}

/// `obj` as a read-only, C-contiguous, 2-D numpy array of `T`; otherwise a
/// `TypeError` (not an array, wrong dtype) or `ValueError` (shape, layout)
/// naming the argument.
pub fn contiguous_2d<'py, T: Element>(
    obj: &Bound<'py, PyAny>,
    what: &str,
) -> PyResult<PyReadonlyArray2<'py, T>> {
    let array = obj.cast::<PyUntypedArray>().map_err(|_| {
        PyTypeError::new_err(format!(
            "{what} must be a numpy array, got {}",
            obj.get_type()
                .name()
                .map_or_else(|_| "?".into(), |n| n.to_string())
        ))
    })?;
    if array.ndim() != 2 {
        return Err(PyValueError::new_err(format!(
            "{what} must be a 2-D array, got {} dimensions",
            array.ndim()
        )));
    }
    let typed = array.cast::<PyArray2<T>>().map_err(|_| {
        let got = array
            .dtype()
            .str()
            .map_or_else(|_| "?".into(), |s| s.to_string());
        let want = T::get_dtype(obj.py())
            .str()
            .map_or_else(|_| "?".into(), |s| s.to_string());
        PyTypeError::new_err(format!("{what} must have dtype {want}, got {got}"))
    })?;
    if !typed.is_c_contiguous() {
        return Err(PyValueError::new_err(format!(
            "{what} must be C-contiguous (numpy.ascontiguousarray makes a copy that is)"
        )));
    }
    Ok(typed.readonly())
}

/// The values of a contiguous array.
pub fn slice<'a, T: Element>(array: &'a PyReadonlyArray2<'_, T>) -> PyResult<&'a [T]> {
    array
        .as_slice()
        .map_err(|e| PyValueError::new_err(e.to_string()))
}

/// Fills `out`, a writeable, C-contiguous 2-D numpy array of float64,
/// float32 or uint32, with the points of the request `spec(n, d, dtype)`
/// built from its shape and type, with the GIL released. The caller
/// allocates the array (numpy asks the kernel for huge pages for large
/// arrays, which makes the first write to each page much cheaper).
pub fn fill_2d(
    py: Python<'_>,
    out: &Bound<'_, PyAny>,
    spec: impl Fn(u64, u32, Dtype) -> PointSpec,
) -> PyResult<()> {
    fn fill<T: Element + Send>(
        py: Python<'_>,
        array: &Bound<'_, PyArray2<T>>,
        spec: impl Fn(u64, u32, Dtype) -> PointSpec,
        dtype: Dtype,
    ) -> PyResult<()>
    where
        for<'a> &'a mut [T]: Into<Output<'a>>,
    {
        let shape = array.shape();
        let d = u32::try_from(shape[1])
            .map_err(|_| PyValueError::new_err(format!("d = {} is too large", shape[1])))?;
        let spec = spec(shape[0] as u64, d, dtype);
        points::check_request(&spec).map_err(engine_error)?;
        if !array.is_c_contiguous() {
            return Err(PyValueError::new_err("out must be C-contiguous"));
        }
        let mut view = array
            .try_readwrite()
            .map_err(|e| PyValueError::new_err(format!("out must be writeable: {e}")))?;
        let values = view
            .as_slice_mut()
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        py.detach(|| points::generate_into(&spec, values.into()))
            .map_err(engine_error)
    }
    let array = out
        .cast::<PyUntypedArray>()
        .map_err(|_| PyTypeError::new_err("out must be a numpy array"))?;
    if array.ndim() != 2 {
        return Err(PyValueError::new_err(format!(
            "out must be a 2-D array, got {} dimensions",
            array.ndim()
        )));
    }
    if let Ok(a) = out.cast::<PyArray2<f64>>() {
        fill(py, a, spec, Dtype::F64)
    } else if let Ok(a) = out.cast::<PyArray2<f32>>() {
        fill(py, a, spec, Dtype::F32)
    } else if let Ok(a) = out.cast::<PyArray2<u32>>() {
        fill(py, a, spec, Dtype::U32)
    } else {
        let got = array
            .dtype()
            .str()
            .map_or_else(|_| "?".into(), |s| s.to_string());
        Err(PyTypeError::new_err(format!(
            "out must have dtype float64, float32 or uint32, got {got}"
        )))
    }
}
