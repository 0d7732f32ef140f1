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

/// The `(n, d)` array of a point request, allocated by numpy (whose
/// allocator asks the kernel for huge pages for large arrays, which makes the
/// first write to each page much cheaper) and filled in place with the GIL
/// released.
pub fn filled_2d<'py>(
    py: Python<'py>,
    spec: &PointSpec,
    n: usize,
    d: usize,
) -> PyResult<Bound<'py, PyAny>> {
    fn fill<'py, T: Element + Send>(
        py: Python<'py>,
        spec: &PointSpec,
        shape: [usize; 2],
    ) -> PyResult<Bound<'py, PyAny>>
    where
        for<'a> &'a mut [T]: Into<Output<'a>>,
    {
        // Refuse a bad request before numpy allocates anything for it.
        points::check_request(spec).map_err(engine_error)?;
        let array = PyArray2::<T>::zeros(py, shape, false);
        {
            let mut view = array.readwrite();
            let values = view
                .as_slice_mut()
                .map_err(|e| PyValueError::new_err(e.to_string()))?;
            py.detach(|| points::generate_into(spec, values.into()))
                .map_err(engine_error)?;
        }
        Ok(array.into_any())
    }
    let shape = [n, d];
    match spec.dtype {
        Dtype::F64 => fill::<f64>(py, spec, shape),
        Dtype::F32 => fill::<f32>(py, spec, shape),
        Dtype::U32 => fill::<u32>(py, spec, shape),
    }
}
