//! `lowdisc._lowdisc.render`: the path tracer with the GIL released,
//! progress reported to a Python callable from the calling thread, and
//! Ctrl-C cancelling the render.

use std::sync::atomic::{AtomicU64, Ordering};

use numpy::{PyArray1, PyArray3, PyArrayMethods};
use pyo3::prelude::*;

use super::arrays::engine_error;
use super::interrupt::interruptible;
use crate::engine::render::{self as engine, RenderRequest};

/// Renders `scene` (a built-in name or a pbrt-v4 file); `None` settings
/// take the scene's value, else the default; `net` as
/// [`super::nets::net_arg`] takes it. Returns the `(height, width,
/// 3)` float32 image and the warnings. `progress(done, total)` (samples) is
/// called from this thread while the render runs.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (scene, sampler, net, spp, seed, max_depth, resolution, threads, threshold,
                    paper_all_dims, spectral, approximate, progress))]
fn render<'py>(
    py: Python<'py>,
    scene: String,
    sampler: Option<String>,
    net: Option<Bound<'py, PyAny>>,
    spp: Option<u32>,
    seed: Option<u64>,
    max_depth: Option<u32>,
    resolution: Option<(u32, u32)>,
    threads: Option<usize>,
    threshold: Option<f64>,
    paper_all_dims: Option<bool>,
    spectral: bool,
    approximate: bool,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<(Bound<'py, PyArray3<f32>>, Vec<String>)> {
    let request = RenderRequest {
        scene,
        sampler,
        net: super::nets::net_arg(net.as_ref())?,
        spp,
        seed,
        max_depth,
        resolution: resolution.map(|(w, h)| [w, h]),
        threads,
        threshold,
        paper_all_dims,
        spectral,
        approximate,
    };
    let (done, total) = (AtomicU64::new(0), AtomicU64::new(0));
    let report = |d: u64, t: u64| {
        total.store(t, Ordering::Relaxed);
        done.fetch_max(d, Ordering::Relaxed);
    };
    let mut reported = None;
    let tick = || match &progress {
        Some(callback) => {
            let now = (done.load(Ordering::Relaxed), total.load(Ordering::Relaxed));
            if now.1 > 0 && reported != Some(now) {
                reported = Some(now);
                callback.call1(now)?;
            }
            Ok(())
        }
        None => Ok(()),
    };
    let work = |cancel: &_| engine::render(&request, &report, cancel);
    let image = interruptible(py, work, tick)?.map_err(engine_error)?;
    let array = PyArray1::from_vec(py, image.pixels).reshape([image.height, image.width, 3])?;
    Ok((array, image.warnings))
}

/// The built-in scenes' names.
#[pyfunction]
fn builtin_scenes() -> Vec<&'static str> {
    engine::builtin_scenes()
}

/// Adds the render functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(render, m)?)?;
    m.add_function(wrap_pyfunction!(builtin_scenes, m)?)?;
    Ok(())
}
