//! Estimated cost of every metric, so that a caller can refuse a job before
//! it starts instead of running for hours or exhausting memory.
//!
//! Work is counted in elementary operations (one point-coordinate step of the
//! inner loop), memory in bytes of the largest buffers. The estimates are
//! upper-bound-like formulas of each algorithm's loops, not timings; their
//! purpose is a guard, so they err on the high side. The exact star
//! discrepancy's estimate is [`crate::estimated_work`], which
//! [`crate::star_discrepancy_with`] checks itself.

use crate::BoundsOptions;

/// `n·m` and friends as `f64`, saturating rather than overflowing.
fn product(factors: &[f64]) -> f64 {
    factors.iter().product()
}

/// Work of [`crate::random_box_lower_bound`]: every box counts every point
/// in every dimension, `boxes · n · d`.
pub fn random_box_work(n: usize, d: usize, boxes: usize) -> f64 {
    product(&[boxes as f64, n as f64, d as f64])
}

/// Work of [`crate::star_bounds`]: the random boxes, the threshold-accepting
/// moves (each a local discrepancy over all points) and the bracketing grid
/// (its corners, 2^22 by default and none above 22 dimensions, times `d`,
/// plus `n · d`).
pub fn bounds_work(n: usize, d: usize, options: &BoundsOptions) -> f64 {
    let moves = product(&[options.ta_iterations as f64, options.ta_restarts as f64]);
    let corners = match options.grid_cells {
        Some(k) => (k as f64 + 1.0).powf(d as f64),
        // Above 22 dimensions the default is the trivial bound, no grid.
        None if d > 22 => 0.0,
        None => (1u64 << 22) as f64,
    };
    random_box_work(n, d, options.random_boxes)
        + product(&[moves, n as f64, d as f64])
        + product(&[corners + n as f64, d as f64])
}

/// Work of the L2-type discrepancies ([`crate::l2_discrepancy`],
/// [`crate::l2_discrepancies`]): the symmetric pair sum, `n (n + 1) / 2 · d`.
pub fn l2_work(n: usize, d: usize) -> f64 {
    let n = n as f64;
    product(&[n, n + 1.0, 0.5, d as f64])
}

/// Work of the nearest-neighbour distances ([`crate::distance_stats`]): each
/// point visits at least its `3^d` neighbouring grid cells (capped by the
/// `n` other points it could compare with when the grid is coarse).
pub fn distance_work(n: usize, d: usize) -> f64 {
    let cells = 3f64.powf(d as f64).min(n as f64);
    product(&[n as f64, cells.max(1.0), d as f64])
}

/// Work of [`crate::radial_power_spectrum`] up to frequency `k`: the half
/// plane of `(2k + 1)(k + 1)` frequencies, each summing over `n` points.
pub fn spectrum_work(n: usize, k: usize) -> f64 {
    let k = k as f64;
    product(&[n as f64, 2.0 * k + 1.0, k + 1.0])
}

/// Memory of [`crate::radial_power_spectrum`] up to frequency `k`: the
/// per-point phase tables of both axes, `2 · n · (k + 1)` pairs of `f64`.
pub fn spectrum_memory(n: usize, k: usize) -> f64 {
    product(&[2.0, n as f64, k as f64 + 1.0, 16.0])
}

/// Memory of a point set of `n` points in `d` dimensions (`f64` coordinates).
pub fn points_memory(n: usize, d: usize) -> f64 {
    product(&[n as f64, d as f64, 8.0])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn estimates_grow_with_their_inputs_and_never_overflow() {
        assert_eq!(l2_work(4, 3), 30.0);
        assert_eq!(random_box_work(10, 2, 100), 2000.0);
        assert_eq!(
            spectrum_memory(65_536, 4096),
            2.0 * 65_536.0 * 4097.0 * 16.0
        );
        assert!(spectrum_work(65_536, 4096) > 1e12);
        assert!(distance_work(1000, 2) < distance_work(1000, 3));
        let huge = random_box_work(usize::MAX, usize::MAX, usize::MAX);
        assert!(huge.is_finite() && huge > 1e57);
        let default = bounds_work(256, 2, &BoundsOptions::default());
        assert!(default > random_box_work(256, 2, 10_000));
        assert!(default < 1e9, "{default:e}");
    }
}
