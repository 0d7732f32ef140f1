//! Benchmark crate (benchmarks live in `benches/`).
