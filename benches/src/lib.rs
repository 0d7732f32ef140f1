//! Shared inputs for the criterion benchmarks in `benches/` (run them with
//! `cargo bench -p lowdisc-benches`; see `benches/README.md`).
//!
//! Every benchmark that compares lowdisc with `sobol_burley` walks the same
//! fixed, seeded list of `(index, dimension)` pairs, restricted to what
//! `sobol_burley` supports (indices below `2^16`, dimensions below 256), so the
//! two libraries do the same work on the same inputs.
//!
//! [`clock`] is the criterion clock the benchmarks use (thread CPU time) and
//! [`report`] turns criterion's saved estimates into the README's table (the
//! `bench-table` binary prints it).

pub mod clock;
pub mod report;

use lowdisc::hash::mix64;

/// Number of `(index, dimension)` pairs each benchmark iteration walks.
pub const PAIRS: usize = 4096;

/// Indices are drawn below this bound (`sobol_burley` supports `2^16`).
pub const INDEX_LIMIT: u32 = 1 << 16;

/// Dimensions are drawn below this bound (`sobol_burley` supports 256).
pub const DIMENSION_LIMIT: u32 = 256;

/// Values written per `GrayCodeBatch::fill` call in the batch benchmarks
/// (256 KiB of `u32`).
pub const BATCH_VALUES: usize = 1 << 16;

/// Point widths (dimensions per point) of the batch benchmarks.
pub const BATCH_WIDTHS: [u32; 4] = [1, 4, 64, 1024];

/// The fixed seed of the input lists.
pub const INPUT_SEED: u64 = 0x05ee_d0fb_e4c4;

/// `PAIRS` pseudo-random `(index, dimension)` pairs with `index < 2^16` and
/// `dimension < 256`, the same on every run.
pub fn pairs_1d() -> Vec<(u32, u32)> {
    (0..PAIRS as u64)
        .map(|i| {
            let h = mix64(INPUT_SEED ^ mix64(i));
            let index = (h as u32) % INDEX_LIMIT;
            let dim = ((h >> 32) as u32) % DIMENSION_LIMIT;
            (index, dim)
        })
        .collect()
}

/// `PAIRS` pseudo-random `(index, dimension set)` pairs for 4-D samples:
/// `index < 2^16` and `set < 64`, covering dimensions `4 * set .. 4 * set + 4`
/// (all below 256).
pub fn pairs_4d() -> Vec<(u32, u32)> {
    pairs_1d()
        .into_iter()
        .map(|(index, dim)| (index, dim / 4))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inputs_stay_within_sobol_burley_limits() {
        let pairs = pairs_1d();
        assert_eq!(pairs.len(), PAIRS);
        assert!(
            pairs
                .iter()
                .all(|&(i, d)| i < INDEX_LIMIT && d < DIMENSION_LIMIT)
        );
        assert!(pairs_4d().iter().all(|&(_, s)| 4 * s + 3 < DIMENSION_LIMIT));
        // Not degenerate: many distinct indices and dimensions.
        let mut dims: Vec<u32> = pairs.iter().map(|p| p.1).collect();
        dims.sort_unstable();
        dims.dedup();
        assert!(dims.len() > 200);
    }
}
