//! Tabulated sampling distributions: piecewise-constant 1D densities
//! ([`Distribution1D`]) and 2D densities built from a marginal and
//! conditionals ([`Distribution2D`]).
//!
//! They importance-sample light selection (by power) and environment maps (by
//! pixel brightness). Both use inverse-CDF sampling with a binary search, so a
//! sample is a monotone function of the uniform input, which keeps the
//! stratification of low-discrepancy points.

mod distribution1d;
mod distribution2d;
#[cfg(test)]
pub(crate) mod tests;

pub use distribution1d::{ContinuousSample, DiscreteSample, Distribution1D};
pub use distribution2d::Distribution2D;

/// The largest `f32` below 1: uniform inputs are clamped to `[0, ONE_MINUS_EPSILON]`.
pub const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

/// Clamps a uniform sample to `[0, 1)`; NaN becomes 0.
#[inline]
pub(crate) fn clamp_unit(u: f32) -> f32 {
    if u > 0.0 {
        u.min(ONE_MINUS_EPSILON)
    } else {
        0.0
    }
}
