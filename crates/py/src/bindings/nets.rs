//! The `net` argument of the render and pixel-sampler functions: `None`,
//! a str (a built-in net's name or a file) or a C-contiguous uint32 numpy
//! array `(dims, 32)` of generator-matrix columns.

use lowdisc::net::Net;
use numpy::PyUntypedArrayMethods;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyString;

use super::arrays::{contiguous_2d, engine_error, slice};
use crate::engine::nets::{self, NetSource};

/// The net `obj` gives, checked (`None` for `None`).
pub fn net_arg(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Net>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    let source = if let Ok(name) = obj.cast::<PyString>() {
        NetSource::NameOrFile(name.to_str()?.to_owned())
    } else {
        let array = contiguous_2d::<u32>(obj, "net")?;
        let shape = array.shape();
        if shape[1] != 32 {
            return Err(PyValueError::new_err(format!(
                "net must have shape (dims, 32), got ({}, {})",
                shape[0], shape[1]
            )));
        }
        NetSource::Matrices(nets::matrices(slice(&array)?).map_err(engine_error)?)
    };
    nets::resolve(&source).map(Some).map_err(engine_error)
}
