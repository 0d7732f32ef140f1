//! The adapter between Python and lowdisc: every call into the `lowdisc` and
//! `lowdisc-metrics` crates is here, behind plain-Rust functions that check
//! their arguments first (so nothing below can panic on bad input).
//!
//! * [`points`]: sequences (Sobol, Halton, independent, stratified) as digit
//!   words or floats, from any start index, in parallel chunks, written into
//!   an array the caller provides; [`sobol_fill`] is the Sobol part.
//! * [`pixel`]: the renderer's pixel samplers, by catalog name.
//! * [`nets`]: the generator matrices (`net=`) of the Sobol samplers: a
//!   built-in name, a file or matrices in memory.
//! * [`metrics`]: discrepancies, distances and spectra of point arrays.
//! * [`render`]: the path tracer's images, as `lowdisc render` makes them.
//! * [`images`]: error metrics of images against a reference and the
//!   experiment's paired-seed ratio.
//!
//! Samplers and randomizations are chosen through lowdisc's catalog by name,
//! so a change of lowdisc's types touches only this module.

pub mod images;
pub mod metrics;
pub mod nets;
pub mod pixel;
pub mod points;
pub mod render;
pub mod sobol_fill;

use core::fmt;

/// Values per parallel work item: large enough to amortise a chunk's set-up,
/// small enough to spread a request over all cores.
pub(crate) const CHUNK_VALUES: usize = 1 << 16;

/// Runs `work` on `workers` threads (scipy's convention: -1 is every core,
/// `k >= 1` a pool of `k` threads). The engine's parallel sums use fixed
/// chunks added in a fixed order, so the result does not depend on it.
pub fn with_workers<T: Send>(workers: i64, work: impl FnOnce() -> T + Send) -> Result<T> {
    match workers {
        -1 => Ok(work()),
        k if k >= 1 => {
            let threads = usize::try_from(k).unwrap_or(usize::MAX).min(MAX_WORKERS);
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .map_err(|e| EngineError::value(format!("cannot start {threads} threads: {e}")))?;
            Ok(pool.install(work))
        }
        other => Err(EngineError::value(format!(
            "Invalid number of workers: {other}, must be -1 or > 0"
        ))),
    }
}

/// The most threads `workers` starts (more than any machine's cores).
pub const MAX_WORKERS: usize = 1024;

/// What went wrong, and which Python exception it becomes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum EngineError {
    /// A bad value (`ValueError`).
    Value(String),
    /// A value of the wrong kind (`TypeError`).
    Type(String),
}

impl EngineError {
    /// A `ValueError` with this message.
    pub fn value(message: impl Into<String>) -> Self {
        EngineError::Value(message.into())
    }
}

impl fmt::Display for EngineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EngineError::Value(m) | EngineError::Type(m) => f.write_str(m),
        }
    }
}

impl From<lowdisc::Error> for EngineError {
    fn from(e: lowdisc::Error) -> Self {
        EngineError::Value(e.to_string())
    }
}

impl From<lowdisc_metrics::MetricsError> for EngineError {
    fn from(e: lowdisc_metrics::MetricsError) -> Self {
        EngineError::Value(e.to_string())
    }
}

/// Result of an engine call.
pub type Result<T> = core::result::Result<T, EngineError>;

/// The element type of an output array.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dtype {
    /// `float64`: the digit word times `2^-32` (exact), or the sequence's
    /// own double value (Halton, stratified).
    F64,
    /// `float32`: the 24 leading digits (never rounded up to 1).
    F32,
    /// `uint32`: the digit word `floor(x * 2^32)`.
    U32,
}

impl Dtype {
    /// Parses numpy's name of the type (`float64`, `float32`, `uint32`).
    pub fn from_name(name: &str) -> Result<Dtype> {
        match name {
            "float64" => Ok(Dtype::F64),
            "float32" => Ok(Dtype::F32),
            "uint32" => Ok(Dtype::U32),
            other => Err(EngineError::Type(format!(
                "dtype must be float64, float32 or uint32, got {other}"
            ))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn workers_sets_the_thread_count() {
        assert_eq!(with_workers(1, rayon::current_num_threads), Ok(1));
        assert_eq!(with_workers(3, rayon::current_num_threads), Ok(3));
        let all = rayon::current_num_threads();
        assert_eq!(with_workers(-1, rayon::current_num_threads), Ok(all));
        assert!(
            with_workers(0, || ())
                .unwrap_err()
                .to_string()
                .contains("must be -1 or > 0")
        );
        assert!(with_workers(-2, || ()).is_err());
    }
}

/// An output array's values, point-major.
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    /// `float64` values.
    F64(Vec<f64>),
    /// `float32` values.
    F32(Vec<f32>),
    /// `uint32` digit words.
    U32(Vec<u32>),
}
