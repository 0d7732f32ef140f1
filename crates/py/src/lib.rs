//! # lowdisc-py: lowdisc for Python
//!
//! The extension module `lowdisc._lowdisc` behind the Python package in
//! `python/`: lowdisc's sequences, the renderer's pixel samplers, the
//! point-set metrics, renders of the path tracer and the experiment's image
//! measures, as numpy arrays.
//!
//! * [`engine`] is the only module that calls the `lowdisc`,
//!   `lowdisc-metrics`, `lowdisc-render`, `lowdisc-image` and
//!   `lowdisc-experiment` crates. It is plain Rust (no Python types),
//!   validates every argument before calling them, and is what the unit
//!   tests exercise.
//! * `bindings` (feature `python`) turns Python arguments into engine calls
//!   and engine errors into `ValueError`/`TypeError`, releasing the GIL for
//!   the work; long calls (discrepancies, renders) run on a worker thread
//!   that Ctrl-C cancels.
//!
//! Without the `python` feature the crate builds and tests without Python.

pub mod engine;

#[cfg(feature = "python")]
mod bindings;
