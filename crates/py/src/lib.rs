//! # lowdisc-py: lowdisc for Python
//!
//! The extension module `lowdisc._lowdisc` behind the Python package in
//! `python/`: lowdisc's sequences, the renderer's pixel samplers and the
//! point-set metrics, as numpy arrays.
//!
//! * [`engine`] is the only module that calls the `lowdisc` and
//!   `lowdisc-metrics` crates. It is plain Rust (no Python types), validates
//!   every argument before calling them, and is what the unit tests exercise.
//! * `bindings` (feature `python`) turns Python arguments into engine calls
//!   and engine errors into `ValueError`/`TypeError`, releasing the GIL for
//!   the work.
//!
//! Without the `python` feature the crate builds and tests without Python.

pub mod engine;

#[cfg(feature = "python")]
mod bindings;
