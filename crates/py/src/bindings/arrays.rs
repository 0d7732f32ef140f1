//! Array conversions of the bindings: checked views of numpy inputs and
//! numpy outputs of engine values.

use numpy::{
    Element, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

use crate::engine::{EngineError, Values};

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

/// Engine values as an `(n, d)` array of their type.
pub fn values_2d(py: Python<'_>, values: Values, n: usize, d: usize) -> PyResult<Bound<'_, PyAny>> {
    Ok(match values {
        Values::F64(v) => PyArray1::from_vec(py, v).reshape([n, d])?.into_any(),
        Values::F32(v) => PyArray1::from_vec(py, v).reshape([n, d])?.into_any(),
        Values::U32(v) => PyArray1::from_vec(py, v).reshape([n, d])?.into_any(),
    })
}
